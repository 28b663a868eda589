// billiards::collide_with_friction against the impulse equations written out by hand in long double
// (an independent reference, not the runtime's code path), the conservation laws, the energy, the
// μ = 0 reduction to collide(..., e) and the published throw of a stun shot (Alciatore, TP A-14); the
// spin kernels over the whole exponent range against long double, and their scaling helpers against
// std::ilogb and std::ldexp.
#include "test_support.hpp"

#include <billiards/spin.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

namespace {

using Long3 = Eigen::Matrix<long double, 3, 1>;

template <typename Scalar>
using Ball = billiards::SpinningBall<Scalar>;

// The impulse equations by hand (definition.impulse), I = (2/5) m R², J = J_n n − j û_t on ball 2:
// J_n = (1 + e) m1 m2/(m1 + m2) |(v2 − v1)·n|, j = min(μ J_n, |u_t|/k), k = 1/m1 + 1/m2 + R1²/I1 + R2²/I2.
struct Reference {
  Long3 v1, w1, v2, w2;
  long double tangential_impulse;
};

template <typename Scalar>
Reference by_hand(const Ball<Scalar>& a, const Ball<Scalar>& b, const Eigen::Matrix<Scalar, 3, 1>& n_,
                  long double e, long double mu) {
  const Long3 n = n_.template cast<long double>();
  const Long3 v1 = a.velocity.template cast<long double>(),
              w1 = a.angular_velocity.template cast<long double>();
  const Long3 v2 = b.velocity.template cast<long double>(),
              w2 = b.angular_velocity.template cast<long double>();
  const long double m1 = a.mass, m2 = b.mass, R1 = a.radius, R2 = b.radius;
  const long double I1 = 0.4L * m1 * R1 * R1, I2 = 0.4L * m2 * R2 * R2;
  const long double approach = (v2 - v1).dot(n);
  if (!(approach < 0)) return {v1, w1, v2, w2, 0};
  const long double Jn = (1 + e) * m1 * m2 / (m1 + m2) * -approach;
  const Long3 r1 = R1 * n, r2 = -R2 * n;
  const Long3 u = (v2 + w2.cross(r2)) - (v1 + w1.cross(r1));
  const Long3 ut = u - u.dot(n) * n;
  const long double k = 1 / m1 + 1 / m2 + R1 * R1 / I1 + R2 * R2 / I2;
  const long double slip = ut.norm();
  const long double j = slip > 0 ? std::min(mu * Jn, slip / k) : 0;
  const Long3 J = Jn * n - (slip > 0 ? Long3(j * ut / slip) : Long3::Zero());
  return {v1 - J / m1, w1 + r1.cross(-J) / I1, v2 + J / m2, w2 + r2.cross(J) / I2, j};
}

template <typename Scalar>
Eigen::Matrix<Scalar, 3, 1> random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  Eigen::Vector3d n(gauss(rng), gauss(rng), gauss(rng));
  return (n / n.norm()).cast<Scalar>();
}

template <typename Scalar>
Ball<Scalar> random_ball(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> speed(-3, 3), spin(-100, 100), mass(0.05, 5), radius(0.01, 0.1);
  return {Eigen::Vector3d(speed(rng), speed(rng), speed(rng)).cast<Scalar>(),
          Eigen::Vector3d(spin(rng), spin(rng), spin(rng)).cast<Scalar>(), Scalar(mass(rng)),
          Scalar(radius(rng))};
}

long double scale_of(const Reference& r) {
  return std::max({r.v1.norm(), r.v2.norm(), 0.1L * r.w1.norm(), 0.1L * r.w2.norm(), 1.0L});
}

}  // namespace

TEMPLATE_TEST_CASE("collide_with_friction: the impulse equations, conservation and energy", "[runtime][spin]",
                   float, double) {
  using Scalar = TestType;
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> unit(0, 1);
  const long double eps = std::numeric_limits<Scalar>::epsilon();
  int sticking = 0, sliding = 0;
  for (int i = 0; i < 100000; ++i) {
    Ball<Scalar> a = random_ball<Scalar>(rng), b = random_ball<Scalar>(rng);
    const Eigen::Matrix<Scalar, 3, 1> n = random_unit<Scalar>(rng);
    // Make the pair approach: flip ball 2's velocity along n if needed.
    if ((b.velocity - a.velocity).dot(n) >= 0) b.velocity -= Scalar(2) * (b.velocity - a.velocity).dot(n) * n;
    const Scalar e = Scalar(unit(rng)), mu = Scalar(0.5 * unit(rng));
    const auto [x, y] = billiards::collide_with_friction(a, b, n, e, mu);
    const Reference r = by_hand(a, b, n, e, mu);
    if ((r.v2 - r.v1).dot(n.template cast<long double>()) >= 0 && r.tangential_impulse > 0) {
      const long double slip_after = [&] {
        const Long3 nn = n.template cast<long double>();
        const Long3 u = (r.v2 + r.w2.cross(-(long double)b.radius * nn)) -
                        (r.v1 + r.w1.cross((long double)a.radius * nn));
        return (u - u.dot(nn) * nn).norm();
      }();
      (slip_after < 1e-9L * scale_of(r) ? sticking : sliding) += 1;
    }
    const long double tolerance = 256 * eps * scale_of(r) * (1 + std::max(a.mass / b.mass, b.mass / a.mass));
    INFO("case " << i);
    CHECK((x.velocity.template cast<long double>() - r.v1).norm() <= tolerance);
    CHECK((y.velocity.template cast<long double>() - r.v2).norm() <= tolerance);
    CHECK((x.angular_velocity.template cast<long double>() - r.w1).norm() <= tolerance / a.radius);
    CHECK((y.angular_velocity.template cast<long double>() - r.w2).norm() <= tolerance / b.radius);
    // Conservation, evaluated in long double on the returned values.
    const long double m1 = a.mass, m2 = b.mass, R1 = a.radius, R2 = b.radius;
    const long double I1 = 0.4L * m1 * R1 * R1, I2 = 0.4L * m2 * R2 * R2;
    const Long3 nn = n.template cast<long double>();
    const auto L = [&](const Ball<Scalar>& ball, long double I, const Long3& centre) {
      return Long3(I * ball.angular_velocity.template cast<long double>() +
                   ball.mass * centre.cross(ball.velocity.template cast<long double>()));
    };
    const Long3 p_before =
        m1 * a.velocity.template cast<long double>() + m2 * b.velocity.template cast<long double>();
    const Long3 p_after =
        m1 * x.velocity.template cast<long double>() + m2 * y.velocity.template cast<long double>();
    const long double momentum_scale = std::max(m1, m2) * scale_of(r);
    CHECK((p_after - p_before).norm() <= 256 * eps * momentum_scale);
    CHECK((L(x, I1, -R1 * nn) - L(a, I1, -R1 * nn)).norm() <= 256 * eps * momentum_scale * R1 * 10);
    CHECK((L(y, I2, R2 * nn) - L(b, I2, R2 * nn)).norm() <= 256 * eps * momentum_scale * R2 * 10);
    const auto energy = [&](const Ball<Scalar>& p, long double I) {
      return 0.5L * p.mass * p.velocity.template cast<long double>().squaredNorm() +
             0.5L * I * p.angular_velocity.template cast<long double>().squaredNorm();
    };
    const long double before = energy(a, I1) + energy(b, I2), after = energy(x, I1) + energy(y, I2);
    CHECK(after <= before * (1 + 64 * eps));
  }
  // Both regimes were exercised.
  CHECK(sticking > 1000);
  CHECK(sliding > 1000);
}

TEMPLATE_TEST_CASE("collide_with_friction: no friction is collide(..., e), bit for bit", "[runtime][spin]",
                   float, double) {
  using Scalar = TestType;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 10000; ++i) {
    const Ball<Scalar> a = random_ball<Scalar>(rng), b = random_ball<Scalar>(rng);
    const Eigen::Matrix<Scalar, 3, 1> n = random_unit<Scalar>(rng);
    const Scalar e = Scalar(unit(rng));
    if (!((b.velocity - a.velocity).dot(n) < 0)) continue;
    const auto [x, y] = billiards::collide_with_friction(a, b, n, e, Scalar(0));
    const auto plain = billiards::collide(a.mass, a.velocity, b.mass, b.velocity, n, e);
    CHECK(x.velocity == plain.first);
    CHECK(y.velocity == plain.second);
    CHECK(x.angular_velocity == a.angular_velocity);
    CHECK(y.angular_velocity == b.angular_velocity);
  }
}

TEMPLATE_TEST_CASE("collide_with_friction: a pair that does not approach is unchanged", "[runtime][spin]",
                   float, double) {
  using Scalar = TestType;
  using V = Eigen::Matrix<Scalar, 3, 1>;
  const Ball<Scalar> a{V(-1, 0.5, Scalar(-0.0)), V(3, 4, 5), 1, Scalar(0.03)};
  const Ball<Scalar> b{V(1, 0, 0), V(-3, 1, 2), 2, Scalar(0.02)};
  const auto [x, y] = billiards::collide_with_friction(a, b, V(1, 0, 0), Scalar(1), Scalar(0.2));
  CHECK(x.velocity == a.velocity);
  CHECK(std::signbit(x.velocity.z()));
  CHECK(x.angular_velocity == a.angular_velocity);
  CHECK(y.velocity == b.velocity);
  CHECK(y.angular_velocity == b.angular_velocity);
}

TEMPLATE_TEST_CASE("collide_with_friction: masses anywhere in the type's range, as accurate as masses near 1",
                   "[runtime][spin]", float, double) {
  using Scalar = TestType;
  using limits = std::numeric_limits<Scalar>;
  std::mt19937_64 rng(14);
  std::uniform_int_distribution<int> exponent(limits::min_exponent, limits::max_exponent - 2);
  std::uniform_real_distribution<double> unit(0, 1);
  const long double eps = limits::epsilon();
  for (int i = 0; i < 20000; ++i) {
    Ball<Scalar> a = random_ball<Scalar>(rng), b = random_ball<Scalar>(rng);
    // Every other pair at the ends of the range: the smallest normal mass beside the largest.
    const int ea = i % 2 ? exponent(rng) : (i % 4 ? limits::min_exponent : limits::max_exponent - 2);
    const int eb = i % 2 ? exponent(rng) : (i % 4 ? limits::max_exponent - 2 : limits::min_exponent);
    a.mass = std::ldexp(Scalar(1 + unit(rng)), ea - 1);
    b.mass = std::ldexp(Scalar(1 + unit(rng)), eb - 1);
    const Eigen::Matrix<Scalar, 3, 1> n = random_unit<Scalar>(rng);
    if ((b.velocity - a.velocity).dot(n) >= 0) b.velocity -= Scalar(2) * (b.velocity - a.velocity).dot(n) * n;
    const Scalar e = Scalar(unit(rng)), mu = Scalar(0.5 * unit(rng));
    const auto [x, y] = billiards::checked::collide_with_friction(a, b, n, e, mu);
    const Reference r = by_hand(a, b, n, e, mu);
    // No mass-ratio factor here: only the ratio enters the kernels, and no mass's size.
    const long double tolerance = 64 * eps * scale_of(r);
    INFO("case " << i << ": masses " << a.mass << ", " << b.mass);
    CHECK((x.velocity.template cast<long double>() - r.v1).norm() <= tolerance);
    CHECK((y.velocity.template cast<long double>() - r.v2).norm() <= tolerance);
    CHECK((x.angular_velocity.template cast<long double>() - r.w1).norm() <= tolerance / a.radius);
    CHECK((y.angular_velocity.template cast<long double>() - r.w2).norm() <= tolerance / b.radius);
  }
}

TEMPLATE_TEST_CASE("collide_with_friction: the stun-shot throw is atan(min(mu, tan(phi)/7)) (TP A-14)",
                   "[runtime][spin]", float, double) {
  using Scalar = TestType;
  using V = Eigen::Matrix<Scalar, 3, 1>;
  const double pi = std::acos(-1.0);
  for (const double mu : {0.02, 0.06, 0.1}) {
    for (int degrees = 1; degrees <= 89; ++degrees) {
      const double phi = degrees * pi / 180;
      // The cue ball moves along x; the line of centres is at the cut angle φ to it.
      const Ball<Scalar> cue{V(2, 0, 0), V::Zero(), Scalar(0.17), Scalar(0.028575)};
      const Ball<Scalar> object{V::Zero(), V::Zero(), Scalar(0.17), Scalar(0.028575)};
      const V n = V(Scalar(std::cos(phi)), Scalar(std::sin(phi)), 0);
      const auto [x, y] = billiards::collide_with_friction(cue, object, n, Scalar(1), Scalar(mu));
      const double departure = std::atan2(double(y.velocity.y()), double(y.velocity.x()));
      const double thrown = phi - departure;
      const double expected = std::atan(std::min(mu, std::tan(phi) / 7));
      INFO("mu " << mu << " phi " << degrees << "°");
      CHECK(std::fabs(thrown - expected) <=
            (std::is_same_v<Scalar, float> ? 2e-5 : 1e-12) * (1 + std::tan(phi)));
    }
  }
}

TEMPLATE_TEST_CASE("checked::collide_with_friction rejects bad input, naming the argument", "[runtime][spin]",
                   float, double) {
  using Scalar = TestType;
  using V = Eigen::Matrix<Scalar, 3, 1>;
  const Ball<Scalar> good{V(1, 0, 0), V(0, 0, 1), 1, Scalar(0.03)};
  const V n(1, 0, 0);
  const Scalar nan = std::numeric_limits<Scalar>::quiet_NaN(), inf = std::numeric_limits<Scalar>::infinity();
  const auto rejects = [&](Ball<Scalar> a, Ball<Scalar> b, V normal, Scalar e, Scalar mu,
                           const char* argument) {
    try {
      static_cast<void>(billiards::checked::collide_with_friction(a, b, normal, e, mu));
      FAIL("accepted; expected a rejection of " << argument);
    } catch (const billiards::invalid_argument& error) {
      CHECK(error.argument() == argument);
      CHECK(std::string(error.what()).find("billiards::checked::collide_with_friction") != std::string::npos);
    }
  };
  Ball<Scalar> bad = good;
  bad.mass = -1;
  rejects(bad, good, n, 1, Scalar(0.1), "ball1.mass");
  bad = good;
  bad.mass = inf;
  rejects(good, bad, n, 1, Scalar(0.1), "ball2.mass");
  bad = good;
  bad.radius = nan;
  rejects(bad, good, n, 1, Scalar(0.1), "ball1.radius");
  bad = good;
  bad.velocity.y() = nan;
  rejects(bad, good, n, 1, Scalar(0.1), "ball1.velocity");
  bad = good;
  bad.angular_velocity.x() = inf;
  rejects(good, bad, n, 1, Scalar(0.1), "ball2.angular_velocity");
  rejects(good, good, V(1, 1, 0), 1, Scalar(0.1), "n");
  rejects(good, good, n, Scalar(1.5), Scalar(0.1), "restitution");
  rejects(good, good, n, 1, Scalar(-0.1), "friction");
  rejects(good, good, n, 1, nan, "friction");
  // Accepted input returns exactly the unchecked result.
  const Ball<Scalar> other{V(-1, 0.2, 0), V(3, 0, 0), 2, Scalar(0.02)};
  const auto checked = billiards::checked::collide_with_friction(good, other, n, Scalar(0.9), Scalar(0.2));
  const auto plain = billiards::collide_with_friction(good, other, n, Scalar(0.9), Scalar(0.2));
  CHECK(checked.first.velocity == plain.first.velocity);
  CHECK(checked.second.angular_velocity == plain.second.angular_velocity);
}

// ---- The spin kernels over the whole exponent range --------------------------------------

namespace {

// Log-uniform over the whole positive range, the smallest subnormal to the largest finite number.
template <typename Scalar>
Scalar anywhere(std::mt19937_64& random) {
  using limits = std::numeric_limits<Scalar>;
  std::uniform_real_distribution<double> exponent(std::log2(static_cast<double>(limits::denorm_min())),
                                                  std::log2(static_cast<double>(limits::max())));
  return std::clamp(static_cast<Scalar>(std::exp2(exponent(random))), limits::denorm_min(), limits::max());
}

// Whether `computed` is `exact` (long double, whose exponent range holds every product of these
// inputs) correctly rounded to Scalar within `ulps` relative ULP, the unit floored at the smallest
// subnormal; where the exact value rounds to ±∞ in Scalar, ±∞.
template <typename Scalar>
bool within_ulps(Scalar computed, long double exact, long double ulps) {
  using limits = std::numeric_limits<Scalar>;
  const long double overflow =
      static_cast<long double>(limits::max()) + std::ldexp(1.0L, limits::max_exponent - 1 - limits::digits);
  if (std::fabs(exact) >= overflow) return std::isinf(computed) && (computed > 0) == (exact > 0);
  if (!std::isfinite(computed)) return false;
  const long double unit = std::max(static_cast<long double>(limits::epsilon()) * std::fabs(exact),
                                    static_cast<long double>(limits::denorm_min()));
  return std::fabs(static_cast<long double>(computed) - exact) <= ulps * unit;
}

}  // namespace

TEMPLATE_TEST_CASE("kernels::binary_exponent and times_power_of_two are std::ilogb and std::ldexp",
                   "[runtime][spin]", float, double) {
  using Scalar = TestType;
  namespace support = billiards::kernels;  // the helpers of billiards/kernel_support.hpp
  std::mt19937_64 random(29);
  std::uniform_int_distribution<int> exponent(-2 * std::numeric_limits<Scalar>::max_exponent - 60,
                                              2 * std::numeric_limits<Scalar>::max_exponent + 60);
  for (const Scalar x : billiards_test::every_kind_of<Scalar>(17, 3000)) {
    INFO("x = " << x);
    const bool ordinary = std::isfinite(x) && x != 0;
    CHECK(support::binary_exponent(x) == (ordinary ? Scalar(std::ilogb(x)) : Scalar(0)));
    if (ordinary)
      CHECK(std::ldexp(x, -std::ilogb(x)) == support::times_power_of_two(x, -support::binary_exponent(x)));
    for (const int k : {0, 1, -1, 4096, -4096, 5000, -5000, exponent(random), exponent(random)}) {
      INFO("k = " << k);
      const Scalar expected = std::ldexp(x, k), scaled = support::times_power_of_two(x, Scalar(k));
      if (std::isnan(x)) {
        CHECK(std::isnan(scaled));
      } else {
        CHECK(std::memcmp(&expected, &scaled, sizeof expected) == 0);  // the same bits, signed zeros too
      }
    }
  }
  // A NaN exponent is clamped, not converted (which would be undefined): 1 · 2^−4096 is +0.
  CHECK(support::times_power_of_two(Scalar(1), std::numeric_limits<Scalar>::quiet_NaN()) == Scalar(0));
}

TEMPLATE_TEST_CASE("The spin kernels over the whole exponent range, against long double", "[runtime][spin]",
                   float, double) {
  using Scalar = TestType;
  using L = long double;
  namespace spin = billiards::kernels::spin;
  std::mt19937_64 random(31);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 20000; ++i) {
    const Scalar a = anywhere<Scalar>(random), b = anywhere<Scalar>(random), c = anywhere<Scalar>(random),
                 d = anywhere<Scalar>(random), e = Scalar(unit(random));
    const L la = a, lb = b, lc = c, ld = d, le = e;
    INFO("a = " << a << ", b = " << b << ", c = " << c << ", d = " << d << ", e = " << e);
    // The formulas as the audit states them (sliding.slide_time, rolling.stop_time, spinning.stop_time,
    // kernel.spin_change_per_impulse, kernel.spin_change, friction.normal_impulse, k for solid spheres).
    CHECK(within_ulps(spin::slide_time(a, b, c), 2 * la / (7 * lb * lc), 3));
    CHECK(within_ulps(spin::roll_time(a, b, c), la / (lb * lc), 3));
    CHECK(within_ulps(spin::spin_time(a, b, c, d), 2 * lb * la / (5 * lc * ld), 3));
    CHECK(within_ulps(spin::spin_change_per_impulse(a, b), 5 / (2 * la * lb), 3));
    CHECK(within_ulps(spin::spin_change(a, b), 5 * la / (2 * lb), 3));
    CHECK(within_ulps(spin::normal_impulse(a, b, e, -c), (1 + le) * (la * lb / (la + lb)) * lc, 4));
    CHECK(within_ulps(spin::tangential_inverse_effective_mass(a, b), 3.5L * (1 / la + 1 / lb), 3));
    // kernel.tangential_velocity_change: j/m1 and j/m2 for masses a, b, approach −c, slip d, μ ∈ [0, 1).
    const Scalar mu = Scalar(unit(random));
    const L bound = std::min((1 + le) * L(mu) * lc, 2 * ld / 7);
    const auto change = spin::tangential_velocity_change(a, b, e, mu, -c, d);
    CHECK(within_ulps(change.first, bound * lb / (la + lb), 4));
    CHECK(within_ulps(change.second, bound * la / (la + lb), 4));
  }
  // Found by the accuracy tool: a bound of 8e34 over a light ball of 2e-4 overflowed float before the
  // small-mass form multiplied by the other mass, 3e-43.
  if constexpr (std::is_same_v<Scalar, float>) {
    const float m1 = 0.000188278573f, m2 = 3.33509035e-43f, e = 0.874731421f, mu = 0.842392862f,
                approach = -1.04723191e+35f, slip = 2.92764817e+35f;
    const auto change = spin::tangential_velocity_change(m1, m2, e, mu, approach, slip);
    const L bound = std::min((1 + L(e)) * L(mu) * -L(approach), 2 * L(slip) / 7);
    CHECK(within_ulps(change.first, bound * L(m2) / (L(m1) + L(m2)), 4));
    CHECK(within_ulps(change.second, bound * L(m1) / (L(m1) + L(m2)), 4));
  }
}
