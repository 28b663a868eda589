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

std::vector<MassCase> beyond_plain_mass_cases(const GiNaC::ex& m1, const GiNaC::ex& m2) {
  const GiNaC::ex high = plain_mass_high(), x_min = smallest_normal();
  // Each in one binade, so that each mass's binary exponent is fixed: [low, top] or [low, top).
  const auto between = [](const GiNaC::ex& low, const GiNaC::ex& x, const GiNaC::ex& top) {
    return std::vector<GiNaC::ex>{low <= x, x <= top};
  };
  const auto below = [](const GiNaC::ex& low, const GiNaC::ex& x, const GiNaC::ex& top) {
    return std::vector<GiNaC::ex>{low <= x, x < top};
  };
  const auto both = [](std::vector<GiNaC::ex> a, const std::vector<GiNaC::ex>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const GiNaC::ex light_low = GiNaC::numeric(1, 2), light_high = GiNaC::numeric(5, 8);
  const GiNaC::ex heavy_low = GiNaC::numeric(3, 2) / x_min, heavy_high = GiNaC::numeric(7, 4) / x_min;
  return {
      {both(below(1, m1, 2), below(2 * high, m2, 4 * high))},
      {both(below(2 * high, m1, 4 * high), below(1, m2, 2))},
      {both(between(light_low, m1, light_high), between(heavy_low, m2, heavy_high)), 16},
      {both(between(heavy_low, m1, heavy_high), between(light_low, m2, light_high)), 16},
  };
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

const std::vector<std::pair<std::string, GiNaC::ex>>& named_constant_spellings() {
  static const std::vector<std::pair<std::string, GiNaC::ex>> table = {
      {"smallest_normal<Scalar>", smallest_normal()}, {"infinity<Scalar>", infinity()},
      {"plain_mass_low<Scalar>", plain_mass_low()},   {"plain_mass_high<Scalar>", plain_mass_high()},
      {"moderate_low<Scalar>", moderate_low()},       {"moderate_high<Scalar>", moderate_high()}};
  return table;
}

std::optional<GiNaC::ex> named_constant_spelled(const std::string& spelling) {
  for (const auto& [name, constant] : named_constant_spellings()) {
    if (name == spelling) return constant;
  }
  return std::nullopt;
}

const std::vector<BinaryFormat>& emitted_formats() {
  static const std::vector<BinaryFormat> formats = {{"float", 24, -125, 128}, {"double", 53, -1021, 1024}};
  return formats;
}

std::optional<GiNaC::numeric> value_in(const GiNaC::ex& constant, const BinaryFormat& format) {
  const GiNaC::numeric two(2);
  // min_exponent − 1 is even in both formats, so √smallest_normal is a power of two.
  const GiNaC::numeric smallest = two.power(format.min_exponent - 1);
  const GiNaC::numeric mass_low = 4 * two.power((format.min_exponent - 1) / 2);
  const GiNaC::numeric moderate = two.power(-(format.max_exponent / 4 - 2));
  if (constant.is_equal(smallest_normal())) return smallest;
  if (constant.is_equal(plain_mass_low())) return mass_low;
  if (constant.is_equal(plain_mass_high())) return GiNaC::inverse(mass_low);
  if (constant.is_equal(moderate_low())) return moderate;
  if (constant.is_equal(moderate_high())) return GiNaC::inverse(moderate);
  return std::nullopt;
}

}  // namespace billiards::derive
