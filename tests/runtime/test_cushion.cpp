// billiards::collide_with_cushion against Han (2005)'s equations 14–23 typed from the paper in long double
// (with μ in the stick/slip test, in the cushion's frame reached by a rotation about ẑ), the paper's
// restitution form and reflection for a frictionless cushion at the equator, the energy, the sense of
// English, frame invariance, and the checked call's errors.
#include "../fuzz/han_2005.hpp"

#include <billiards/shot.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

namespace {

using Long = long double;
using L3 = Eigen::Matrix<Long, 3, 1>;
using billiards_fuzz::han_2005;

template <typename Scalar>
Long off(const Eigen::Matrix<Scalar, 3, 1>& x, const L3& reference, Long scale) {
  return (x.template cast<Long>() - reference).norm() / (Long(std::numeric_limits<Scalar>::epsilon()) * scale);
}

template <typename Scalar>
Long energy(const billiards::SpinningBall<Scalar>& b) {
  const Long m = b.mass, R = b.radius;
  return m * b.velocity.template cast<Long>().squaredNorm() / 2 +
         Long(2) / 5 * m * R * R * b.angular_velocity.template cast<Long>().squaredNorm() / 2;
}

// A ball on the cloth moving into a cushion of random direction, with random spin and parameters; every
// `regime`-th draw has its slip small against the friction, so that both regimes come up.
template <typename S>
struct Draw {
  billiards::SpinningBall<S> ball;
  billiards::Cushion<S> cushion;
};

template <typename S>
Draw<S> draw(std::mt19937_64& random) {
  using V = Eigen::Matrix<S, 3, 1>;
  std::uniform_real_distribution<double> unit(-1, 1), angle(-M_PI, M_PI);
  const S R = S(0.028575 * std::exp(unit(random)));
  const double psi = angle(random);
  const V n(S(std::cos(psi)), S(std::sin(psi)), 0);
  const double speed = 4 * std::exp(2 * unit(random));
  const double heading = psi + 1.5 * unit(random);  // within 86° of the normal
  V v(S(speed * std::cos(heading)), S(speed * std::sin(heading)), 0);
  if (!(v.dot(n) > 0)) v = -v;
  if (!(v.x() * n.x() + v.y() * n.y() > 0)) v = V(n.x(), n.y(), 0);
  const V w = V(S(unit(random)), S(unit(random)), S(unit(random))) * S(2 * speed / R * std::fabs(unit(random)));
  billiards::Cushion<S> cushion{n, S(R * (1 + 0.6 * std::fabs(unit(random)))), S(0.5 + 0.5 * std::fabs(unit(random))),
                                S(std::fabs(unit(random)))};
  return {{v, w, S(0.17 * std::exp(unit(random))), R}, cushion};
}

}  // namespace

TEMPLATE_TEST_CASE("collide_with_cushion: Han (2005)'s equations with μ in the stick/slip test", "[shot][cushion]",
                   float, double) {
  using S = TestType;
  std::mt19937_64 random(2005);
  int sticking = 0;
  for (int i = 0; i < 20000; ++i) {
    const Draw<S> d = draw<S>(random);
    const billiards::SpinningBall<S> after = billiards::collide_with_cushion(d.ball, d.cushion);
    bool sticks = false;
    const billiards::SpinningBall<Long> expected = han_2005(d.ball, d.cushion, &sticks);
    const Long R = d.ball.radius;
    const Long scale = Long(d.ball.velocity.norm()) + R * Long(d.ball.angular_velocity.norm());
    // Near the regimes' border the rounded test may take either side; both agree there to rounding.
    INFO("draw " << i);
    CHECK(off(after.velocity, expected.velocity, scale) <= 64);
    CHECK(off(after.angular_velocity, expected.angular_velocity, scale / R) <= 64);
    CHECK(after.velocity.z() == d.ball.velocity.z());
    CHECK(after.mass == d.ball.mass);
    sticking += sticks;
  }
  CHECK(sticking > 2000);
  CHECK(sticking < 18000);
}

TEMPLATE_TEST_CASE("collide_with_cushion: frictionless at the equator it is the paper's restitution form and reflection",
                   "[shot][cushion]", float, double) {
  using S = TestType;
  using V = Eigen::Matrix<S, 3, 1>;
  const S eps = std::numeric_limits<S>::epsilon();
  const V n = V(S(0.6), S(-0.8), 0);
  for (const S e : {S(1), S(0.8), S(0)}) {
    const billiards::SpinningBall<S> ball{V(S(1.5), S(-2), 0), V(S(30), S(-12), S(44)), S(0.17), S(0.028575)};
    const billiards::SpinningBall<S> after = billiards::collide_with_cushion(ball, billiards::Cushion<S>{n, ball.radius, e, 0});
    const L3 vl = ball.velocity.template cast<Long>(), nl = n.template cast<Long>();
    const L3 expected = vl - (1 + Long(e)) * vl.dot(nl) * nl;
    CHECK(off(after.velocity, expected, vl.norm()) <= 8);
    CHECK(after.angular_velocity == ball.angular_velocity);
    if (e == 1) CHECK(std::fabs(Long(after.velocity.norm()) - vl.norm()) <= 8 * eps * vl.norm());
  }
}

TEMPLATE_TEST_CASE("collide_with_cushion: the ball's energy never increases", "[shot][cushion]", float, double) {
  using S = TestType;
  std::mt19937_64 random(23);
  for (int i = 0; i < 20000; ++i) {
    const Draw<S> d = draw<S>(random);
    const billiards::SpinningBall<S> after = billiards::collide_with_cushion(d.ball, d.cushion);
    INFO("draw " << i);
    CHECK(energy(after) <= energy(d.ball) * (1 + 64 * Long(std::numeric_limits<S>::epsilon())));
  }
}

TEMPLATE_TEST_CASE("collide_with_cushion: running English widens the rebound, reverse English narrows it",
                   "[shot][cushion]", float, double) {
  using S = TestType;
  using V = Eigen::Matrix<S, 3, 1>;
  const S R = S(0.028575);
  const V n(0, 1, 0);  // the cushion along x, ŷ = ẑ × n = −x̂
  const billiards::Cushion<S> cushion{n, S(1.27) * R, S(0.85), S(0.8)};
  // Moving into the cushion and along −x̂, that is along the cushion's ŷ: v_y > 0 in its frame.
  const V v(S(-1), S(1.5), 0);
  const auto angle = [&](S spin_up) {
    const billiards::SpinningBall<S> after =
        billiards::collide_with_cushion(billiards::SpinningBall<S>{v, V(0, 0, spin_up), S(0.17), R}, cushion);
    return std::atan2(std::fabs(after.velocity.x()), std::fabs(after.velocity.y()));  // from the normal
  };
  // In the cushion's frame ω_z is the same: running English is ω_z < 0 for v_y > 0.
  const S plain = angle(0), running = angle(S(-20)), reverse = angle(S(20));
  CHECK(running > plain);
  CHECK(reverse < plain);
}

TEMPLATE_TEST_CASE("collide_with_cushion: a ball not moving into the cushion is returned unchanged", "[shot][cushion]",
                   float, double) {
  using S = TestType;
  using V = Eigen::Matrix<S, 3, 1>;
  const billiards::SpinningBall<S> ball{V(S(-1), S(2), 0), V(S(3), S(4), S(5)), S(0.17), S(0.028575)};
  for (const V& n : {V(1, 0, 0), V(0, -1, 0)}) {
    const billiards::SpinningBall<S> after =
        billiards::collide_with_cushion(ball, billiards::Cushion<S>{n, S(1.27) * ball.radius, S(0.85), S(0.2)});
    CHECK(after.velocity == ball.velocity);
    CHECK(after.angular_velocity == ball.angular_velocity);
  }
}

TEMPLATE_TEST_CASE("checked::collide_with_cushion names the argument it rejects", "[shot][cushion][checked]", float,
                   double) {
  using S = TestType;
  using V = Eigen::Matrix<S, 3, 1>;
  const billiards::SpinningBall<S> ball{V(S(1), S(2), 0), V(S(3), S(4), S(5)), S(0.17), S(0.03125)};
  const billiards::Cushion<S> cushion{V(1, 0, 0), S(0.0390625), S(0.85), S(0.2)};
  const char* name = "billiards::checked::collide_with_cushion: ";
  auto bad = cushion;
  bad.height = S(0.0625);
  CHECK_THROWS_WITH(billiards::checked::collide_with_cushion(ball, bad),
                    Catch::Contains(std::string(name) + "cushion.height is 0.0625, expected a nose height in [R, 2R)"));
  bad = cushion;
  bad.normal = V(S(0.6), 0, S(0.8));
  CHECK_THROWS_WITH(billiards::checked::collide_with_cushion(ball, bad), Catch::Contains("cushion.normal is"));
  bad.normal = V(2, 0, 0);
  CHECK_THROWS_WITH(billiards::checked::collide_with_cushion(ball, bad), Catch::Contains("a unit vector"));
  bad = cushion;
  bad.restitution = S(-0.5);
  CHECK_THROWS_WITH(billiards::checked::collide_with_cushion(ball, bad), Catch::Contains("cushion.restitution is -0.5"));
  bad = cushion;
  bad.friction = std::numeric_limits<S>::quiet_NaN();
  CHECK_THROWS_WITH(billiards::checked::collide_with_cushion(ball, bad), Catch::Contains("cushion.friction is nan"));
  auto flying = ball;
  flying.velocity.z() = S(0.5);
  CHECK_THROWS_WITH(billiards::checked::collide_with_cushion(flying, cushion),
                    Catch::Contains("ball.velocity is") && Catch::Contains("on the cloth"));
  auto weightless = ball;
  weightless.mass = 0;
  CHECK_THROWS_WITH(billiards::checked::collide_with_cushion(weightless, cushion), Catch::Contains("ball.mass is 0"));
  const billiards::SpinningBall<S> after = billiards::checked::collide_with_cushion(ball, cushion);
  const billiards::SpinningBall<S> unchecked = billiards::collide_with_cushion(ball, cushion);
  CHECK(after.velocity == unchecked.velocity);
  CHECK(after.angular_velocity == unchecked.angular_velocity);
}
