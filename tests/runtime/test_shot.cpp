// billiards::strike against the impulse equations written out by hand in long double (Δv = J/m d,
// Δω = I⁻¹ r × J d, J from the tip's restitution), TP A-30's closed forms for a ball at rest, natural
// roll, a centre hit, the energy of cue and ball, and the checked call's errors.
#include <billiards/shot.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

namespace {

using Long = long double;
using L3 = Eigen::Matrix<Long, 3, 1>;

// The strike from the definitions: the frame, the contact point, J from restitution along d.
template <typename Scalar>
billiards::SpinningBall<Long> by_hand(const billiards::SpinningBall<Scalar>& ball, const billiards::Cue<Scalar>& cue) {
  const Long phi = cue.azimuth, theta = cue.elevation, a = cue.side_offset, b = cue.up_offset;
  const L3 d(std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), -std::sin(theta));
  const L3 s(std::sin(phi), -std::cos(phi), 0);
  const L3 u = s.cross(d);
  const Long m = ball.mass, R = ball.radius, M = cue.mass, e = cue.tip_restitution;
  const L3 r = R * (a * s + b * u - std::sqrt(1 - a * a - b * b) * d);
  const L3 v = ball.velocity.template cast<Long>(), w = ball.angular_velocity.template cast<Long>();
  const Long inertia = Long(2) / 5 * m * R * R;
  const Long approach = Long(cue.speed) - (v + w.cross(r)).dot(d);
  billiards::SpinningBall<Long> out{v, w, m, R};
  if (approach <= 0) return out;
  // (v' + ω' × r)·d − V' = e (V − (v + ω × r)·d), with v' = v + J d/m, ω' = ω + r × J d/I, V' = V − J/M.
  const Long response = 1 / m + 1 / M + r.cross(d).dot(r.cross(d)) / inertia;
  const Long J = (1 + e) * approach / response;
  out.velocity = v + J / m * d;
  out.angular_velocity = w + r.cross(J * d) / inertia;
  return out;
}

template <typename Scalar>
Long off(const Eigen::Matrix<Scalar, 3, 1>& x, const L3& reference, Long scale) {
  return (x.template cast<Long>() - reference).norm() / (Long(std::numeric_limits<Scalar>::epsilon()) * scale);
}

}  // namespace

TEMPLATE_TEST_CASE("strike: a ball at rest gets TP A-30's speed and spin", "[shot]", float, double) {
  using S = TestType;
  using V = Eigen::Matrix<S, 3, 1>;
  const billiards::SpinningBall<S> ball{V::Zero(), V::Zero(), S(0.17), S(0.028575)};
  for (const S a : {S(0), S(0.25), S(-0.5)}) {
    for (const S b : {S(0), S(0.4), S(-0.3)}) {
      for (const S e : {S(1), S(0.75)}) {
        const billiards::Cue<S> cue{S(0.54), S(3), S(0.7), S(0.1), a, b, e};
        const billiards::SpinningBall<S> struck = billiards::strike(ball, cue);
        const billiards::SpinningBall<Long> expected = by_hand(ball, cue);
        const Long speed = (1 + Long(e)) * 3 / (1 + Long(0.17) / Long(0.54) + Long(2.5) * (Long(a) * a + Long(b) * b));
        CHECK(std::fabs(Long(struck.velocity.norm()) - speed) <= 16 * std::numeric_limits<S>::epsilon() * speed);
        CHECK(off(struck.velocity, expected.velocity, speed) <= 16);
        CHECK(off(struck.angular_velocity, expected.angular_velocity, speed / Long(0.028575)) <= 32);
      }
    }
  }
}

TEMPLATE_TEST_CASE("strike: natural roll at b = 2/5, no spin from a centre hit", "[shot]", float, double) {
  using S = TestType;
  using V = Eigen::Matrix<S, 3, 1>;
  const billiards::SpinningBall<S> ball{V::Zero(), V::Zero(), S(0.17), S(0.028575)};
  const billiards::SpinningBall<S> rolled = billiards::strike(ball, billiards::Cue<S>{S(0.54), S(2), S(1.1), 0, 0, S(0.4), 1});
  const V slip = rolled.velocity + rolled.angular_velocity.cross(V(0, 0, -ball.radius));
  CHECK(slip.norm() <= 16 * std::numeric_limits<S>::epsilon() * rolled.velocity.norm());
  const billiards::SpinningBall<S> centre = billiards::strike(ball, billiards::Cue<S>{S(0.54), S(2), S(-2), S(0.3), 0, 0, 1});
  CHECK(centre.angular_velocity.norm() <= 4 * std::numeric_limits<S>::epsilon() * centre.velocity.norm() / ball.radius);
}

TEMPLATE_TEST_CASE("strike: the energy of cue and ball is kept for e_tip = 1 and lost below", "[shot]", float, double) {
  using S = TestType;
  using V = Eigen::Matrix<S, 3, 1>;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int i = 0; i < 1000; ++i) {
    const billiards::SpinningBall<S> ball{V(S(unit(random)), S(unit(random)), 0),
                                          V(S(30 * unit(random)), S(30 * unit(random)), S(30 * unit(random))),
                                          S(0.17), S(0.028575)};
    const S e = i % 2 ? S(1) : S(0.5 + 0.5 * std::fabs(unit(random)));
    const billiards::Cue<S> cue{S(0.54), S(4 + unit(random)), S(3 * unit(random)), S(0.5 * std::fabs(unit(random))),
                                S(0.6 * unit(random)), S(0.6 * unit(random)), e};
    const billiards::SpinningBall<S> struck = billiards::strike(ball, cue);
    const billiards::SpinningBall<Long> expected = by_hand(ball, cue);
    const Long scale = Long(cue.speed) + Long(ball.velocity.norm()) + Long(ball.radius * ball.angular_velocity.norm());
    CHECK(off(struck.velocity, expected.velocity, scale) <= 64);
    CHECK(off(struck.angular_velocity, expected.angular_velocity, scale / Long(ball.radius)) <= 64);
    // The cue's speed after, V − J/M with J = m |Δv|, and the energies in long double.
    const Long J = Long(ball.mass) * (expected.velocity - ball.velocity.template cast<Long>()).norm();
    const Long inertia = Long(2) / 5 * Long(ball.mass) * Long(ball.radius) * Long(ball.radius);
    const auto energy = [&](Long cue_speed, const L3& v, const L3& w) {
      return Long(cue.mass) * cue_speed * cue_speed / 2 + Long(ball.mass) * v.squaredNorm() / 2 + inertia * w.squaredNorm() / 2;
    };
    const Long before = energy(cue.speed, ball.velocity.template cast<Long>(), ball.angular_velocity.template cast<Long>());
    const Long after = energy(Long(cue.speed) - J / Long(cue.mass), struck.velocity.template cast<Long>(),
                              struck.angular_velocity.template cast<Long>());
    if (e == 1) {
      CHECK(std::fabs(after - before) <= 256 * std::numeric_limits<S>::epsilon() * before);
    } else {
      CHECK(after <= before * (1 + 256 * std::numeric_limits<S>::epsilon()));
    }
  }
}

TEMPLATE_TEST_CASE("strike: a tip that does not catch the ball leaves it alone", "[shot]", float, double) {
  using S = TestType;
  using V = Eigen::Matrix<S, 3, 1>;
  // The ball runs away along the cue's axis faster than the cue: no contact.
  const billiards::SpinningBall<S> ball{V(5, 0, 0), V::Zero(), S(0.17), S(0.028575)};
  const billiards::SpinningBall<S> same = billiards::strike(ball, billiards::Cue<S>{S(0.54), S(2), 0, 0, 0, 0, 1});
  CHECK(same.velocity == ball.velocity);
  CHECK(same.angular_velocity == ball.angular_velocity);
}

TEMPLATE_TEST_CASE("checked::strike names the argument it rejects", "[shot][checked]", float, double) {
  using S = TestType;
  using V = Eigen::Matrix<S, 3, 1>;
  const billiards::SpinningBall<S> ball{V::Zero(), V::Zero(), S(0.17), S(0.028575)};
  const billiards::Cue<S> cue{S(0.54), S(2), 0, 0, 0, 0, 1};
  auto bad = cue;
  bad.up_offset = S(0.875);
  bad.side_offset = S(0.5);
  CHECK_THROWS_WITH(billiards::checked::strike(ball, bad), Catch::Contains("billiards::checked::strike: cue.up_offset is 0.875"));
  bad = cue;
  bad.elevation = S(2);
  CHECK_THROWS_WITH(billiards::checked::strike(ball, bad), Catch::Contains("cue.elevation is 2, expected an angle in [0, pi/2)"));
  bad = cue;
  bad.tip_restitution = S(1.5);
  CHECK_THROWS_WITH(billiards::checked::strike(ball, bad), Catch::Contains("cue.tip_restitution is 1.5"));
  bad = cue;
  bad.mass = 0;
  CHECK_THROWS_WITH(billiards::checked::strike(ball, bad), Catch::Contains("cue.mass is 0"));
  auto heavy = ball;
  heavy.radius = -1;
  CHECK_THROWS_WITH(billiards::checked::strike(heavy, cue), Catch::Contains("ball.radius is -1"));
  const billiards::SpinningBall<S> struck = billiards::checked::strike(ball, cue);
  CHECK(struck.velocity == billiards::strike(ball, cue).velocity);
}
