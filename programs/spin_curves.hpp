// The published curves of spinning balls, computed through billiards::runtime as a user would, beside
// the closed forms they are known by (the figures of billiards-spin-figures and its tests):
// - the throw of a stun shot (Alciatore, technical proof TP A-14): the object ball leaves
//   atan(min(μ, tan φ/7)) off the line of centres at cut angle φ, for e = 1;
// - the 30° rule: a rolling cue ball after a frictionless elastic hit at cut angle φ leaves, once it
//   rolls again, at θ = atan(sin φ cos φ/(sin² φ + 2/5)) from its original line.
#pragma once

#include <billiards/cloth.hpp>
#include <billiards/spin.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace billiards::programs {

/// A pool ball: 57.15 mm across, 170 g (the table example's too).
inline constexpr double pool_ball_radius = 0.028575, pool_ball_mass = 0.17;

/// The throw angle in radians of the object ball of a stun shot at cut angle `cut_angle` (radians, in
/// (0, π/2)): the cue ball slides at 2 m/s without spin into an equal object ball at rest, through
/// billiards::collide_with_friction with `friction` and `restitution`; the throw is the angle between
/// the line of centres and the object ball's departure.
inline double stun_shot_throw(double cut_angle, double friction, double restitution = 1) {
  using V = Eigen::Vector3d;
  const billiards::SpinningBall<double> cue{V(2, 0, 0), V::Zero(), pool_ball_mass, pool_ball_radius};
  const billiards::SpinningBall<double> object{V::Zero(), V::Zero(), pool_ball_mass, pool_ball_radius};
  const V n(std::cos(cut_angle), std::sin(cut_angle), 0);
  const auto after = billiards::checked::collide_with_friction(cue, object, n, restitution, friction).second;
  return cut_angle - std::atan2(after.velocity.y(), after.velocity.x());
}

/// TP A-14's throw for e = 1, the reference stun_shot_throw is drawn against.
inline double stun_shot_throw_formula(double cut_angle, double friction) {
  return std::atan(std::min(friction, std::tan(cut_angle) / 7));
}

/// The angle in radians between a rolling cue ball's line before and after it hits an equal object ball
/// at rest at cut angle `cut_angle` (radians, in (0, π/2)), frictionless and elastic
/// (collide_with_friction with μ = 0, e = 1), measured once the cue ball rolls again on a cloth with
/// sliding friction 0.2 and no rolling resistance (billiards::evolve through the sliding phase).
inline double thirty_degree_deflection(double cut_angle) {
  using V = Eigen::Vector3d;
  // Rolling along x: ω = ẑ × v/R.
  const billiards::SpinningBall<double> cue{V(2, 0, 0), V(0, 2 / pool_ball_radius, 0), pool_ball_mass,
                                            pool_ball_radius};
  const billiards::SpinningBall<double> object{V::Zero(), V::Zero(), pool_ball_mass, pool_ball_radius};
  const V n(std::cos(cut_angle), std::sin(cut_angle), 0);
  const auto after = billiards::checked::collide_with_friction(cue, object, n, 1.0, 0.0).first;
  const billiards::Cloth<double> cloth{0.2, 0, 0};
  const billiards::BallOnCloth<double> ball{V(0, 0, pool_ball_radius), after.velocity, after.angular_velocity,
                                            pool_ball_radius};
  const auto rolling =
      billiards::checked::evolve(ball, cloth, billiards::checked::transition_time(ball, cloth));
  if (billiards::checked::motion(rolling, cloth) != billiards::Motion::rolling) {
    throw std::logic_error("thirty_degree_deflection: the cue ball does not roll after its sliding phase");
  }
  return std::fabs(std::atan2(rolling.velocity.y(), rolling.velocity.x()));
}

/// The 30° rule's closed form, the reference thirty_degree_deflection is drawn against.
inline double thirty_degree_formula(double cut_angle) {
  const double s = std::sin(cut_angle), c = std::cos(cut_angle);
  return std::atan(s * c / (s * s + 0.4));
}

}  // namespace billiards::programs
