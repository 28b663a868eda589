// collide_batch against collide, pair by pair and bit for bit, and its errors. This file is also built
// with -march=native (billiards_runtime_native_tests), where both may fuse multiply-adds: they must
// still agree to the bit.
#define EIGEN_RUNTIME_NO_MALLOC
#include "test_support.hpp"

#include <billiards/batch.hpp>
#include <billiards/collision.hpp>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

using billiards_test::Config;

namespace {

template <typename Scalar>
bool same_bits(Scalar a, Scalar b) {
  return std::memcmp(&a, &b, sizeof(Scalar)) == 0;
}

}  // namespace

TEMPLATE_TEST_CASE("collide_batch gives collide's results bit for bit", "[runtime][batch]",
                   (Config<float, 1>), (Config<float, 2>), (Config<float, 3>), (Config<float, 4>),
                   (Config<double, 1>), (Config<double, 2>), (Config<double, 3>), (Config<double, 4>)) {
  using Scalar = typename TestType::Scalar;
  using Vector = typename TestType::Vector;
  constexpr std::size_t dimension = TestType::dimension;
  // 10,000 pairs (in blocks of 4096: one in the plain range, one mixed, a last one part full) and past
  // 2^17, beyond the second-level cache.
  const std::size_t count = GENERATE(std::size_t{10000}, (std::size_t{1} << 17) + 1000);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> component(-10, 10), decade(-3, 3);
  std::vector<Scalar> m1(count), m2(count);
  std::array<std::vector<Scalar>, dimension> v1, v2, n;
  for (std::size_t k = 0; k < dimension; ++k) v1[k].resize(count), v2[k].resize(count), n[k].resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    // The first half in the plain form's mass range, so whole blocks take the plain kernel; in the
    // second half every 10th ball immovable and every 15th of extreme mass, so blocks there take the
    // full kernel.
    const bool second_half = i >= count / 2;
    m1[i] = static_cast<Scalar>(std::pow(10.0, decade(random)));
    m2[i] = second_half && i % 10 == 0 ? std::numeric_limits<Scalar>::infinity()
                                       : static_cast<Scalar>(std::pow(10.0, decade(random)));
    if (second_half && i % 15 == 0) m1[i] = std::numeric_limits<Scalar>::max() / Scalar(4);
    if (second_half && i % 15 == 7) m1[i] = std::numeric_limits<Scalar>::min();
    Vector direction;
    for (std::size_t k = 0; k < dimension; ++k)
      direction[Eigen::Index(k)] = static_cast<Scalar>(component(random));
    direction.normalize();
    for (std::size_t k = 0; k < dimension; ++k) {
      // Every 7th pair has a ball at rest with negative zeros: the wall's ball must keep them.
      const bool signed_zero = i % 7 == 0;
      v1[k][i] = static_cast<Scalar>(component(random));
      v2[k][i] = signed_zero ? Scalar(-0.0) : static_cast<Scalar>(component(random));
      n[k][i] = direction[Eigen::Index(k)];
    }
  }
  const auto before1 = v1, before2 = v2;
  billiards::Components<Scalar, dimension> x1, x2;
  billiards::Components<const Scalar, dimension> normal;
  for (std::size_t k = 0; k < dimension; ++k) x1[k] = v1[k], x2[k] = v2[k], normal[k] = n[k];

  SECTION("every pair as collide computes it, to the bit") {
    billiards::collide_batch<Scalar, dimension>(m1, x1, m2, x2, normal);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < count; ++i) {
      Vector a, b, unit;
      for (std::size_t k = 0; k < dimension; ++k) {
        a[Eigen::Index(k)] = before1[k][i];
        b[Eigen::Index(k)] = before2[k][i];
        unit[Eigen::Index(k)] = n[k][i];
      }
      const auto [y1, y2] = billiards::collide(m1[i], a, m2[i], b, unit);
      for (std::size_t k = 0; k < dimension; ++k) {
        const bool same =
            same_bits(v1[k][i], y1[Eigen::Index(k)]) && same_bits(v2[k][i], y2[Eigen::Index(k)]);
        if (!same) {
          ++differing;
          UNSCOPED_INFO("pair " << i << " component " << k << ": batch " << v1[k][i] << ", " << v2[k][i]
                                << "; collide " << y1[Eigen::Index(k)] << ", " << y2[Eigen::Index(k)]);
        }
      }
    }
    CHECK(differing == 0);
  }
  SECTION("spans of different lengths are rejected before anything is updated") {
    const std::span<const Scalar> short_m2(m2.data(), count - 1);
    CHECK_THROWS_WITH(
        (billiards::collide_batch<Scalar, dimension>(m1, x1, short_m2, x2, normal)),
        Catch::Contains("m2 has " + std::to_string(count - 1) + " items, expected " + std::to_string(count)));
    CHECK(v1 == before1);
    CHECK(v2 == before2);
  }
}

TEMPLATE_TEST_CASE("kernels::within_plain_mass_range, on the bits, is the range the comparisons state",
                   "[runtime][batch]", float, double) {
  using Scalar = TestType;
  using limits = std::numeric_limits<Scalar>;
  const Scalar low = billiards::kernels::plain_mass_low<Scalar>(),
               high = billiards::kernels::plain_mass_high<Scalar>();
  std::vector<Scalar> values = {Scalar(0),
                                Scalar(-0.0),
                                limits::denorm_min(),
                                limits::min(),
                                std::nextafter(low, Scalar(0)),
                                low,
                                std::nextafter(low, high),
                                Scalar(1),
                                std::nextafter(high, Scalar(0)),
                                high,
                                std::nextafter(high, limits::infinity()),
                                limits::max(),
                                limits::infinity(),
                                limits::quiet_NaN(),
                                -limits::quiet_NaN(),
                                -low,
                                -Scalar(1),
                                -limits::infinity()};
  const std::vector<Scalar> every_kind = billiards_test::every_kind_of<Scalar>(11, 2000);
  values.insert(values.end(), every_kind.begin(), every_kind.end());
  // The range as written, by floating-point comparisons (what the predicate computes on the device).
  const auto in_range = [&](Scalar a, Scalar b) { return low <= a && a <= high && low <= b && b <= high; };
  for (const Scalar a : values) {
    for (const Scalar b :
         {Scalar(1), low, high, std::nextafter(high, limits::infinity()), limits::quiet_NaN()}) {
      INFO("m1 = " << a << ", m2 = " << b);
      CHECK(billiards::kernels::within_plain_mass_range(a, b) == in_range(a, b));
      CHECK(billiards::kernels::within_plain_mass_range(b, a) == in_range(b, a));
    }
  }
  // On the host the bits are compared (also in constant evaluation).
  STATIC_REQUIRE(billiards::kernels::orders_as_bits<Scalar>());
  STATIC_REQUIRE(billiards::kernels::within_plain_mass_range(Scalar(1), Scalar(2)));
  STATIC_REQUIRE_FALSE(billiards::kernels::within_plain_mass_range(Scalar(1), limits::infinity()));
  // The range's ends as the documentation states them.
  CHECK(low == std::ldexp(Scalar(1), sizeof(Scalar) == 8 ? -509 : -61));
  CHECK(high == std::ldexp(Scalar(1), sizeof(Scalar) == 8 ? 509 : 61));
}
