// Beyond the paper: restitution, immovable bodies, extreme masses, any direction, approaching
// contacts — each against its own hand-written formula (paper_formula.hpp), for float and double in
// 2-D and 3-D.
#include <billiards/collision.hpp>

#include "paper_formula.hpp"
#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace {

using billiards_test::Config;
using billiards_test::exact;

template <typename Vector>
Vector random_vector(std::mt19937_64& random, double scale = 10) {
  std::uniform_real_distribution<double> component(-scale, scale);
  Vector v;
  for (int i = 0; i < v.size(); ++i) v[i] = static_cast<typename Vector::Scalar>(component(random));
  return v;
}

template <typename Vector>
Vector random_unit(std::mt19937_64& random) {
  Eigen::Matrix<double, Vector::RowsAtCompileTime, 1> n;
  do {
    n = random_vector<decltype(n)>(random, 1);
  } while (n.norm() < 1e-2);
  return (n / n.norm()).template cast<typename Vector::Scalar>();
}

// Checks x1, x2 against the reference componentwise, within 8 scaled ULP: 8ε(|vᵢ| + c Σⱼ(|v1ⱼ| +
// |v2ⱼ|)|nⱼ| |nᵢ|) with c the ball's impulse coefficient, plus the smallest subnormal for results that
// underflow.
template <typename Vector, int N = Vector::RowsAtCompileTime>
bool within_scaled_ulp(const Vector& x1, const Vector& x2, const paper::Result<N>& reference, long double m1,
                       const Vector& v1, long double m2, const Vector& v2, const Vector& d, long double e) {
  using Scalar = typename Vector::Scalar;
  const long double epsilon = std::numeric_limits<Scalar>::epsilon();
  const long double tiny = std::numeric_limits<Scalar>::denorm_min();
  const paper::Vector<N> n = exact(d) / exact(d).norm();
  const long double c1 = (1 + e) / (1 + m1 / m2), c2 = (1 + e) / (1 + m2 / m1);
  const long double spread = (exact(v1).cwiseAbs() + exact(v2).cwiseAbs()).dot(n.cwiseAbs());
  for (int i = 0; i < N; ++i) {
    const long double bound1 = 8 * epsilon * (std::fabs(exact(v1)[i]) + c1 * spread * std::fabs(n[i])) + tiny;
    const long double bound2 = 8 * epsilon * (std::fabs(exact(v2)[i]) + c2 * spread * std::fabs(n[i])) + tiny;
    if (!(std::fabs(x1[i] - reference.x1[i]) <= bound1) || !(std::fabs(x2[i] - reference.x2[i]) <= bound2)) {
      return false;
    }
  }
  return true;
}

}  // namespace

TEMPLATE_TEST_CASE("Beyond the paper", "[runtime][beyond]", (Config<float, 2>), (Config<float, 3>),
                   (Config<double, 2>), (Config<double, 3>)) {
  using Scalar = typename TestType::Scalar;
  using Vector = typename TestType::Vector;
  constexpr int N = TestType::dimension;
  const long double epsilon = std::numeric_limits<Scalar>::epsilon();
  const Scalar infinity = std::numeric_limits<Scalar>::infinity();
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> unit_interval(0, 1), decade(-3, 3);
  const auto random_mass = [&] { return static_cast<Scalar>(std::pow(10.0, decade(random))); };
  const auto bits_equal = [](const Vector& a, const Vector& b) {
    return std::memcmp(a.data(), b.data(), sizeof(Scalar) * std::size_t(N)) == 0;
  };
  // `same(d)` for d = 2^k d0 at every k that keeps d exact and finite, failing the test naming k where it
  // is false; returns how many were compared.
  const auto at_every_scaling = [](const Vector& d0, const auto& same) {
    using limits = std::numeric_limits<Scalar>;
    int compared = 0;
    for (int k = limits::min_exponent - limits::digits; k < limits::max_exponent; ++k) {
      Vector d;
      for (int i = 0; i < N; ++i) d[i] = std::ldexp(d0[i], k);
      bool exact_scaling = d.allFinite();
      for (int i = 0; i < N; ++i) exact_scaling = exact_scaling && std::ldexp(d[i], -k) == d0[i];
      if (!exact_scaling) continue;
      if (!same(d)) FAIL("d = 2^" << k << " d0 differs from d0");
      ++compared;
    }
    return compared;
  };

  SECTION("restitution: the hand-written formula, separation = e × approach, and the energy lost") {
    for (int trial = 0; trial < 20000; ++trial) {
      const Scalar m1 = random_mass(), m2 = random_mass();
      const Vector v1 = random_vector<Vector>(random), v2 = random_vector<Vector>(random);
      const Vector n = random_unit<Vector>(random);
      const Scalar e = trial % 10 == 0   ? Scalar(1)
                       : trial % 10 == 1 ? Scalar(0)
                                         : Scalar(unit_interval(random));
      const auto [x1, x2] = billiards::collide(m1, v1, m2, v2, n, e);
      const auto reference = paper::restitution_collision<N>(m1, exact(v1), m2, exact(v2), exact(n), e);
      REQUIRE(within_scaled_ulp(x1, x2, reference, m1, v1, m2, v2, n, e));

      const long double approach = (exact(v2) - exact(v1)).dot(exact(n));
      const long double separation = (exact(x2) - exact(x1)).dot(exact(n));
      const long double speeds = exact(v1).norm() + exact(v2).norm();
      CHECK(std::fabs(separation + e * approach) <= 16 * epsilon * speeds * (1 + e));

      const long double M1 = m1, M2 = m2;
      const long double before = (M1 * exact(v1).squaredNorm() + M2 * exact(v2).squaredNorm()) / 2;
      const long double after = (M1 * exact(x1).squaredNorm() + M2 * exact(x2).squaredNorm()) / 2;
      const long double lost =
          M1 * M2 / (M1 + M2) * (1 - static_cast<long double>(e) * e) * approach * approach / 2;
      const long double tolerance = 32 * epsilon * (M1 + M2) * speeds * speeds;
      CHECK(std::fabs((before - after) - lost) <= tolerance);
      CHECK(before - after >= -8 * epsilon * before);  // ΔK ≥ −8ε K₀: no energy is created beyond rounding
    }
  }

  SECTION("e = 1 is the paper's call, bit for bit") {
    for (int trial = 0; trial < 1000; ++trial) {
      const Scalar m1 = random_mass(), m2 = random_mass();
      const Vector v1 = random_vector<Vector>(random), v2 = random_vector<Vector>(random);
      const Vector n = random_unit<Vector>(random);
      const auto [x1, x2] = billiards::collide(m1, v1, m2, v2, n);
      const auto [y1, y2] = billiards::collide(m1, v1, m2, v2, n, Scalar(1));
      CHECK((x1.array() == y1.array()).all());
      CHECK((x2.array() == y2.array()).all());
    }
  }

  SECTION("an infinite mass on either side is an exact, finite cushion") {
    for (int trial = 0; trial < 1000; ++trial) {
      const Scalar m = random_mass();
      const Vector v = random_vector<Vector>(random), wall_velocity = Vector::Zero();
      const Vector n = random_unit<Vector>(random);
      const Vector reflected = billiards::reflect(v, n);
      const auto [x1, x2] = billiards::collide(m, v, infinity, wall_velocity, n);
      CHECK((x1.array() == reflected.array()).all());
      CHECK((x2.array() == wall_velocity.array()).all());
      const auto [y1, y2] = billiards::collide(infinity, wall_velocity, m, v, n);
      CHECK((y2.array() == reflected.array()).all());
      CHECK((y1.array() == wall_velocity.array()).all());
      // A moving wall keeps its velocity; the ball leaves with v + 2((w − v)·n) n.
      const Vector w = random_vector<Vector>(random);
      const auto [z1, z2] = billiards::collide(m, v, infinity, w, n);
      CHECK(z1.allFinite());
      CHECK((z2.array() == w.array()).all());
      const long double relative = (exact(w) - exact(v)).dot(exact(n));
      CHECK((exact(z1) - (exact(v) + 2 * relative * exact(n))).cwiseAbs().maxCoeff() <=
            8 * epsilon * (exact(v).cwiseAbs().maxCoeff() + 2 * (exact(v).norm() + exact(w).norm())));
    }
  }

  SECTION("masses 2^k for every exponent of the type, subnormals included, in both orders") {
    const int lowest = std::numeric_limits<Scalar>::min_exponent - std::numeric_limits<Scalar>::digits;
    const int highest = std::numeric_limits<Scalar>::max_exponent - 1;
    const Vector v1 = random_vector<Vector>(random), v2 = random_vector<Vector>(random);
    const Vector n = random_unit<Vector>(random);
    long checked = 0;
    for (int j = lowest; j <= highest; ++j) {
      for (int k = lowest; k <= highest; k += (std::is_same_v<Scalar, double> ? 3 : 1)) {
        const Scalar small_or_large = std::ldexp(Scalar(1), j), other = std::ldexp(Scalar(1), k);
        REQUIRE(small_or_large > 0);
        REQUIRE(other > 0);
        for (const auto& [m1, m2] : {std::pair{small_or_large, other}, std::pair{other, small_or_large}}) {
          const auto [x1, x2] = billiards::collide(m1, v1, m2, v2, n);
          REQUIRE(x1.allFinite());
          REQUIRE(x2.allFinite());
          const auto reference = paper::collision<N>(m1, exact(v1), m2, exact(v2), exact(n));
          if (!within_scaled_ulp(x1, x2, reference, m1, v1, m2, v2, n, 1)) {
            FAIL("masses " << m1 << " and " << m2);
          }
        }
        ++checked;
      }
    }
    CHECK(checked > 10000);
  }

  SECTION("a heavy ball at rest still moves by its exact tiny amount") {
    // m1 at the top of the range, m2 small: ρ1 = m1/m2 overflows, yet x1 = (1 + e) s m2/(m1 + m2) n is
    // a normal number that momentum conservation needs.
    const Scalar heavy = std::numeric_limits<Scalar>::max(), light = Scalar(0.0686);
    const Vector n = Vector::Unit(0);
    const Vector v1 = Vector::Zero(), v2 = Vector::Unit(0) * Scalar(-1e9);
    for (const Scalar e : {Scalar(1), Scalar(0.5), Scalar(0)}) {
      const auto [x1, x2] = billiards::collide(heavy, v1, light, v2, n, e);
      const long double expected = (1 + static_cast<long double>(e)) * -1e9L * light / heavy;
      REQUIRE(expected != 0);
      CHECK(std::fabs((x1[0] - expected) / expected) <= 8 * epsilon);
      const auto [y2, y1] = billiards::collide(light, v2, heavy, v1, n, e);  // the other order
      CHECK(y1 == x1);
      CHECK(y2 == x2);
    }
  }

  SECTION("a scaled direction gives the unit normal's result") {
    for (int trial = 0; trial < 10000; ++trial) {
      const Scalar m1 = random_mass(), m2 = random_mass();
      const Vector v1 = random_vector<Vector>(random), v2 = random_vector<Vector>(random);
      const Vector n = random_unit<Vector>(random);
      const Scalar scale = static_cast<Scalar>(std::pow(10.0, decade(random))) * (trial % 2 ? 1 : -1);
      const Vector d = scale * n;
      const Scalar e = Scalar(unit_interval(random));
      const auto [x1, x2] = billiards::collide_along_direction(m1, v1, m2, v2, d, e);
      const auto reference = paper::restitution_collision<N>(m1, exact(v1), m2, exact(v2), exact(d), e);
      REQUIRE(within_scaled_ulp(x1, x2, reference, m1, v1, m2, v2, d, e));
    }
  }

  SECTION("a direction of any length gives the same bits, taken as it is or scaled first") {
    // d = 2^k d0 for every k that keeps d exact and finite: where d·d is moderate the call takes the dot
    // products of d as it is and scales late, elsewhere it scales d first; every quantity then differs
    // by a power of two only, so the results must agree with d0's to the last bit, in both calls that
    // take a direction.
    using limits = std::numeric_limits<Scalar>;
    int compared = 0;
    for (int trial = 0; trial < 20; ++trial) {
      const Scalar m1 = random_mass(), m2 = random_mass(), e = Scalar(unit_interval(random));
      const Vector v1 = random_vector<Vector>(random), v2 = random_vector<Vector>(random);
      const Vector d0 = random_vector<Vector>(random), zero = Vector::Zero();
      const auto along = billiards::collide_along_direction(m1, v1, m2, v2, d0, e);
      const auto approaching = billiards::collide_if_approaching(m1, zero, v1, m2, d0, v2, e);
      compared += at_every_scaling(d0, [&](const Vector& d) {
        const auto [z1, z2] = billiards::collide_along_direction(m1, v1, m2, v2, d, e);
        const auto [w1, w2] = billiards::collide_if_approaching(m1, zero, v1, m2, d, v2, e);
        return bits_equal(z1, along.first) && bits_equal(z2, along.second) && bits_equal(w1, approaching.first) &&
               bits_equal(w2, approaching.second);
      });
    }
    CHECK(compared > 18 * (limits::max_exponent - limits::min_exponent));
  }

  SECTION("the same bits for every length of d down to relative velocities at the edge of the normal range") {
    // The promise holds where every product (v2 − v1)_i d'_i and d'_i d'_i (d' = d scaled to its unit
    // binade) and every partial sum of them is zero or a normal number: the dot products of d and 2^k d
    // then differ by a power of two only. At its edge: d' with every component in ±[1/2, 1), and a
    // relative velocity whose products with it are each the smallest normal number or just above (and
    // of one sign, so that their sums do not cancel into the subnormal range); subnormal outputs
    // included (x1 − v1 = c1 d' is of the order of those velocities). A 64th of those velocities, whose
    // products are subnormal, breaks it in both types (d = 2^k d' then differs in the last bits).
    using limits = std::numeric_limits<Scalar>;
    int compared = 0, subnormal_outputs = 0;
    for (int trial = 0; trial < 40; ++trial) {
      const Scalar m1 = random_mass(), m2 = random_mass(), e = Scalar(unit_interval(random));
      Vector d0, v2;
      const Vector v1 = Vector::Zero();
      for (int i = 0; i < N; ++i) {
        const Scalar sign = unit_interval(random) < 0.5 ? Scalar(-1) : Scalar(1);
        d0[i] = sign * Scalar(0.5 + 0.5 * unit_interval(random));
        // The least v with |v d0_i| ≥ the smallest normal number, exactly, times 1 to 1 + 2^-4.
        Scalar v = std::nextafter(limits::min() / std::fabs(d0[i]), limits::infinity());
        v = v * Scalar(1 + unit_interval(random) / 16);
        REQUIRE(static_cast<long double>(v) * std::fabs(d0[i]) >= static_cast<long double>(limits::min()));
        v2[i] = sign * v;
      }
      const auto along = billiards::collide_along_direction(m1, v1, m2, v2, d0, e);
      for (int i = 0; i < N; ++i)
        subnormal_outputs += (along.first[i] != 0 && std::fabs(along.first[i]) < limits::min());
      compared += at_every_scaling(d0, [&](const Vector& d) {
        const auto [z1, z2] = billiards::collide_along_direction(m1, v1, m2, v2, d, e);
        return bits_equal(z1, along.first) && bits_equal(z2, along.second);
      });
    }
    CHECK(compared > 36 * (limits::max_exponent - limits::min_exponent));
    CHECK(subnormal_outputs > 0);
  }

  SECTION("a heavy ball's subnormal change keeps its digits along a direction of any length") {
    // m1/m2 beyond the normal range: ball 1 moves by a subnormal amount. Scaled to its unit binade, d
    // leaves that change within a rounding or two of the smallest subnormal; taken unscaled, a long d
    // would multiply the rounding of the multiple by |d| (what the fuzzer once found).
    using limits = std::numeric_limits<Scalar>;
    const Scalar heavy = std::ldexp(Scalar(1), limits::max_exponent / 2);
    const Scalar light = std::ldexp(Scalar(1), -limits::max_exponent / 2 - 10);
    const long double tiny = limits::denorm_min();
    Vector v1 = Vector::Zero(), v2 = Vector::Zero(), d0 = Vector::Zero();
    for (int i = 0; i < N; ++i) {
      v2[i] = Scalar(-1) / Scalar(i + 1);
      d0[i] = Scalar(1) - Scalar(0.25) * Scalar(i);
    }
    for (int k = -30; k <= 30; ++k) {
      Vector d;
      for (int i = 0; i < N; ++i) d[i] = std::ldexp(d0[i], k);
      for (const Scalar e : {Scalar(1), Scalar(0.5)}) {
        const auto [x1, x2] = billiards::collide_along_direction(heavy, v1, light, v2, d, e);
        const auto reference =
            paper::restitution_collision<N>(heavy, exact(v1), light, exact(v2), exact(d), e);
        for (int i = 0; i < N; ++i) {
          REQUIRE(reference.x1[i] != 0);
          REQUIRE(std::fabs(reference.x1[i]) < limits::min());
          if (!(std::fabs(x1[i] - reference.x1[i]) <= 2 * tiny)) {
            FAIL("d = 2^" << k << " d0, e = " << e << ": x1[" << i << "] = " << x1[i] << ", exact "
                          << static_cast<double>(reference.x1[i]));
          }
        }
      }
    }
  }

  SECTION("only approaching contacts are resolved; separating ones are left unchanged") {
    int approaching = 0, separating = 0;
    for (int trial = 0; trial < 10000; ++trial) {
      const Scalar m1 = random_mass(), m2 = random_mass();
      const Vector v1 = random_vector<Vector>(random), v2 = random_vector<Vector>(random);
      const Vector p1 = random_vector<Vector>(random), p2 = random_vector<Vector>(random);
      const Scalar e = Scalar(unit_interval(random));
      const auto [x1, x2] = billiards::collide_if_approaching(m1, p1, v1, m2, p2, v2, e);
      const Vector d = p2 - p1;
      if ((exact(v2) - exact(v1)).dot(exact(d)) < 0) {
        ++approaching;
        const auto reference = paper::restitution_collision<N>(m1, exact(v1), m2, exact(v2), exact(d), e);
        REQUIRE(within_scaled_ulp(x1, x2, reference, m1, v1, m2, v2, d, e));
        CHECK((exact(x2) - exact(x1)).dot(exact(d)) >=
              -16 * epsilon * (exact(v1).norm() + exact(v2).norm()) * exact(d).norm());
      } else {
        ++separating;
        CHECK((x1.array() == v1.array()).all());
        CHECK((x2.array() == v2.array()).all());
      }
    }
    CHECK(approaching > 1000);
    CHECK(separating > 1000);
  }
}

TEMPLATE_TEST_CASE("Unchanged means every bit: negative zeros are kept", "[runtime][beyond]",
                   (Config<float, 2>), (Config<float, 3>), (Config<double, 2>), (Config<double, 3>)) {
  using Scalar = typename TestType::Scalar;
  using Vector = typename TestType::Vector;
  const auto bits_equal = [](const Vector& a, const Vector& b) {
    return std::memcmp(a.data(), b.data(), sizeof(Scalar) * std::size_t(a.size())) == 0;
  };
  Vector negative_zero = Vector::Constant(Scalar(-0.0)), p1 = Vector::Zero(), p2 = Vector::Zero();
  p2[0] = 1;
  Vector moving_away = negative_zero;
  moving_away[0] = Scalar(2);  // (2, −0, …): ball 2 moves away from ball 1
  SECTION("a separating pair comes back unchanged, −0 included") {
    const auto [x1, x2] =
        billiards::collide_if_approaching(Scalar(1), p1, negative_zero, Scalar(3), p2, moving_away);
    CHECK(bits_equal(x1, negative_zero));
    CHECK(bits_equal(x2, moving_away));
    CHECK(std::signbit(x1[1]));
  }
  SECTION("a wall (infinite mass) keeps its velocity's bits") {
    Vector n = Vector::Zero();
    n[0] = 1;
    Vector v = Vector::Zero();
    v[0] = Scalar(-1);
    const auto [x1, x2] =
        billiards::collide(Scalar(1), v, std::numeric_limits<Scalar>::infinity(), negative_zero, n);
    CHECK(bits_equal(x2, negative_zero));
    CHECK(x1[0] == Scalar(1));
    const auto [y1, y2] = billiards::collide(Scalar(1), v, std::numeric_limits<Scalar>::infinity(),
                                             negative_zero, n, Scalar(0.5));
    CHECK(bits_equal(y2, negative_zero));
  }
  SECTION("reflect leaves the tangential −0 alone") {
    Vector n = Vector::Zero();
    n[0] = 1;
    const Vector r = billiards::reflect(negative_zero, n);
    CHECK(bits_equal(r, negative_zero));
  }
}

TEMPLATE_TEST_CASE("The moderate squared length: bits against comparisons on every kind of input",
                   "[runtime][beyond]", float, double) {
  using Scalar = TestType;
  using limits = std::numeric_limits<Scalar>;
  const Scalar high = std::ldexp(Scalar(1), limits::max_exponent / 4), low = 1;
  std::vector<Scalar> inputs = billiards_test::every_kind_of<Scalar>(23, 3000);
  for (const Scalar edge : {low, high}) {
    inputs.push_back(edge);
    inputs.push_back(std::nextafter(edge, Scalar(0)));
    inputs.push_back(std::nextafter(edge, limits::infinity()));
  }
  int inside = 0;
  for (const Scalar x : inputs) {
    const bool expected = low <= x && x <= high;
    CHECK(billiards::detail::has_moderate_squared_length(x) == expected);
    inside += expected ? 1 : 0;
  }
  CHECK(inside > 4);
}
