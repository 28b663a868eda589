// The benchmark's reference kernel (billiards/reference_kernels.hpp): the raw derivation, the quadratic
// formula with √D, against the paper's formula typed by hand (paper_formula.hpp) in long double. It is
// exact where the paper's sanity checks are, and accurate to a bound that grows as the contact becomes
// tangent: D = B² − 4AC cancels there, which is why the runtime does not use it.
#include <billiards/reference_kernels.hpp>

#include "paper_formula.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

TEMPLATE_TEST_CASE("The raw derivation's kernel picks the collision root", "[runtime][reference]", float,
                   double) {
  using Scalar = TestType;
  using billiards::reference_kernels::raw_normal_velocity_change;
  SECTION("equal masses, one at rest: the normal velocities are exchanged exactly") {
    const auto change = raw_normal_velocity_change(Scalar(1), Scalar(1), Scalar(1), Scalar(0));
    CHECK(change.first == Scalar(-1));
    CHECK(change.second == Scalar(1));
  }
  SECTION("the other sign of (v2 − v1)·n takes the other root, still the collision") {
    const auto change = raw_normal_velocity_change(Scalar(1), Scalar(1), Scalar(0), Scalar(1));
    CHECK(change.first == Scalar(1));
    CHECK(change.second == Scalar(-1));
  }
  SECTION("against the paper's formula on random contacts") {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> mass(0.1, 10), speed(-10, 10);
    const long double epsilon = std::numeric_limits<Scalar>::epsilon();
    for (int sample = 0; sample < 20000; ++sample) {
      const Scalar m1 = static_cast<Scalar>(mass(random)), m2 = static_cast<Scalar>(mass(random));
      const Scalar v1n = static_cast<Scalar>(speed(random)), v2n = static_cast<Scalar>(speed(random));
      const paper::Vector<1> n(1.0L);
      const auto reference = paper::collision<1>(m1, paper::Vector<1>(v1n), m2, paper::Vector<1>(v2n), n);
      const auto change = raw_normal_velocity_change(m1, m2, v1n, v2n);
      // √D loses about ε (B² + 4|AC|)/D of its value to cancellation, D = m1² ((v2 − v1)·n)².
      const long double speeds =
          std::fabs(static_cast<long double>(v1n)) + std::fabs(static_cast<long double>(v2n));
      const long double relative = std::fabs(static_cast<long double>(v2n) - v1n);
      const long double ratio =
          std::max<long double>(m1 / static_cast<long double>(m2), m2 / static_cast<long double>(m1));
      const long double bound = 64 * epsilon * (1 + ratio) * (1 + ratio) * speeds * speeds / relative;
      INFO("m1 " << m1 << " m2 " << m2 << " v1n " << v1n << " v2n " << v2n);
      CHECK(std::fabs(change.first - (reference.x1[0] - v1n)) <= bound);
      CHECK(std::fabs(change.second - (reference.x2[0] - v2n)) <= bound);
    }
  }
}
