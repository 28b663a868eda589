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

std::vector<GiNaC::ex> plain_mass_range(const GiNaC::ex& m1, const GiNaC::ex& m2) {
  return {plain_mass_low() <= m1, m1 <= plain_mass_high(), plain_mass_low() <= m2, m2 <= plain_mass_high()};
}

const GiNaC::symbol& moderate_low() {
  static const GiNaC::symbol constant("moderate_low", "x_{\\text{low}}");
  return constant;
}

const GiNaC::symbol& moderate_high() {
  static const GiNaC::symbol constant("moderate_high", "x_{\\text{high}}");
  return constant;
}

bool is_named_constant(const GiNaC::ex& e) { return e.is_equal(infinity()) || positive_finite_rank(e) >= 0; }

int positive_finite_rank(const GiNaC::ex& e) {
  if (e.is_equal(smallest_normal())) return 0;
  if (e.is_equal(plain_mass_low())) return 1;
  if (e.is_equal(moderate_low())) return 2;
  if (e.is_equal(moderate_high())) return 3;
  if (e.is_equal(plain_mass_high())) return 4;
  return -1;
}

}  // namespace billiards::derive
