// collide_batch against collide, pair by pair, and its errors.
#define EIGEN_RUNTIME_NO_MALLOC
#include <billiards/batch.hpp>
#include <billiards/collision.hpp>

#include <catch2/catch.hpp>

#include <random>
#include <vector>

TEMPLATE_TEST_CASE("collide_batch gives collide's results", "[runtime][batch]", float, double) {
  using Scalar = TestType;
  constexpr std::size_t count = 1000;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> component(-10, 10), decade(-3, 3);
  std::vector<Scalar> m1(count), m2(count);
  std::array<std::vector<Scalar>, 3> v1, v2, n;
  for (std::size_t k = 0; k < 3; ++k) v1[k].resize(count), v2[k].resize(count), n[k].resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    m1[i] = static_cast<Scalar>(std::pow(10.0, decade(random)));
    m2[i] = i % 10 == 0 ? std::numeric_limits<Scalar>::infinity()
                        : static_cast<Scalar>(std::pow(10.0, decade(random)));
    Eigen::Vector3d direction(component(random), component(random), component(random));
    direction.normalize();
    for (std::size_t k = 0; k < 3; ++k) {
      v1[k][i] = static_cast<Scalar>(component(random));
      v2[k][i] = static_cast<Scalar>(component(random));
      n[k][i] = static_cast<Scalar>(direction[static_cast<Eigen::Index>(k)]);
    }
  }
  const auto before1 = v1, before2 = v2;
  billiards::Components<Scalar, 3> x1{v1[0], v1[1], v1[2]}, x2{v2[0], v2[1], v2[2]};
  const billiards::Components<const Scalar, 3> normal{n[0], n[1], n[2]};

  SECTION("every pair as collide computes it") {
    billiards::collide_batch<Scalar, 3>(m1, x1, m2, x2, normal);
    using Vector = Eigen::Matrix<Scalar, 3, 1>;
    for (std::size_t i = 0; i < count; ++i) {
      const Vector a(before1[0][i], before1[1][i], before1[2][i]),
          b(before2[0][i], before2[1][i], before2[2][i]);
      const Vector unit(n[0][i], n[1][i], n[2][i]);
      const auto [y1, y2] = billiards::collide(m1[i], a, m2[i], b, unit);
      for (std::size_t k = 0; k < 3; ++k) {
        // The same kernel; the dot products may associate differently from Eigen's, so to rounding.
        const Scalar tolerance = 8 * std::numeric_limits<Scalar>::epsilon() * (a.norm() + b.norm());
        CHECK(std::abs(v1[k][i] - y1[static_cast<Eigen::Index>(k)]) <= tolerance);
        CHECK(std::abs(v2[k][i] - y2[static_cast<Eigen::Index>(k)]) <= tolerance);
      }
    }
  }
  SECTION("spans of different lengths are rejected before anything is updated") {
    const std::span<const Scalar> short_m2(m2.data(), count - 1);
    CHECK_THROWS_WITH((billiards::collide_batch<Scalar, 3>(m1, x1, short_m2, x2, normal)),
                      Catch::Contains("m2 has 999 items, expected 1000"));
    CHECK(v1 == before1);
    CHECK(v2 == before2);
  }
}
