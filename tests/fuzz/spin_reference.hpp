// The fuzz harness's references for the spinning-ball calls: collide_with_friction and a ball on the
// cloth computed again in long double from the formulas as the guides print them (the
// impulse J = J_n n − j û_t with j = min(μ J_n, |u_t|/k), k = (7/2)(1/m1 + 1/m2); each phase's closed
// form), not from the kernels, with the rounding the calls may add as an explicit bound.
#pragma once

#include "reference.hpp"

#include <billiards/cloth.hpp>
#include <billiards/spin.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace billiards_fuzz {

using Long3 = Eigen::Matrix<Long, 3, 1>;

/// What collide_with_friction must return: the reference state of each ball with a bound on each
/// vector's distance from it; or, on the edge of approaching, the inputs unchanged (bit for bit) too.
struct ExpectedSpin {
  Long3 v1, w1, v2, w2;
  Long v_bound1 = 0, w_bound1 = 0, v_bound2 = 0, w_bound2 = 0;
  bool collision = true, unchanged = false;
};

template <typename Scalar>
ExpectedSpin expected_friction_collision(const billiards::SpinningBall<Scalar>& a,
                                         const billiards::SpinningBall<Scalar>& b,
                                         const Eigen::Matrix<Scalar, 3, 1>& normal, Scalar e_, Scalar mu_) {
  const Long3 n = normal.template cast<Long>(), v1 = a.velocity.template cast<Long>(),
              w1 = a.angular_velocity.template cast<Long>(), v2 = b.velocity.template cast<Long>(),
              w2 = b.angular_velocity.template cast<Long>();
  const Long m1 = a.mass, m2 = b.mass, R1 = a.radius, R2 = b.radius, e = e_, mu = mu_;
  const Long epsilon = std::numeric_limits<Scalar>::epsilon(),
             tiny = std::numeric_limits<Scalar>::denorm_min();
  const Long s = (v2 - v1).dot(n);
  const Long uncertain = tolerance * epsilon * (v1.norm() + v2.norm()) + 16 * tiny;
  ExpectedSpin expected;
  expected.collision = s < uncertain;
  expected.unchanged = s >= -uncertain;
  const Long Jn = (1 + e) * m1 * m2 / (m1 + m2) * std::fabs(s);
  const Long3 u = (v2 + w2.cross(-R2 * n)) - (v1 + w1.cross(R1 * n));
  const Long3 ut = u - u.dot(n) * n;
  const Long slip = ut.norm(), k = Long(3.5) * (1 / m1 + 1 / m2);
  const Long j = slip > 0 ? std::min(mu * Jn, slip / k) : 0;
  const Long3 direction = slip > 0 ? Long3(ut / slip) : Long3::Zero();
  const Long3 J = Jn * n - j * direction;  // on ball 2
  expected.v1 = v1 - J / m1;
  expected.v2 = v2 + J / m2;
  expected.w1 = w1 + Long(2.5) * j / (m1 * R1) * n.cross(direction);
  expected.w2 = w2 + Long(2.5) * j / (m2 * R2) * n.cross(direction);
  // Rounding: relative to the velocities and contact-point speeds that enter the slip and the normal
  // speed (a direction û_t ill-determined by rounding carries a j/m of the same order), and absolute
  // at the smallest subnormal, which a spin change scales by 5/(2R), and in every result's own rounding.
  const Long scale = v1.norm() + v2.norm() + R1 * w1.norm() + R2 * w2.norm() + 2 * std::fabs(s);
  const Long underflow = 16 * tiny * (v1.lpNorm<1>() + v2.lpNorm<1>() + 3);
  expected.v_bound1 = tolerance * epsilon * (v1.norm() + scale) + underflow;
  expected.v_bound2 = tolerance * epsilon * (v2.norm() + scale) + underflow;
  expected.w_bound1 =
      tolerance * epsilon * (w1.norm() + Long(2.5) * scale / R1) + Long(2.5) * underflow / R1 + 4 * tiny;
  expected.w_bound2 =
      tolerance * epsilon * (w2.norm() + Long(2.5) * scale / R2) + Long(2.5) * underflow / R2 + 4 * tiny;
  // Within rounding of touching, the normal impulse is uncertain by (1 + e) μ_red times the rounding of
  // (v2 − v1)·n, and so is the friction it allows: anything up to that bound (or sticking) is right.
  if (expected.unchanged && slip > 0) {
    const Long j_most = std::min(mu * (1 + e) * m1 * m2 / (m1 + m2) * (std::fabs(s) + uncertain), slip / k);
    expected.v_bound1 += j_most / m1;
    expected.v_bound2 += j_most / m2;
    expected.w_bound1 += Long(2.5) * j_most / (m1 * R1);
    expected.w_bound2 += Long(2.5) * j_most / (m2 * R2);
  }
  return expected;
}

/// nullptr when `result` is right, else what is wrong.
template <typename Scalar>
const char* compare_spin(const billiards::Collision<billiards::SpinningBall<Scalar>>& result,
                         const billiards::SpinningBall<Scalar>& a, const billiards::SpinningBall<Scalar>& b,
                         const ExpectedSpin& expected) {
  const auto same = [](const billiards::SpinningBall<Scalar>& x, const billiards::SpinningBall<Scalar>& y) {
    return same_bits(x.velocity, y.velocity) && same_bits(x.angular_velocity, y.angular_velocity);
  };
  if (expected.unchanged && same(result.first, a) && same(result.second, b)) return nullptr;
  if (!expected.collision) return "a separating pair was not returned unchanged (bit for bit)";
  const auto off = [](const Eigen::Matrix<Scalar, 3, 1>& x, const Long3& reference) {
    return (x.template cast<Long>() - reference).norm();
  };
  if (!(off(result.first.velocity, expected.v1) <= expected.v_bound1) ||
      !(off(result.second.velocity, expected.v2) <= expected.v_bound2))
    return "a velocity farther from the reference than rounding allows";
  if (!(off(result.first.angular_velocity, expected.w1) <= expected.w_bound1) ||
      !(off(result.second.angular_velocity, expected.w2) <= expected.w_bound2))
    return "an angular velocity farther from the reference than rounding allows";
  return nullptr;
}

/// m (|v|² + (2/5) R² |ω|²), twice the kinetic energy, in long double.
template <typename Scalar>
Long twice_energy(Long mass, Long radius, const Eigen::Matrix<Scalar, 3, 1>& v,
                  const Eigen::Matrix<Scalar, 3, 1>& w) {
  return mass * (v.template cast<Long>().squaredNorm() +
                 Long(0.4) * radius * radius * w.template cast<Long>().squaredNorm());
}

/// The most twice_energy() of one ball's results can gain from rounding below the normal range: each
/// velocity and spin is known only to a few times the smallest subnormal δ there, and an error δ in ω
/// carries (2/5) m R² (2|ω| + δ) δ of it — with R = 2^124 an ω_y of 2^−149 left unchanged (its change
/// of 2^−154 underflowed) holds more energy than a velocity of 2e-10 (float; found by a fuzz run of
/// 9 minutes).
template <typename Scalar>
Long subnormal_energy(Long mass, Long radius, const Eigen::Matrix<Scalar, 3, 1>& v_before,
                      const Eigen::Matrix<Scalar, 3, 1>& w_before, const Eigen::Matrix<Scalar, 3, 1>& v_after,
                      const Eigen::Matrix<Scalar, 3, 1>& w_after) {
  const Long delta = 4 * Long(std::numeric_limits<Scalar>::denorm_min());
  const auto size = [](const Eigen::Matrix<Scalar, 3, 1>& x) { return x.template cast<Long>().norm(); };
  return mass * delta *
         (size(v_before) + size(v_after) + delta +
          Long(0.4) * radius * radius * (size(w_before) + size(w_after) + delta));
}

/// A ball on the cloth after t within one phase, by its closed form (sliding: v0 − μ_s g t û,
/// ω_h0 + (5 μ_s g t/(2R)) ẑ × û; rolling: v0 − μ_r g t v̂ with ω_h = ẑ × v/R; the spin about ẑ
/// decaying at 5 μ_sp g/(2R) to 0 in any phase), or nothing when the phase is not clear beyond
/// rounding or t comes within rounding of the phase's end. `bound` receives the rounding allowed on
/// the position, the velocity and the angular velocity.
struct ExpectedCloth {
  bool known = false;
  Long3 position, velocity, angular_velocity;
  Long position_bound = 0, velocity_bound = 0, angular_bound = 0;
};

template <typename Scalar>
ExpectedCloth expected_on_cloth(const billiards::BallOnCloth<Scalar>& ball,
                                const billiards::Cloth<Scalar>& cloth, Scalar t_) {
  ExpectedCloth expected;
  const Long3 p = ball.position.template cast<Long>(), v = ball.velocity.template cast<Long>(),
              w = ball.angular_velocity.template cast<Long>();
  const Long R = ball.radius, g = cloth.gravity, t = t_;
  const Long epsilon = std::numeric_limits<Scalar>::epsilon();
  const Long3 up(0, 0, 1);
  Long3 slip = v + w.cross(-R * up);
  slip.z() = 0;
  const Long3 horizontal(v.x(), v.y(), 0);
  const Long speed = horizontal.norm(), spin = std::hypot(w.x(), w.y()), slip_speed = slip.norm();
  // The runtime's rolling tolerance, 16 ε (|v| + R |ω_h|): clear of it by a factor of 4 either way.
  const Long rolling_tolerance = 16 * epsilon * (speed + R * spin);
  // Below the normal range the slip's terms round to multiples of the smallest subnormal whatever the
  // tolerance (float: v = 2^−149 and R ω_x = −2^−149 (1 − 5e-5) round to a slip of exactly 0, rolling,
  // where the exact slip of 7e-50 is sliding by the relative test; found by a fuzz run of 9 minutes).
  const Long slip_rounding = 4 * Long(std::numeric_limits<Scalar>::denorm_min());
  const bool sliding = slip_speed > 4 * rolling_tolerance + slip_rounding,
             rolling = slip_speed + slip_rounding < rolling_tolerance / 4 && speed > 0;
  if (!sliding && !rolling) return expected;
  const Long mu = sliding ? Long(cloth.sliding_friction) : Long(cloth.rolling_friction);
  const Long end = mu > 0 ? (sliding ? 2 * slip_speed / (7 * mu * g) : speed / (mu * g))
                          : std::numeric_limits<Long>::infinity();
  if (!(t <= end * (1 - 1e-3L))) return expected;
  const Long3 direction = sliding ? Long3(slip / slip_speed) : Long3(horizontal / speed);
  const Long deceleration = mu * g;
  expected.velocity = horizontal - deceleration * t * direction;
  expected.position = p + horizontal * t - deceleration * t * t / 2 * direction;
  expected.position.z() = p.z();
  const Long3 turned = sliding ? Long3(w + Long(2.5) * deceleration * t / R * up.cross(direction))
                               : Long3(up.cross(expected.velocity) / R);
  const Long spin_decay = Long(2.5) * Long(cloth.spinning_friction) * g * t / R;
  expected.angular_velocity =
      Long3(turned.x(), turned.y(), std::copysign(std::max(std::fabs(w.z()) - spin_decay, Long(0)), w.z()));
  // Rounding of each closed form's terms, and of the spin about ẑ near its stop (a step at its stop
  // time, then the rest of the phase); absolute at the smallest subnormal where a product such as
  // μ g t underflows (scaled by 1/R in a spin change).
  const Long K = tolerance * epsilon, moved = speed * t + deceleration * t * t;
  const Long tiny = 8 * Long(std::numeric_limits<Scalar>::denorm_min());
  expected.position_bound = K * (p.norm() + moved) + K * moved + tiny;
  expected.velocity_bound = K * (speed + deceleration * t) + tiny;
  expected.angular_bound =
      K * (w.norm() + (speed + deceleration * t) / R + Long(2.5) * deceleration * t / R + spin_decay) + tiny +
      tiny / R;
  expected.known = true;
  return expected;
}

}  // namespace billiards_fuzz
