#include "core/named_constants.hpp"

namespace billiards::derive {

const GiNaC::symbol& smallest_normal() {
  static const GiNaC::symbol constant("smallest_normal", "x_{\\min}");
  return constant;
}

const GiNaC::symbol& infinity() {
  static const GiNaC::symbol constant("infinity", "\\infty");
  return constant;
}

const GiNaC::symbol& plain_mass_low() {
  static const GiNaC::symbol constant("plain_mass_low", "m_{\\text{low}}");
  return constant;
}

const GiNaC::symbol& plain_mass_high() {
  static const GiNaC::symbol constant("plain_mass_high", "m_{\\text{high}}");
  return constant;
}

bool is_named_constant(const GiNaC::ex& e) {
  return e.is_equal(smallest_normal()) || e.is_equal(infinity()) || e.is_equal(plain_mass_low()) ||
         e.is_equal(plain_mass_high());
}

int positive_finite_rank(const GiNaC::ex& e) {
  if (e.is_equal(smallest_normal())) return 0;
  if (e.is_equal(plain_mass_low())) return 1;
  if (e.is_equal(plain_mass_high())) return 2;
  return -1;
}

}  // namespace billiards::derive
