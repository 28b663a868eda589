// A ball on the cloth: the phases against their closed forms written out by hand, the published rules
// of thumb (the 5/7 rule, the 30° rule through collide_with_friction and evolve), frictionless phases
// that last forever, energy that never increases, and the checked calls.
#include <billiards/cloth.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>

namespace {

template <typename Scalar>
using V3 = Eigen::Matrix<Scalar, 3, 1>;

constexpr double radius = 0.028575;  // a pool ball, m

template <typename Scalar>
billiards::BallOnCloth<Scalar> on_table(V3<Scalar> velocity, V3<Scalar> spin) {
  return {V3<Scalar>(0, 0, Scalar(radius)), velocity, spin, Scalar(radius)};
}

template <typename Scalar>
Scalar energy(const billiards::BallOnCloth<Scalar>& b) {  // per unit mass
  return b.velocity.squaredNorm() / 2 + Scalar(0.2) * b.radius * b.radius * b.angular_velocity.squaredNorm();
}

template <typename Scalar>
Scalar tolerance() {
  return std::is_same_v<Scalar, float> ? Scalar(2e-5) : Scalar(1e-12);
}

}  // namespace

TEMPLATE_TEST_CASE("cloth: a stun shot slides, then rolls at 5/7 of its speed", "[runtime][cloth]", float,
                   double) {
  using Scalar = TestType;
  const billiards::Cloth<Scalar> cloth{Scalar(0.2), Scalar(0.01), Scalar(0.044)};
  const auto ball = on_table<Scalar>(V3<Scalar>(2, 0, 0), V3<Scalar>::Zero());
  CHECK(billiards::motion(ball, cloth) == billiards::Motion::sliding);
  const Scalar slide = billiards::transition_time(ball, cloth);
  CHECK(slide == Approx(2.0 * 2 / (7 * 0.2 * 9.81)).epsilon(tolerance<Scalar>()));
  const auto rolling = billiards::evolve(ball, cloth, slide);
  CHECK(billiards::motion(rolling, cloth) == billiards::Motion::rolling);
  CHECK(rolling.velocity.x() == Approx(5.0 / 7 * 2).epsilon(tolerance<Scalar>()));
  CHECK(rolling.angular_velocity.y() == Approx(5.0 / 7 * 2 / radius).epsilon(tolerance<Scalar>()));
  // Distance slid: v0 t − ½ μ_s g t².
  CHECK(rolling.position.x() ==
        Approx(2 * slide - 0.5 * 0.2 * 9.81 * slide * slide).epsilon(tolerance<Scalar>()));
  CHECK(rolling.position.z() == Scalar(radius));
}

TEMPLATE_TEST_CASE("cloth: the phases follow their closed forms and energy never increases",
                   "[runtime][cloth]", float, double) {
  using Scalar = TestType;
  const double mu_s = 0.2, mu_r = 0.01, mu_sp = 0.044, g = 9.81;
  const billiards::Cloth<Scalar> cloth{Scalar(mu_s), Scalar(mu_r), Scalar(mu_sp)};
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> speed(-3, 3), spin(-200, 200), when(0, 20);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d v0(speed(rng), speed(rng), 0), w0(spin(rng), spin(rng), spin(rng));
    const auto ball = on_table<Scalar>(v0.cast<Scalar>(), w0.cast<Scalar>());
    const Eigen::Vector3d v = ball.velocity.template cast<double>(),
                          w = ball.angular_velocity.template cast<double>();
    // By hand: u0 = v0 + ω0 × (−R ẑ), t_s = 2|u0|/(7 μ_s g), v(t_s) = v0 − (2/7) u0, t_r = |v(t_s)|/(μ_r g).
    const Eigen::Vector3d u0(v.x() - radius * w.y(), v.y() + radius * w.x(), 0);
    const double slide = 2 * u0.norm() / (7 * mu_s * g);
    const Eigen::Vector3d rolling_velocity = v - 2.0 / 7 * u0;
    const double roll = rolling_velocity.norm() / (mu_r * g);
    const double spin_stop = 2 * radius * std::fabs(w.z()) / (5 * mu_sp * g);
    const double t = when(rng);
    const auto later = billiards::evolve(ball, cloth, Scalar(t));
    INFO("case " << i << " t " << t << " slide " << slide << " roll " << roll);
    Eigen::Vector3d expected_velocity, expected_position;
    const Eigen::Vector3d p0(0, 0, radius);
    if (t <= slide) {
      const Eigen::Vector3d direction = u0 / u0.norm();
      expected_velocity = v - mu_s * g * t * direction;
      expected_position = p0 + v * t - 0.5 * mu_s * g * t * t * direction;
    } else {
      const Eigen::Vector3d p1 = p0 + v * slide - 0.5 * mu_s * g * slide * slide * (u0 / u0.norm());
      const double s = std::min(t - slide, roll);
      const Eigen::Vector3d direction = rolling_velocity / rolling_velocity.norm();
      expected_velocity = t - slide >= roll ? Eigen::Vector3d::Zero()
                                            : Eigen::Vector3d(rolling_velocity - mu_r * g * s * direction);
      expected_position = p1 + rolling_velocity * s - 0.5 * mu_r * g * s * s * direction;
    }
    const double expected_spin =
        t >= spin_stop ? 0.0 : std::copysign(std::fabs(w.z()) - 5 * mu_sp * g * t / (2 * radius), w.z());
    const double scale = 1 + v.norm() + radius * w.norm();
    const double loose = std::is_same_v<Scalar, float> ? 1e-3 : 1e-9;
    CHECK((later.velocity.template cast<double>() - expected_velocity).norm() <= loose * scale);
    CHECK((later.position.template cast<double>() - expected_position).norm() <= loose * scale * (1 + t));
    CHECK(std::fabs(double(later.angular_velocity.z()) - expected_spin) <= loose * scale / radius);
    // The energy at t is no more than at t/2, which is no more than at the start.
    const auto halfway = billiards::evolve(ball, cloth, Scalar(t / 2));
    CHECK(energy(later) <= energy(halfway) * (1 + 64 * std::numeric_limits<Scalar>::epsilon()));
    CHECK(energy(halfway) <= energy(ball) * (1 + 64 * std::numeric_limits<Scalar>::epsilon()));
    // Long after, the ball is at rest.
    CHECK(billiards::motion(billiards::evolve(ball, cloth, Scalar(1000)), cloth) ==
          billiards::Motion::stationary);
  }
}

TEMPLATE_TEST_CASE("cloth: the 30° rule through collide_with_friction (mu = 0) and evolve",
                   "[runtime][cloth]", float, double) {
  using Scalar = TestType;
  const billiards::Cloth<Scalar> cloth{Scalar(0.2), Scalar(0), Scalar(0)};  // rolls on forever once rolling
  const double pi = std::acos(-1.0);
  double largest = 0, at = 0;
  for (int tenth = 10; tenth <= 890; ++tenth) {
    const double phi = tenth * pi / 1800;
    // A rolling cue ball along x (ω = ẑ × v/R), the object ball at rest, the line of centres at φ.
    const V3<Scalar> v(2, 0, 0), w(0, Scalar(2 / radius), 0);
    const billiards::SpinningBall<Scalar> cue{v, w, Scalar(0.17), Scalar(radius)};
    const billiards::SpinningBall<Scalar> object{V3<Scalar>::Zero(), V3<Scalar>::Zero(), Scalar(0.17),
                                                 Scalar(radius)};
    const V3<Scalar> n(Scalar(std::cos(phi)), Scalar(std::sin(phi)), 0);
    const auto after = billiards::collide_with_friction(cue, object, n, Scalar(1), Scalar(0)).first;
    const billiards::BallOnCloth<Scalar> ball{V3<Scalar>(0, 0, Scalar(radius)), after.velocity,
                                              after.angular_velocity, Scalar(radius)};
    const auto rolling = billiards::evolve(ball, cloth, billiards::transition_time(ball, cloth));
    REQUIRE(billiards::motion(rolling, cloth) == billiards::Motion::rolling);
    const double theta = std::fabs(std::atan2(double(rolling.velocity.y()), double(rolling.velocity.x())));
    const double expected = std::atan(std::sin(phi) * std::cos(phi) / (std::sin(phi) * std::sin(phi) + 0.4));
    INFO("phi " << tenth / 10.0 << "°");
    CHECK(std::fabs(theta - expected) <= (std::is_same_v<Scalar, float> ? 1e-5 : 1e-12));
    if (theta > largest) largest = theta, at = phi;
  }
  CHECK(largest * 180 / pi == Approx(33.75).margin(0.01));
  CHECK(at * 180 / pi == Approx(28.1).margin(0.1));
}

TEMPLATE_TEST_CASE("cloth: a phase without friction lasts forever", "[runtime][cloth]", float, double) {
  using Scalar = TestType;
  const Scalar inf = std::numeric_limits<Scalar>::infinity();
  const auto rolling = on_table<Scalar>(V3<Scalar>(1, 0, 0), V3<Scalar>(0, Scalar(1 / radius), 0));
  const billiards::Cloth<Scalar> no_rolling_resistance{Scalar(0.2), Scalar(0), Scalar(0.044)};
  CHECK(billiards::motion(rolling, no_rolling_resistance) == billiards::Motion::rolling);
  CHECK(billiards::transition_time(rolling, no_rolling_resistance) == inf);
  const auto later = billiards::evolve(rolling, no_rolling_resistance, Scalar(100));
  CHECK(later.velocity == rolling.velocity);
  CHECK(later.position.x() == Approx(100).epsilon(tolerance<Scalar>()));
  const auto sliding = on_table<Scalar>(V3<Scalar>(1, 0, 0), V3<Scalar>::Zero());
  CHECK(billiards::transition_time(sliding, billiards::Cloth<Scalar>{0, Scalar(0.01), 0}) == inf);
  const auto spinning = on_table<Scalar>(V3<Scalar>::Zero(), V3<Scalar>(0, 0, 3));
  CHECK(billiards::motion(spinning, no_rolling_resistance) == billiards::Motion::spinning);
  CHECK(billiards::transition_time(spinning, no_rolling_resistance) ==
        Approx(2 * radius * 3 / (5 * 0.044 * 9.81)).epsilon(tolerance<Scalar>()));
  CHECK(billiards::transition_time(spinning, billiards::Cloth<Scalar>{Scalar(0.2), 0, 0}) == inf);
  const auto still = on_table<Scalar>(V3<Scalar>::Zero(), V3<Scalar>::Zero());
  CHECK(billiards::motion(still, no_rolling_resistance) == billiards::Motion::stationary);
  CHECK(billiards::transition_time(still, no_rolling_resistance) == inf);
  CHECK(billiards::Cloth<Scalar>{1, 1, 1}.gravity == Scalar(9.81));
}

TEMPLATE_TEST_CASE("checked cloth calls reject bad input, naming the argument", "[runtime][cloth]", float,
                   double) {
  using Scalar = TestType;
  const billiards::Cloth<Scalar> cloth{Scalar(0.2), Scalar(0.01), Scalar(0.044)};
  const auto good = on_table<Scalar>(V3<Scalar>(1, 0, 0), V3<Scalar>::Zero());
  const Scalar nan = std::numeric_limits<Scalar>::quiet_NaN();
  const auto rejects = [&](const billiards::BallOnCloth<Scalar>& ball, const billiards::Cloth<Scalar>& c,
                           Scalar t, const char* argument) {
    try {
      static_cast<void>(billiards::checked::evolve(ball, c, t));
      FAIL("accepted; expected a rejection of " << argument);
    } catch (const billiards::invalid_argument& error) {
      CHECK(error.argument() == argument);
      // One line, a vector written "(x, y, z)".
      CHECK(std::string(error.what()).find('\n') == std::string::npos);
      if (argument == std::string("ball.position")) CHECK(error.value().front() == '(');
    }
  };
  auto bad = good;
  bad.position.z() = 0;
  rejects(bad, cloth, 1, "ball.position");
  bad = good;
  bad.velocity.z() = Scalar(0.5);
  rejects(bad, cloth, 1, "ball.velocity");
  bad = good;
  bad.radius = -1;
  rejects(bad, cloth, 1, "ball.radius");
  bad = good;
  bad.angular_velocity.x() = nan;
  rejects(bad, cloth, 1, "ball.angular_velocity");
  rejects(good, {Scalar(-0.1), 0, 0}, 1, "cloth.sliding_friction");
  rejects(good, {0, nan, 0}, 1, "cloth.rolling_friction");
  rejects(good, {0, 0, 0, 0}, 1, "cloth.gravity");
  rejects(good, cloth, -1, "t");
  rejects(good, cloth, std::numeric_limits<Scalar>::infinity(), "t");
  CHECK_THROWS_AS(billiards::checked::motion(bad, cloth), billiards::invalid_argument);
  CHECK_THROWS_AS(billiards::checked::transition_time(good, billiards::Cloth<Scalar>{0, 0, -1}),
                  billiards::invalid_argument);
  CHECK(billiards::checked::evolve(good, cloth, Scalar(0.5)).position ==
        billiards::evolve(good, cloth, Scalar(0.5)).position);
  CHECK(billiards::checked::motion(good, cloth) == billiards::Motion::sliding);
}

// Found by the fuzz harness: with μ_s g near the largest float, 5 μ_s g overflowed, a spin about ẑ
// stopping at once (its stop time rounds to 0) made a step of t = 0 give ∞ · 0 = NaN, and the NaN slip
// read as rolling; the ball then "rolled" at its sliding velocity with its spin snapped, creating
// energy. The slide must follow its closed form and end at the 5/7 rule.
TEST_CASE("cloth: a huge sliding friction beside a spin that stops at once still slides",
          "[runtime][cloth]") {
  using L3 = Eigen::Matrix<long double, 3, 1>;
  const billiards::BallOnCloth<float> ball{V3<float>(1, 0, 0x1p-4f), V3<float>(0, -0x1p+31f, 0),
                                           V3<float>(0, -0x1p+31f, -0x1.fbfbfcp-33f), 0x1p-4f};
  const billiards::Cloth<float> cloth{0x1.f1f1f2p-2f, 0, 0x1.d1d1d2p-1f, 0x1.7cp+127f};
  const L3 v0 = ball.velocity.cast<long double>();
  const L3 slip(-ball.angular_velocity.y() * 0x1p-4L, v0.y(), 0);  // v + ω × (−R ẑ)
  const long double deceleration = (long double)cloth.sliding_friction * cloth.gravity;
  const long double slide = 2 * slip.norm() / (7 * deceleration);
  REQUIRE(billiards::checked::motion(ball, cloth) == billiards::Motion::sliding);
  CHECK(billiards::checked::transition_time(ball, cloth) == Approx(double(slide)).epsilon(1e-5));
  // Within the slide: v0 − μ_s g t û.
  const float t = float(slide / 5);
  const auto sliding = billiards::checked::evolve(ball, cloth, t);
  const L3 expected = v0 - deceleration * t * slip / slip.norm();
  CHECK((sliding.velocity.cast<long double>() - expected).norm() <= 1e-5L * v0.norm());
  CHECK(billiards::motion(sliding, cloth) == billiards::Motion::sliding);
  // After it: rolling at v0 − (2/7) u0 for ever (no rolling resistance), no energy created.
  const auto rolling = billiards::checked::evolve(ball, cloth, 1.0f);
  CHECK((rolling.velocity.cast<long double>() - (v0 - slip * 2 / 7)).norm() <= 1e-5L * v0.norm());
  CHECK(billiards::motion(rolling, cloth) == billiards::Motion::rolling);
  CHECK(energy(rolling) <= energy(ball));
}

TEMPLATE_TEST_CASE("cloth: the rolling test by bounds agrees with the rolling tolerance at its edge",
                   "[runtime][cloth]", float, double) {
  using S = TestType;
  // Balls with velocity and spin in every direction and over many decades (one component dominant, or
  // both alike), and slip speeds around the tolerance: a few ulps either side of it and up to a fifth
  // away; detail::slips (the bounds first) against its definition, slip > rolling_tolerance.
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> unit(0, 1);
  int cases = 0;
  for (int k = 0; k < 20000; ++k) {
    billiards::BallOnCloth<S> ball;
    ball.radius = S(0.028575);
    const double scale = std::pow(10.0, -30 + 60 * unit(random)), lean = unit(random) < 0.3 ? 1e-9 : 1.0;
    ball.velocity = V3<S>(S(scale * (unit(random) - 0.5)), S(scale * lean * (unit(random) - 0.5)), 0);
    ball.angular_velocity =
        V3<S>(S(scale * 40 * lean * (unit(random) - 0.5)), S(scale * 40 * (unit(random) - 0.5)), S(unit(random)));
    const S tolerance = billiards::rolling_tolerance(ball);
    if (!(tolerance > 0) || !std::isfinite(tolerance)) continue;
    S slip = unit(random) < 0.5 ? S(tolerance * (1 + 0.4 * (unit(random) - 0.5))) : tolerance;
    for (int step = static_cast<int>(unit(random) * 9) - 4; step != 0; step += step > 0 ? -1 : 1)
      slip = std::nextafter(slip, step > 0 ? S(1e30) : S(0));
    ++cases;
    CHECK(billiards::detail::slips(ball, slip) == (slip > tolerance));
  }
  CHECK(cases > 15000);
}
