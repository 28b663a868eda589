/// \file
/// Resolution: what a contact does to the balls it involves — two balls by billiards::collide_with_friction,
/// a ball and a cushion's nose or a jaw by billiards::collide_with_cushion (the vertical velocity a
/// contact gives dropped: the cloth's reaction keeps a ball on it) — and the pressed contacts off the line
/// of the contact (pressing.hpp takes those on it): bodies the cloth's friction presses together leave a
/// contact separating at least at a given speed, the energy taken from their motion along the contact
/// plane and then from their spins.
#pragma once

#include <billiards/simulation/shot/evolution.hpp>
#include <billiards/simulation/shot/pool_table.hpp>

#include <billiards/cloth.hpp>
#include <billiards/shot.hpp>
#include <billiards/spin.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace billiards::simulation::shot {

/// A ball on the cloth as the contact laws take it: its velocities and mass.
[[nodiscard]] inline SpinningBall<double> spinning(const BallOnCloth<double>& s, double mass) {
  return {s.velocity, s.angular_velocity, mass, s.radius};
}

/// `s` with the velocities a contact left (`after`), its vertical velocity dropped.
inline void take(BallOnCloth<double>& s, const SpinningBall<double>& after) {
  s.velocity = after.velocity;
  s.velocity.z() = 0;  // the cloth's reaction: a ball on the cloth stays on it
  s.angular_velocity = after.angular_velocity;
}

/// The unit normal from ball `a`'s centre towards ball `b`'s, on the cloth's plane.
[[nodiscard]] inline Eigen::Vector3d towards(const BallOnCloth<double>& a, const BallOnCloth<double>& b) {
  Eigen::Vector3d n = b.position - a.position;
  n.z() = 0;
  return n / n.norm();
}

/// The states after two balls `a` and `b` meet along `n`, the unit normal from a's centre to b's
/// (towards(a, b)), by billiards::collide_with_friction; empty where the contact changes nothing (the
/// balls no longer approach: rounding at a graze).
[[nodiscard]] inline std::optional<std::pair<SpinningBall<double>, SpinningBall<double>>> ball_ball(
    const BallOnCloth<double>& a, const BallOnCloth<double>& b, const Eigen::Vector3d& n,
    const PoolPhysics& physics) {
  const auto after = collide_with_friction(spinning(a, physics.mass), spinning(b, physics.mass), n,
                                           physics.ball_restitution, physics.ball_friction);
  const auto same = [](const SpinningBall<double>& x, const BallOnCloth<double>& y) {
    return x.velocity == y.velocity && x.angular_velocity == y.angular_velocity;
  };
  if (same(after.first, a) && same(after.second, b)) return std::nullopt;
  return std::pair{after.first, after.second};
}

/// The unit normal from a ball's centre towards a straight cushion.
[[nodiscard]] inline Eigen::Vector3d towards(const CushionSegment& cushion) {
  return {-cushion.normal.x(), -cushion.normal.y(), 0};
}
/// The unit normal from a ball's centre `position` towards a jaw's axis.
[[nodiscard]] inline Eigen::Vector3d towards(const Jaw& jaw, const Eigen::Vector3d& position) {
  const Eigen::Vector2d d = jaw.centre - Eigen::Vector2d(position.x(), position.y());
  return {d.x() / d.norm(), d.y() / d.norm(), 0};
}

/// The state after ball `a` meets a cushion's nose or a jaw along `normal` (from the ball towards it),
/// by billiards::collide_with_cushion at the table's nose height; empty where the contact changes
/// nothing.
[[nodiscard]] inline std::optional<SpinningBall<double>> ball_cushion(const BallOnCloth<double>& a,
                                                                      const Eigen::Vector3d& normal,
                                                                      const PoolTable& table,
                                                                      const PoolPhysics& physics) {
  const SpinningBall<double> after = collide_with_cushion(
      spinning(a, physics.mass),
      Cushion<double>{normal, table.nose_height, physics.cushion_restitution, physics.cushion_friction});
  if (after.velocity == a.velocity && after.angular_velocity == a.angular_velocity) return std::nullopt;
  return after;
}

/// A pressed contact's new separation speed and the factors for the relative velocity along the contact
/// plane and for the spins.
struct Separation {
  double normal;             ///< the separation speed (m/s)
  double tangential_factor;  ///< the factor for the relative velocity along the contact plane
  double spin_factor;        ///< the factor for the spins
};

/// Bodies leaving a contact at `normal` (their separation speed, below `speed`) raised to `speed`, paid
/// for first from the relative velocity along the contact plane (`tangential_squared` its square) and
/// then from the spins (`spin_energy`), all in units of the reduced mass's half, so that the energy is
/// kept. Where both are spent the separation stays below `speed`.
[[nodiscard]] inline Separation separation(double normal, double tangential_squared, double spin_energy,
                                           double speed) {
  const double need = speed * speed - normal * normal;
  const double from_tangential = std::min(need, tangential_squared);
  const double from_spin = std::min(need - from_tangential, spin_energy);
  return {
      std::sqrt(normal * normal + from_tangential + from_spin),
      tangential_squared > 0 ? std::sqrt((tangential_squared - from_tangential) / tangential_squared) : 1.0,
      spin_energy > 0 ? std::sqrt(std::max(spin_energy - from_spin, 0.0) / spin_energy) : 1.0};
}

/// Whether the cloth presses balls `a` and `b` together along `normal` (from a to b): their relative
/// acceleration in their phases closes the gap.
[[nodiscard]] inline bool presses(const BallOnCloth<double>& a, const BallOnCloth<double>& b,
                                  const Eigen::Vector3d& normal, const Cloth<double>& cloth) {
  const Eigen::Vector2d pressing =
      acceleration(b, motion(b, cloth), cloth) - acceleration(a, motion(a, cloth), cloth);
  return pressing.dot(Eigen::Vector2d(normal.x(), normal.y())) < 0;
}

/// Whether the cloth presses ball `a` into a cushion or jaw along `normal` (from the ball towards it).
[[nodiscard]] inline bool presses(const BallOnCloth<double>& a, const Eigen::Vector3d& normal,
                                  const Cloth<double>& cloth) {
  return acceleration(a, motion(a, cloth), cloth).dot(Eigen::Vector2d(normal.x(), normal.y())) > 0;
}

/// Two balls of equal mass after their contact along `normal` (from a to b): where the cloth presses them
/// together (the relative acceleration along the normal closes the gap) and they separate slower than
/// `speed`, they are made to separate at `speed` (separation()), momentum kept. Returns whether it
/// changed them.
inline bool separate_pressed_pair(BallOnCloth<double>& a, BallOnCloth<double>& b,
                                  const Eigen::Vector3d& normal, const Cloth<double>& cloth, double speed) {
  const Eigen::Vector2d n(normal.x(), normal.y());
  const Eigen::Vector2d va(a.velocity.x(), a.velocity.y()), vb(b.velocity.x(), b.velocity.y());
  const Eigen::Vector2d centre = 0.5 * (va + vb), w = vb - va;
  const double along = w.dot(n);
  if (!(along < speed) || !presses(a, b, normal, cloth)) return false;
  const Eigen::Vector2d tangential = w - along * n;
  const double R = a.radius;
  // Rotational energy 0.2 m R² ω² per ball, in units of m/4.
  const double spin = 0.8 * R * R * (a.angular_velocity.squaredNorm() + b.angular_velocity.squaredNorm());
  const Separation s = separation(along, tangential.squaredNorm(), spin, speed);
  const Eigen::Vector2d turned = s.normal * n + s.tangential_factor * tangential;
  a.velocity.head<2>() = centre - 0.5 * turned;
  b.velocity.head<2>() = centre + 0.5 * turned;
  a.angular_velocity *= s.spin_factor;
  b.angular_velocity *= s.spin_factor;
  return true;
}

/// A ball after its contact with a cushion or jaw, `normal` from the ball towards it: where the cloth
/// presses it into the cushion and it leaves slower than `speed`, it is made to leave at `speed`
/// (separation()). Returns whether it changed the ball.
inline bool separate_pressed_ball(BallOnCloth<double>& a, const Eigen::Vector3d& normal,
                                  const Cloth<double>& cloth, double speed) {
  const Eigen::Vector2d n(-normal.x(), -normal.y());  // from the cushion or jaw into the table
  const Eigen::Vector2d v(a.velocity.x(), a.velocity.y());
  const double along = v.dot(n);
  if (!(along < speed) || !presses(a, normal, cloth)) return false;
  const Eigen::Vector2d tangential = v - along * n;
  const double R = a.radius;
  // Rotational energy 0.2 m R² ω², in units of m/2.
  const Separation s =
      separation(along, tangential.squaredNorm(), 0.4 * R * R * a.angular_velocity.squaredNorm(), speed);
  a.velocity.head<2>() = s.normal * n + s.tangential_factor * tangential;
  a.angular_velocity *= s.spin_factor;
  return true;
}

}  // namespace billiards::simulation::shot
