/// \file
/// Evolution: a ball's phase on the cloth (sliding, rolling, spinning, at rest), how long it lasts, the
/// centre's constant horizontal acceleration within it, and the ball's state within and at the end of
/// it. The closed forms are the runtime's (billiards::evolve, billiards::motion, the derived phase
/// durations); this header adds what the shot's predictions read of them.
#pragma once

#include <billiards/cloth.hpp>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>

namespace billiards::simulation::shot {

/// What holds a ball in sustained contact (pressing.hpp): nothing, a ball, or a cushion.
enum class Pressed : std::uint8_t {
  none,     ///< free on the cloth
  ball,     ///< pressed against a ball, the two moving together
  cushion,  ///< pressed against a straight cushion, at rest there while its spin runs down
};

/// What ends a piece of sustained contact: the quantity that reaches zero.
enum class PressedEnd {
  first_slip,    ///< the cloth's slip under the pair's first ball (the one behind)
  second_slip,   ///< the cloth's slip under the second ball (the one in front)
  contact_slip,  ///< the slip between the two balls at their contact
  speed,         ///< the pair's speed (both balls together)
  spin,          ///< the spin of a ball pressed against a cushion
};

/// A ball's phase on the cloth from a state at its start: free (evolve's closed forms) or a piece of
/// sustained contact (pressing.hpp: a PressedPiece beside it), in which the centre's and the spin's
/// accelerations are constant.
struct Phase {
  Motion motion = Motion::stationary;                         ///< what the ball does in it
  double duration = std::numeric_limits<double>::infinity();  ///< its length (s; +∞ at rest)
  bool moving = false;                                        ///< the centre moves
  Pressed pressed = Pressed::none;                            ///< free, or what presses the ball
  Eigen::Vector2d acceleration = Eigen::Vector2d::Zero();     ///< the centre's, constant within it (m/s²)
};

/// What a piece of sustained contact adds to its phase.
struct PressedPiece {
  std::size_t partner = 0;                                      ///< the pressing ball's or cushion's index
  PressedEnd ending = PressedEnd::speed;                        ///< what ends the piece
  bool first = false;                                           ///< the pair's first ball (behind)
  Eigen::Vector3d spin_acceleration = Eigen::Vector3d::Zero();  ///< dω/dt (rad/s²)
};

/// The state `tau` seconds into a pressed piece begun in state `s`, with the centre's acceleration `a`
/// and the spin's `alpha` constant: x0 + v0 τ + ½ a τ², v0 + a τ, ω0 + α τ.
[[nodiscard]] inline BallOnCloth<double> pressed_state(const BallOnCloth<double>& s, const Eigen::Vector2d& a,
                                                       const Eigen::Vector3d& alpha, double tau) {
  BallOnCloth<double> out = s;
  if (!(tau > 0)) return out;
  out.position.x() += tau * s.velocity.x() + (0.5 * tau * tau) * a.x();
  out.position.y() += tau * s.velocity.y() + (0.5 * tau * tau) * a.y();
  out.velocity.x() += tau * a.x();
  out.velocity.y() += tau * a.y();
  out.angular_velocity += tau * alpha;
  return out;
}

/// The centre's horizontal acceleration in `phase` from state `s`: −μ_s g û sliding (û the contact's
/// slip direction), −μ_r g v̂ rolling, 0 otherwise.
[[nodiscard]] inline Eigen::Vector2d acceleration(const BallOnCloth<double>& s, Motion phase,
                                                  const Cloth<double>& cloth) {
  Eigen::Vector2d direction;
  double size = 0;
  if (phase == Motion::sliding) {
    const Eigen::Vector3d u = contact_slip(s);
    direction = {u.x(), u.y()};
    size = cloth.sliding_friction * cloth.gravity;
  } else if (phase == Motion::rolling) {
    direction = {s.velocity.x(), s.velocity.y()};
    size = cloth.rolling_friction * cloth.gravity;
  } else {
    return Eigen::Vector2d::Zero();
  }
  return -size * (direction / billiards::detail::horizontal_length(direction.x(), direction.y()));
}

/// phase_of given the contact's slip of `s` (billiards::detail::slip_of), computed once for the motion,
/// the duration and the acceleration; a rolling ball's speed likewise once for its duration and its
/// direction.
[[nodiscard]] inline Phase phase_of(const BallOnCloth<double>& s, const Cloth<double>& cloth,
                                    const billiards::detail::Slip<double>& slip) {
  Phase p;
  p.motion = billiards::detail::motion_with(s, slip);
  p.moving = p.motion == Motion::sliding || p.motion == Motion::rolling;
  if (p.motion == Motion::sliding) {
    p.duration = billiards::detail::phase_duration(s, cloth, p.motion, slip);
    const double k = cloth.sliding_friction * cloth.gravity / slip.speed;
    p.acceleration = {-k * slip.vector.x(), -k * slip.vector.y()};
  } else if (p.motion == Motion::rolling) {
    // phase_duration's and acceleration()'s expressions, with the one speed
    const Eigen::Vector2d v(s.velocity.x(), s.velocity.y());
    const double speed = billiards::detail::horizontal_length(v.x(), v.y());
    p.duration = kernels::spin::roll_time(speed, cloth.rolling_friction, cloth.gravity);
    p.acceleration = -(cloth.rolling_friction * cloth.gravity) * (v / speed);
  } else {
    p.duration = billiards::detail::phase_duration(s, cloth, p.motion, slip);
  }
  return p;
}

/// The phase a ball in state `s` is in: its motion, duration and acceleration.
[[nodiscard]] inline Phase phase_of(const BallOnCloth<double>& s, const Cloth<double>& cloth) {
  return phase_of(s, cloth, billiards::detail::slip_of(s));
}

/// The centre and velocity of a ball `tau` seconds into phase `p` begun in state `s` (within the phase):
/// x0 + v0 τ + ½ a τ² and v0 + a τ, without the spin or a change of phase (billiards::evolve gives
/// those), for the many pairs each event predicts.
[[nodiscard]] inline std::pair<Eigen::Vector2d, Eigen::Vector2d> centre_and_velocity(
    const BallOnCloth<double>& s, const Phase& p, double tau) {
  const Eigen::Vector2d r(s.position.x(), s.position.y()), v(s.velocity.x(), s.velocity.y());
  if (!p.moving || !(tau > 0)) return {r, v};
  return {r + tau * v + (0.5 * tau * tau) * p.acceleration, v + tau * p.acceleration};
}

/// A state that rounding left a sliver short of the end of `phase`, set to that end exactly: rolling
/// without slip after sliding, at rest after rolling, without spin about ẑ after spinning.
[[nodiscard]] inline BallOnCloth<double> finish(const BallOnCloth<double>& s, Motion phase) {
  BallOnCloth<double> out = s;
  const Eigen::Vector3d up(0, 0, 1);
  switch (phase) {
    case Motion::sliding: {
      out.velocity = s.velocity - (2.0 / 7.0) * contact_slip(s);
      out.velocity.z() = 0;
      const Eigen::Vector3d spin = up.cross(out.velocity) / s.radius;
      out.angular_velocity.x() = spin.x();
      out.angular_velocity.y() = spin.y();
      break;
    }
    case Motion::rolling:
      out.velocity.setZero();
      out.angular_velocity.x() = out.angular_velocity.y() = 0;
      break;
    case Motion::spinning: out.angular_velocity.z() = 0; break;
    case Motion::stationary: break;
  }
  return out;
}

/// The state at the end of a phase of `duration` begun in state `s`: evolved by its duration, then set
/// to the next phase exactly (finish) should rounding have left it short. `next` receives the phase
/// that state begins (phase_of, with the slip computed once for that test and the phase) and `next_slip`
/// that slip. `start` is the slip of `s` and `spin_end` when its spin about ẑ stops (NaN where not
/// known): a phase that ends before the spin does, at a normal duration, ends by the one step evolve
/// would take (billiards::detail::advance to the phase's end), without working out the phase again.
[[nodiscard]] inline BallOnCloth<double> end_of_phase(const BallOnCloth<double>& s, Motion phase, double duration,
                                                      const Cloth<double>& cloth, Phase& next,
                                                      const billiards::detail::Slip<double>& start, double spin_end,
                                                      billiards::detail::Slip<double>& next_slip) {
  BallOnCloth<double> end = duration < spin_end && duration >= std::numeric_limits<double>::min()
                                ? billiards::detail::advance(s, cloth, phase, start, duration, true, false)
                                : evolve(s, cloth, duration);
  billiards::detail::Slip<double> slip = billiards::detail::slip_of(end);
  if (billiards::detail::motion_with(end, slip) == phase) {
    end = finish(end, phase);
    slip = billiards::detail::slip_of(end);
  }
  next = phase_of(end, cloth, slip);
  next_slip = slip;
  return end;
}
/// The state at the end of a phase, evolved by evolve's own steps; see the overload given the slip.
[[nodiscard]] inline BallOnCloth<double> end_of_phase(const BallOnCloth<double>& s, Motion phase, double duration,
                                                      const Cloth<double>& cloth, Phase& next) {
  // No spin end known: evolve's steps, which never read the slip passed.
  billiards::detail::Slip<double> next_slip;
  return end_of_phase(s, phase, duration, cloth, next, billiards::detail::Slip<double>{Eigen::Vector3d::Zero(), 0},
                      std::numeric_limits<double>::quiet_NaN(), next_slip);
}
/// The state at the end of a phase; see the overload that gives the next phase too.
[[nodiscard]] inline BallOnCloth<double> end_of_phase(const BallOnCloth<double>& s, Motion phase,
                                                      double duration, const Cloth<double>& cloth) {
  Phase next;
  return end_of_phase(s, phase, duration, cloth, next);
}

/// The kinetic energy of a ball of mass `mass` (J): ½ m v² + ⅕ m R² ω² (a solid sphere).
[[nodiscard]] inline double kinetic_energy(const BallOnCloth<double>& s, double mass) {
  return 0.5 * mass * s.velocity.squaredNorm() +
         0.2 * mass * s.radius * s.radius * s.angular_velocity.squaredNorm();
}

}  // namespace billiards::simulation::shot
