// The bit manipulation printed for the kernels (billiards/kernel_support.hpp) — binary_exponent, times_power_of_two and the range
// tests on bits (bits_above, larger) — checked over every exponent of float and double against exact
// references: long double, whose range holds every x · 2^k exactly, and the comparisons the range tests
// stand for. Built twice: as host code, and with BILLIARDS_TEST_DEVICE_PATH, which defines __CUDA_ARCH__
// before the header so that its device path (std::ilogb, std::ldexp, comparisons) runs on the host.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#if defined(BILLIARDS_TEST_DEVICE_PATH)
#define __CUDA_ARCH__ 800
#endif
#include <billiards/spin_kernels.hpp>

namespace spin = billiards::kernels::spin;
namespace support = billiards::kernels;  // the helpers of billiards/kernel_support.hpp

namespace {

// ±s · 2^k for every exponent k of the format's finite numbers, subnormals included, and significands
// s = 1, 1 + ε, 1.5 and 2 − ε where the format holds them.
template <typename Scalar>
std::vector<Scalar> every_exponent() {
  using limits = std::numeric_limits<Scalar>;
  std::vector<Scalar> values;
  const int lowest = limits::min_exponent - limits::digits;  // the smallest subnormal is 2^lowest
  for (int k = lowest; k < limits::max_exponent; ++k) {
    for (const long double s : {1.0L, 1.0L + static_cast<long double>(limits::epsilon()), 1.5L,
                                2.0L - static_cast<long double>(limits::epsilon())}) {
      const long double exact = std::ldexp(s, k);
      const auto x = static_cast<Scalar>(exact);
      if (static_cast<long double>(x) != exact || !std::isfinite(x)) continue;  // not held exactly
      values.push_back(x);
      values.push_back(-x);
    }
  }
  return values;
}

template <typename Scalar>
bool same_bits(Scalar a, Scalar b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEMPLATE_TEST_CASE("binary_exponent is ⌊log2 |x|⌋ at every exponent, 0 for ±0, ±∞ and NaN",
                   "[runtime][support]", float, double) {
  using Scalar = TestType;
  using limits = std::numeric_limits<Scalar>;
  for (const Scalar x : every_exponent<Scalar>()) {
    int exponent = 0;
    // frexp gives x = f 2^e with f in [1/2, 1): ⌊log2 |x|⌋ = e − 1, exactly, subnormals included.
    std::frexp(static_cast<long double>(x), &exponent);
    INFO("x = " << x);
    CHECK(support::binary_exponent(x) == Scalar(exponent - 1));
  }
  for (const Scalar special :
       {Scalar(0), -Scalar(0), limits::infinity(), -limits::infinity(), limits::quiet_NaN()})
    CHECK(support::binary_exponent(special) == Scalar(0));
}

TEMPLATE_TEST_CASE("times_power_of_two is x · 2^k rounded once, for every exponent of x and of the result",
                   "[runtime][support]", float, double) {
  using Scalar = TestType;
  using limits = std::numeric_limits<Scalar>;
  const std::vector<Scalar> xs = every_exponent<Scalar>();
  // x · 2^k in long double is exact (its exponents reach ±16382), and converting it to Scalar rounds
  // once, to nearest: the correctly rounded result.
  const auto expected = [](Scalar x, int k) {
    return static_cast<Scalar>(std::ldexp(static_cast<long double>(x), k));
  };
  const int span = limits::max_exponent - limits::min_exponent + limits::digits + 2;
  // Every k that moves 1 and −1.5 anywhere from beyond the largest to below the smallest subnormal.
  for (int k = -span; k <= span; ++k) {
    for (const Scalar x : {Scalar(1), Scalar(-1.5)}) {
      INFO("x = " << x << ", k = " << k);
      CHECK(same_bits(support::times_power_of_two(x, Scalar(k)), expected(x, k)));
    }
  }
  // Every x, moved by the k that take it to each end of the range and over it.
  for (const Scalar x : xs) {
    const int e = static_cast<int>(support::binary_exponent(x));
    for (const int k : {0, 1, -1, -e, limits::max_exponent - 1 - e, limits::max_exponent - e,
                        limits::min_exponent - 1 - e, limits::min_exponent - limits::digits - e,
                        limits::min_exponent - limits::digits - 1 - e, 4096, -4096, 5000, -5000}) {
      INFO("x = " << x << ", k = " << k);
      CHECK(same_bits(support::times_power_of_two(x, Scalar(k)), expected(x, k)));
    }
  }
  // ±0, ±∞ and NaN stay as they are; a NaN exponent is clamped to −4096, not converted.
  CHECK(same_bits(support::times_power_of_two(-Scalar(0), Scalar(7)), -Scalar(0)));
  CHECK(support::times_power_of_two(limits::infinity(), Scalar(-7)) == limits::infinity());
  CHECK(std::isnan(support::times_power_of_two(limits::quiet_NaN(), Scalar(3))));
  CHECK(support::times_power_of_two(Scalar(1), limits::quiet_NaN()) == Scalar(0));
}

TEMPLATE_TEST_CASE("The range tests on bits are the comparisons they stand for, at every exponent",
                   "[runtime][support]", float, double) {
  using Scalar = TestType;
  using limits = std::numeric_limits<Scalar>;
  std::vector<Scalar> xs = every_exponent<Scalar>();
  for (const Scalar end : {support::plain_mass_low<Scalar>(), support::plain_mass_high<Scalar>(),
                           support::moderate_low<Scalar>(), support::moderate_high<Scalar>()}) {
    xs.push_back(end);
    xs.push_back(std::nextafter(end, Scalar(0)));
    xs.push_back(std::nextafter(end, limits::infinity()));
  }
  for (const Scalar special : {Scalar(0), -Scalar(0), limits::infinity(), -limits::infinity(),
                               limits::quiet_NaN(), limits::denorm_min(), limits::max()})
    xs.push_back(special);
  const auto in = [](Scalar x, Scalar low, Scalar high) { return low <= x && x <= high; };
  const Scalar mass_low = support::plain_mass_low<Scalar>(), mass_high = support::plain_mass_high<Scalar>();
  const Scalar low = support::moderate_low<Scalar>(), high = support::moderate_high<Scalar>();
  const Scalar one = Scalar(1);
  for (const Scalar x : xs) {
    INFO("x = " << x);
    CHECK(spin::within_plain_mass_range(x, one) == in(x, mass_low, mass_high));
    CHECK(spin::within_plain_mass_range(one, x) == in(x, mass_low, mass_high));
    CHECK(spin::slide_time_is_moderate(x, one, one) == in(x, low, high));
    CHECK(spin::slide_time_is_moderate(one, one, x) == in(x, low, high));
    CHECK(spin::spin_time_is_moderate(one, one, x, one) == in(x, low, high));
  }
}
