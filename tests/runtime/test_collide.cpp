// billiards::collide and billiards::reflect against the hand-written paper formula, conservation
// laws, symmetries and exact cases, for float and double in 2-D and 3-D.
#define EIGEN_RUNTIME_NO_MALLOC  // lets a test forbid heap allocation inside Eigen
#include <billiards/collision.hpp>

#include "paper_formula.hpp"
#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>

namespace {

using billiards_test::Config;
using billiards_test::exact;

template <typename Vector>
Vector random_unit_normal(std::mt19937_64& random) {
  std::normal_distribution<double> gaussian;
  Eigen::Matrix<double, Vector::RowsAtCompileTime, 1> n;
  do {
    for (int i = 0; i < n.size(); ++i) n[i] = gaussian(random);
  } while (n.norm() < 1e-3);
  return (n / n.norm()).template cast<typename Vector::Scalar>();
}

// Calls sample(x) for positive finite x of Scalar at every exponent, subnormal ones and the top
// binades included: each binade's first number, one at a random mantissa and its last number.
template <typename Scalar, typename Sample>
void at_every_exponent(std::mt19937_64& random, Sample sample) {
  using limits = std::numeric_limits<Scalar>;
  std::uniform_real_distribution<double> mantissa(1, 2);
  for (int e = limits::min_exponent - limits::digits; e <= limits::max_exponent; ++e) {
    for (const Scalar x :
         {std::ldexp(Scalar(1), e - 1), std::ldexp(static_cast<Scalar>(mantissa(random)), e - 1),
          std::nextafter(std::ldexp(Scalar(1), e), Scalar(0))}) {
      if (x > 0 && std::isfinite(x)) sample(x);
    }
  }
}

template <typename Vector>
Vector random_velocity(std::mt19937_64& random) {
  std::uniform_real_distribution<double> component(-10, 10);
  Vector v;
  for (int i = 0; i < v.size(); ++i) v[i] = static_cast<typename Vector::Scalar>(component(random));
  return v;
}

template <typename Scalar>
Scalar random_mass(std::mt19937_64& random) {
  std::uniform_real_distribution<double> decade(-3, 3);  // 10^-3 … 10^3: six decades
  return static_cast<Scalar>(std::pow(10.0, decade(random)));
}

// One random collision: masses over six decades, velocities in [−10, 10], a random unit normal.
template <typename Vector>
struct Sample {
  using Scalar = typename Vector::Scalar;
  Scalar m1, m2;
  Vector v1, v2, n;

  explicit Sample(std::mt19937_64& random)
      : m1(random_mass<Scalar>(random)),
        m2(random_mass<Scalar>(random)),
        v1(random_velocity<Vector>(random)),
        v2(random_velocity<Vector>(random)),
        n(random_unit_normal<Vector>(random)) {}
};

}  // namespace

TEMPLATE_TEST_CASE("collide agrees with the paper's formula", "[runtime][elastic]", (Config<float, 2>),
                   (Config<float, 3>), (Config<double, 2>), (Config<double, 3>)) {
  using Scalar = typename TestType::Scalar;
  using Vector = typename TestType::Vector;
  constexpr int N = TestType::dimension;
  const long double epsilon = std::numeric_limits<Scalar>::epsilon();
  std::mt19937_64 random(20231202);

  SECTION("every component of 10^5 random collisions lies within the rounding bound") {
    // Bound per component i: 8ε(|v1ᵢ| + c Σⱼ(|v1ⱼ| + |v2ⱼ|)|nⱼ| |nᵢ|), c = 2 m2/(m1 + m2); ball 2 alike.
    long double worst = 0;  // the largest error seen, as a fraction of its bound
    for (int trial = 0; trial < 100000; ++trial) {
      const auto [m1, m2, v1, v2, n] = Sample<Vector>(random);
      const auto [x1, x2] = billiards::collide(m1, v1, m2, v2, n);
      const auto reference = paper::collision<N>(m1, exact(v1), m2, exact(v2), exact(n));
      const long double c1 = 2.0L * m2 / (static_cast<long double>(m1) + m2);
      const long double c2 = 2.0L * m1 / (static_cast<long double>(m1) + m2);
      const long double spread = (exact(v1).cwiseAbs() + exact(v2).cwiseAbs()).dot(exact(n).cwiseAbs());
      for (int i = 0; i < N; ++i) {
        const long double n_i = std::fabs(static_cast<long double>(n[i]));
        const long double bound1 =
            8 * epsilon * (std::fabs(static_cast<long double>(v1[i])) + c1 * spread * n_i);
        const long double bound2 =
            8 * epsilon * (std::fabs(static_cast<long double>(v2[i])) + c2 * spread * n_i);
        const long double error1 = std::fabs(x1[i] - reference.x1[i]);
        const long double error2 = std::fabs(x2[i] - reference.x2[i]);
        if (error1 > bound1 || error2 > bound2) {
          INFO("trial " << trial << " component " << i << ": m1 " << m1 << " m2 " << m2 << " error " << error1
                        << " / " << bound1 << ", " << error2 << " / " << bound2);
          FAIL("outside the rounding bound");
        }
        if (bound1 > 0) worst = std::max(worst, error1 / bound1);
        if (bound2 > 0) worst = std::max(worst, error2 / bound2);
      }
    }
    INFO("largest error as a fraction of the bound: " << static_cast<double>(worst));
    CHECK(worst <= 1);
  }

  SECTION("momentum and kinetic energy are conserved to rounding") {
    for (int trial = 0; trial < 10000; ++trial) {
      const auto [m1, m2, v1, v2, n] = Sample<Vector>(random);
      const auto [x1, x2] = billiards::collide(m1, v1, m2, v2, n);
      const long double M1 = m1, M2 = m2;
      const long double scale = M1 * exact(v1).norm() + M2 * exact(v2).norm();
      const paper::Vector<N> momentum_change =
          (M1 * exact(x1) + M2 * exact(x2)) - (M1 * exact(v1) + M2 * exact(v2));
      CHECK(momentum_change.cwiseAbs().maxCoeff() <= 32 * epsilon * scale);
      const long double energy_before = M1 * exact(v1).squaredNorm() + M2 * exact(v2).squaredNorm();
      const long double energy_after = M1 * exact(x1).squaredNorm() + M2 * exact(x2).squaredNorm();
      CHECK(std::fabs(energy_after - energy_before) <=
            32 * epsilon * scale * (exact(v1).norm() + exact(v2).norm()));
    }
  }

  SECTION("negating n changes nothing, bit for bit") {
    for (int trial = 0; trial < 10000; ++trial) {
      const auto [m1, m2, v1, v2, n] = Sample<Vector>(random);
      const auto [x1, x2] = billiards::collide(m1, v1, m2, v2, n);
      const auto [y1, y2] = billiards::collide(m1, v1, m2, v2, Vector(-n));
      CHECK((x1.array() == y1.array()).all());
      CHECK((x2.array() == y2.array()).all());
    }
  }

  SECTION("swapping the balls swaps the results, bit for bit") {
    for (int trial = 0; trial < 10000; ++trial) {
      const auto [m1, m2, v1, v2, n] = Sample<Vector>(random);
      const auto [x1, x2] = billiards::collide(m1, v1, m2, v2, n);
      const auto [y2, y1] = billiards::collide(m2, v2, m1, v1, n);
      CHECK((x1.array() == y1.array()).all());
      CHECK((x2.array() == y2.array()).all());
    }
  }

  SECTION("equal masses, first ball at rest: the paper's exact exchange") {
    for (int axis = 0; axis < N; ++axis) {
      const Vector n = Vector::Unit(axis);
      const Scalar m = random_mass<Scalar>(random);
      const Vector v2 = random_velocity<Vector>(random);
      // Not head-on: x1 = v2∥, x2 = v2 − v2∥, exactly.
      const auto [x1, x2] = billiards::collide(m, Vector::Zero().eval(), m, v2, n);
      const Vector v2_parallel = v2[axis] * n;
      CHECK((x1.array() == v2_parallel.array()).all());
      CHECK((x2.array() == (v2 - v2_parallel).array()).all());
      // Head-on: the first ball takes all the velocity and the second stops.
      const Vector head_on = v2[axis] * n;
      const auto [y1, y2] = billiards::collide(m, Vector::Zero().eval(), m, head_on, n);
      CHECK((y1.array() == head_on.array()).all());
      CHECK((y2.array() == 0).all());
    }
  }

  SECTION("reflect is the cushion, v − 2(v·n)n") {
    for (int trial = 0; trial < 10000; ++trial) {
      const Vector v = random_velocity<Vector>(random);
      const Vector n = random_unit_normal<Vector>(random);
      const Vector w = billiards::reflect(v, n);
      const auto reference = paper::reflection<N>(exact(v), exact(n));
      const long double bound = 8 * epsilon * exact(v).cwiseAbs().maxCoeff();
      CHECK((exact(w) - reference).cwiseAbs().maxCoeff() <= bound);
      CHECK(std::fabs(exact(w).norm() - exact(v).norm()) <= bound * N);  // speed kept
    }
  }

  SECTION("nothing is allocated") {
    const Vector v1 = random_velocity<Vector>(random), v2 = random_velocity<Vector>(random);
    const Vector n = random_unit_normal<Vector>(random);
    Eigen::internal::set_is_malloc_allowed(false);
    const auto result = billiards::collide(Scalar(1), v1, Scalar(2), v2, n);
    const Vector reflected = billiards::reflect(v1, n);
    Eigen::internal::set_is_malloc_allowed(true);
    CHECK(result.first.allFinite());
    CHECK(reflected.allFinite());
  }
}

TEST_CASE("collide takes Map, Ref, blocks and expressions", "[runtime][api]") {
  double storage[9] = {1, 0, 0, -1, 0.5, 0, 1, 0, 0};
  const Eigen::Map<const Eigen::Vector3d> v1(storage), v2(storage + 3), n(storage + 6);
  const Eigen::Vector3d plain1 = v1, plain2 = v2, plain_n = n;
  const auto [x1, x2] = billiards::collide(2.0, plain1, 3.0, plain2, plain_n);

  SECTION("Map") {
    const auto [y1, y2] = billiards::collide(2.0, v1, 3.0, v2, n);
    CHECK(y1 == x1);
    CHECK(y2 == x2);
  }
  SECTION("Ref and blocks of a bigger matrix") {
    Eigen::Matrix3d columns;
    columns << plain1, plain2, plain_n;
    const Eigen::Ref<const Eigen::Vector3d> r1 = columns.col(0);
    const auto [y1, y2] = billiards::collide(2.0, r1, 3.0, columns.col(1), columns.block<3, 1>(0, 2));
    CHECK(y1 == x1);
    CHECK(y2 == x2);
  }
  SECTION("expressions") {
    const auto [y1, y2] =
        billiards::collide(2.0, plain1 * 1.0, 3.0, plain2 + Eigen::Vector3d::Zero(), -(-plain_n));
    CHECK(y1 == x1);
    CHECK(y2 == x2);
  }
  SECTION("the result is an aggregate of plain vectors") {
    const billiards::Collision<Eigen::Vector3d> result = billiards::collide(2.0, v1, 3.0, v2, n);
    CHECK(result.first == x1);
    CHECK(result.second == x2);
    STATIC_REQUIRE(std::is_aggregate_v<billiards::Collision<Eigen::Vector3d>>);
  }
}

TEST_CASE("The version macro is the package version", "[runtime][version]") {
  CHECK(std::string(BILLIARDS_VERSION) == BILLIARDS_EXPECTED_VERSION);
  CHECK(std::to_string(BILLIARDS_VERSION_MAJOR) + "." + std::to_string(BILLIARDS_VERSION_MINOR) + "." +
            std::to_string(BILLIARDS_VERSION_PATCH) ==
        BILLIARDS_EXPECTED_VERSION);
}

TEMPLATE_TEST_CASE("binary_exponent and power_of_two read and build the exponent field as frexp and ldexp do",
                   "[runtime][detail]", float, double) {
  using Scalar = TestType;
  using limits = std::numeric_limits<Scalar>;
  std::mt19937_64 random(21);
  at_every_exponent<Scalar>(random, [](Scalar x) {
    int expected = 0;
    static_cast<void>(std::frexp(x, &expected));
    INFO("x = " << x);
    CHECK(billiards::detail::binary_exponent(x) == expected);
  });
  CHECK(billiards::detail::binary_exponent(limits::denorm_min()) ==
        limits::min_exponent - limits::digits + 1);
  CHECK(billiards::detail::binary_exponent(limits::max()) == limits::max_exponent);
  CHECK(billiards::detail::binary_exponent(Scalar(0)) == 0);
  CHECK(billiards::detail::binary_exponent(limits::infinity()) == 0);
  for (int e = limits::min_exponent - 1; e <= limits::max_exponent - 1; ++e) {
    CHECK(billiards::detail::power_of_two<Scalar>(e) == std::ldexp(Scalar(1), e));
  }
}

TEMPLATE_TEST_CASE("times_power_of_two is ldexp to the bit, for every exponent of x and of the power",
                   "[runtime][detail]", float, double) {
  using Scalar = TestType;
  using limits = std::numeric_limits<Scalar>;
  using Bits = billiards::detail::FloatBits<Scalar>;
  std::mt19937_64 random(24);
  // Powers from 2^−(2·range) to 2^(2·range): the normal ones (one multiplication) and beyond (ldexp),
  // with results normal, subnormal, rounded to 0 and overflowing to ∞; x of either sign, and 0 and ∞.
  const int range = limits::max_exponent - limits::min_exponent + limits::digits;
  const auto check = [&](Scalar x) {
    for (const Scalar signed_x : {x, -x}) {
      // Exponents 0, 1, −1, 2, −2, … up to ±2·range: the first where the bits differ, if any.
      std::optional<int> differs_at;
      for (int e = 0; e <= 2 * range && !differs_at; e = e > 0 ? -e : 1 - e) {
        if (std::bit_cast<Bits>(billiards::detail::times_power_of_two(signed_x, e)) !=
            std::bit_cast<Bits>(std::ldexp(signed_x, e)))
          differs_at = e;
      }
      INFO("x = " << signed_x << ": the bits differ from ldexp's at the exponent " << differs_at.value_or(0));
      CHECK(!differs_at);
    }
  };
  at_every_exponent<Scalar>(random, check);
  check(Scalar(0));
  check(limits::infinity());
}

TEMPLATE_TEST_CASE("scale_to_unit_binade is frexp's and ldexp's scaling, at every exponent",
                   "[runtime][detail]", float, double) {
  using Scalar = TestType;
  using limits = std::numeric_limits<Scalar>;
  using V = Eigen::Matrix<Scalar, 3, 1>;
  std::mt19937_64 random(23);
  const auto unit_binade = [](const V& d) {
    auto scalars = billiards::detail::scalars_of(d);
    billiards::detail::scale_to_unit_binade(scalars);
    return V(scalars[0], scalars[1], scalars[2]);
  };
  std::uniform_real_distribution<double> fraction(-1, 1);
  // The reference by frexp and ldexp, component by component: d · 2^−e with e frexp's exponent of
  // the largest |component|; d itself where that is 0 or not finite.
  const auto expected = [](const V& d) {
    const Scalar largest = std::max({std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])});
    int e = 0;
    if (largest > 0 && std::isfinite(largest)) static_cast<void>(std::frexp(largest, &e));
    return V(std::ldexp(d[0], -e), std::ldexp(d[1], -e), std::ldexp(d[2], -e));
  };
  // Every exponent (subnormal and the top binades are the fast path's edges), the largest component
  // in each place and of either sign.
  at_every_exponent<Scalar>(random, [&](Scalar x) {
    for (int place = 0; place < 3; ++place) {
      V d(static_cast<Scalar>(fraction(random)) * x, static_cast<Scalar>(fraction(random)) * x,
          static_cast<Scalar>(fraction(random)) * x);
      d[place] = place == 1 ? -x : x;
      INFO("d = " << d.transpose());
      const V reference = expected(d);
      const V scaled = unit_binade(d);
      for (int k = 0; k < 3; ++k)
        CHECK(std::bit_cast<billiards::detail::FloatBits<Scalar>>(scaled[k]) ==
              std::bit_cast<billiards::detail::FloatBits<Scalar>>(reference[k]));
      CHECK(billiards::detail::largest_magnitude(scaled) >= Scalar(0.5));
      CHECK(billiards::detail::largest_magnitude(scaled) < Scalar(1));
    }
  });
  CHECK(unit_binade(V::Zero()) == V::Zero());
  const V infinite(limits::infinity(), 1, 0);
  CHECK(unit_binade(infinite) == infinite);
}

TEMPLATE_TEST_CASE("scaled_norm is the norm without overflow or underflow of the squares",
                   "[runtime][detail]", float, double) {
  using Scalar = TestType;
  using limits = std::numeric_limits<Scalar>;
  using V = Eigen::Matrix<Scalar, 3, 1>;
  std::mt19937_64 random(22);
  std::uniform_real_distribution<double> component(-1, 1);
  for (int e = limits::min_exponent - limits::digits + 2; e <= limits::max_exponent - 2; e += 3) {
    const V v(static_cast<Scalar>(component(random)), static_cast<Scalar>(component(random)),
              static_cast<Scalar>(component(random)));
    const V w = v * std::ldexp(Scalar(1), e);  // exact where w stays normal
    const long double expected =
        std::sqrt((long double)w[0] * w[0] + (long double)w[1] * w[1] + (long double)w[2] * w[2]);
    INFO("exponent " << e);
    CHECK(std::fabs(billiards::detail::scaled_norm(w) - expected) <=
          4 * limits::epsilon() * expected + limits::denorm_min());
  }
  CHECK(billiards::detail::scaled_norm(V::Zero().eval()) == 0);
}

TEMPLATE_TEST_CASE("scaled_norm's fast path has the general path's bits at every exponent",
                   "[runtime][detail]", (billiards_test::Config<float, 2>),
                   (billiards_test::Config<double, 2>), (billiards_test::Config<float, 3>),
                   (billiards_test::Config<double, 3>)) {
  // For float and double scaled_norm builds both powers of two from the largest exponent field (where
  // they are normal numbers); elsewhere, and here as the reference, it scales by binary_exponent and
  // times_power_of_two. The same factors, so the same bits: every exponent, subnormals and the top
  // binades included, the largest component in each place.
  using Scalar = typename TestType::Scalar;
  using V = typename TestType::Vector;
  using Bits = billiards::detail::FloatBits<Scalar>;
  std::mt19937_64 random(24);
  std::uniform_real_distribution<double> fraction(-1, 1);
  at_every_exponent<Scalar>(random, [&](Scalar x) {
    for (int place = 0; place < V::SizeAtCompileTime; ++place) {
      V v;
      for (int k = 0; k < v.size(); ++k) v[k] = static_cast<Scalar>(fraction(random)) * x;
      v[place] = x;
      const int e = billiards::detail::largest_component_exponent(v);
      const Scalar general =
          billiards::detail::times_power_of_two(billiards::detail::times_power_of_two(v, -e).norm(), e);
      INFO("v = " << v.transpose());
      CHECK(std::bit_cast<Bits>(billiards::detail::scaled_norm(v)) == std::bit_cast<Bits>(general));
    }
  });
}
