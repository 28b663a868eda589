// billiards::collide_with_friction: two spinning solid spheres meeting with Coulomb friction at the
// contact (the spinning-ball model's audit, generated/spinning/AUDIT.md), on top of the generated
// kernels of billiards/spin_kernels.hpp and the restitution kernel of billiards/kernels.hpp.
#pragma once

#include <billiards/checked.hpp>
#include <billiards/collision.hpp>
#include <billiards/spin_kernels.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cassert>
#include <cmath>
#include <string>

namespace billiards {

/// A solid uniform sphere (moment of inertia \f$I = \tfrac{2}{5} m R^2\f$) in flight or on the table:
/// its velocity, its angular velocity (rad/s), its mass and its radius.
template <typename Scalar>
struct SpinningBall {
  Eigen::Matrix<Scalar, 3, 1> velocity;          ///< \f$v\f$
  Eigen::Matrix<Scalar, 3, 1> angular_velocity;  ///< \f$\omega\f$, rad/s
  Scalar mass;                                   ///< \f$m > 0\f$, finite
  Scalar radius;                                 ///< \f$R > 0\f$, finite
};

namespace detail {

template <typename Scalar>
using Vector3 = Eigen::Matrix<Scalar, 3, 1>;

/// The velocity of the point at `offset` from a ball's centre: \f$v + \omega \times r\f$.
template <typename Scalar>
[[nodiscard]] Vector3<Scalar> point_velocity(const Vector3<Scalar>& v, const Vector3<Scalar>& w,
                                             const Vector3<Scalar>& offset) noexcept {
  return v + w.cross(offset);
}

template <typename Scalar>
[[nodiscard]] bool is_finite_positive(Scalar x) noexcept {
  return x > 0 && std::isfinite(x);  // false for NaN
}

template <typename Scalar>
[[nodiscard]] bool is_friction(Scalar mu) noexcept {
  return mu >= 0 && std::isfinite(mu);  // false for NaN
}

}  // namespace detail

/// Two spinning balls colliding with Coulomb friction at the contact. `n` is the unit normal from
/// ball 1's centre to ball 2's. The balls approach iff \f$(v_2 - v_1) \cdot n < 0\f$; a pair that does
/// not approach is returned unchanged (bit for bit).
///
/// The normal impulse is restitution's, \f$J_n = (1 + e)\,\mu_\text{red}\,|(v_2 - v_1) \cdot n|\f$
/// (`friction.normal_impulse`), applied exactly as `collide(m1, v1, m2, v2, n, e)` applies it, so with
/// \f$\mu = 0\f$ the velocities are bit for bit those of that call and the spins are unchanged
/// (`throw.frictionless_is_restitution`). The tangential impulse acts against the tangential slip
/// \f$u_t\f$ of the contact points, \f$u = (v_2 + \omega_2 \times (-R_2 n)) - (v_1 + \omega_1 \times
/// (R_1 n))\f$, with magnitude \f$j = \min(\mu J_n, |u_t|/k)\f$, \f$k = \tfrac{7}{2}(1/m_1 + 1/m_2)\f$
/// (`kernel.friction_impulse`, `impulse.tangential_inverse_effective_mass_solid_spheres`): it stops the
/// slip (sticking) or acts at the Coulomb bound throughout (sliding). Then
/// \f$v_1' = v_1 - J/m_1\f$, \f$v_2' = v_2 + J/m_2\f$ and each spin turns by
/// \f$\tfrac{5 j}{2 m R} (n \times \hat u_t)\f$ (`kernel.spin_change_per_impulse`), with
/// \f$J = J_n n - j \hat u_t\f$ the impulse on ball 2. The tangential part is computed from the mass
/// ratio alone, \f$j/m_1 = \min(-(1 + e)\,\mu\,(v_2 - v_1) \cdot n,\ 2|u_t|/7)/(1 + m_1/m_2)\f$ and
/// the spin change \f$5 (j/m)/(2R)\f$ (`kernel.tangential_velocity_change`, `kernel.spin_change`), so
/// that masses anywhere in the type's range give the same result as masses near 1.
/// Momentum and each ball's angular momentum about
/// its contact point are conserved and no energy is created (`conservation.*`,
/// `friction.energy_nonincreasing_sticking`, `friction.energy_nonincreasing_sliding`).
///
/// Preconditions, asserted in debug builds: masses and radii positive and finite, `n` of unit length,
/// \f$0 \le e \le 1\f$, \f$\mu \ge 0\f$. billiards::checked::collide_with_friction validates them.
template <typename Scalar, typename DN>
[[nodiscard]] Collision<SpinningBall<Scalar>> collide_with_friction(const SpinningBall<Scalar>& ball1,
                                                                    const SpinningBall<Scalar>& ball2,
                                                                    const Eigen::MatrixBase<DN>& n,
                                                                    Scalar restitution,
                                                                    Scalar friction) noexcept {
  detail::require_vectors<DN, detail::Vector3<Scalar>>();
  assert(detail::is_finite_positive(ball1.mass) && detail::is_finite_positive(ball2.mass) &&
         "billiards: spinning balls need positive, finite masses");
  assert(detail::is_finite_positive(ball1.radius) && detail::is_finite_positive(ball2.radius) &&
         "billiards: spinning balls need positive, finite radii");
  assert(detail::is_friction(friction) && "billiards: the friction coefficient must be >= 0 and finite");
  detail::assert_unit(n);
  detail::assert_restitution(restitution);
  const detail::Vector3<Scalar> normal = n;
  const Scalar m1 = ball1.mass, m2 = ball2.mass;
  const Scalar relative_normal_speed = detail::difference_dot(ball1.velocity, ball2.velocity, normal);
  if (!(relative_normal_speed < 0)) return {ball1, ball2};  // separating, resting or NaN: unchanged
  Collision<SpinningBall<Scalar>> after{ball1, ball2};
  // The normal part: the restitution kernel, as collide(m1, v1, m2, v2, n, e).
  const auto change = kernels::normal_velocity_change(m1, m2, Scalar(0), relative_normal_speed, restitution);
  after.first.velocity = detail::plus_multiple(ball1.velocity, change.first, normal);
  after.second.velocity = detail::plus_multiple(ball2.velocity, change.second, normal);
  // The tangential part: Coulomb friction against the slip of the contact points.
  const detail::Vector3<Scalar> slip =
      detail::point_velocity<Scalar>(ball2.velocity, ball2.angular_velocity, -ball2.radius * normal) -
      detail::point_velocity<Scalar>(ball1.velocity, ball1.angular_velocity, ball1.radius * normal);
  const detail::Vector3<Scalar> tangential_slip = slip - detail::dot(slip, normal) * normal;
  const Scalar slip_speed = detail::scaled_norm(tangential_slip);
  if (!(friction > 0) || !(slip_speed > 0)) return after;  // no tangential impulse
  // j/m1 and j/m2 from the mass ratio alone (kernel.tangential_velocity_change): j itself is never
  // formed, so no mass's size can overflow or underflow the velocity and spin changes.
  const auto tangential = kernels::spin::tangential_velocity_change(m1, m2, restitution, friction,
                                                                    relative_normal_speed, slip_speed);
  const detail::Vector3<Scalar> slip_direction = tangential_slip / slip_speed;
  const detail::Vector3<Scalar> spin_axis = normal.cross(slip_direction);
  after.first.velocity = detail::plus_multiple(after.first.velocity, tangential.first, slip_direction);
  after.second.velocity = detail::plus_multiple(after.second.velocity, -tangential.second, slip_direction);
  after.first.angular_velocity = detail::plus_multiple(
      ball1.angular_velocity, kernels::spin::spin_change(tangential.first, ball1.radius), spin_axis);
  after.second.angular_velocity = detail::plus_multiple(
      ball2.angular_velocity, kernels::spin::spin_change(tangential.second, ball2.radius), spin_axis);
  return after;
}

namespace detail {

template <typename Scalar>
void check_positive_finite(const char* function, const std::string& name, Scalar x, const char* what) {
  if (!is_finite_positive(x) || !survives_flushing(x)) {
    throw invalid_argument(function, name, to_text(x), std::string("a positive, finite ") + what);
  }
}

template <typename Scalar>
void check_friction(const char* function, const std::string& name, Scalar mu) {
  if (!is_friction(mu))
    throw invalid_argument(function, name, to_text(mu), "a friction coefficient >= 0, finite");
}

/// A spinning ball's mass, radius, velocity and angular velocity (with R |ω| within the component limit,
/// so that the contact point's velocity is finite).
template <typename Scalar>
void check_spinning_ball(const char* function, const std::string& name, const SpinningBall<Scalar>& ball) {
  check_positive_finite(function, name + ".mass", ball.mass, "mass");
  check_positive_finite(function, name + ".radius", ball.radius, "radius");
  check_components(function, (name + ".velocity").c_str(), ball.velocity, "a velocity");
  check_components(function, (name + ".angular_velocity").c_str(), ball.angular_velocity,
                   "an angular velocity");
  const Scalar contact_speed = ball.radius * ball.angular_velocity.cwiseAbs().maxCoeff();
  if (!(contact_speed <= component_limit<Scalar>())) {
    throw invalid_argument(
        function, name + ".angular_velocity", to_text(ball.angular_velocity),
        "an angular velocity with radius × |ω| at most " + to_text(component_limit<Scalar>()));
  }
}

template <typename Scalar>
[[nodiscard]] bool is_finite(const SpinningBall<Scalar>& ball) noexcept {
  return ball.velocity.allFinite() && ball.angular_velocity.allFinite();
}

}  // namespace detail

namespace checked {

/// billiards::collide_with_friction with every argument validated first: masses and radii positive and
/// finite, velocities and angular velocities finite within component_limit() (and R |ω| too), `n` a unit
/// vector, restitution in [0, 1], friction ≥ 0 and finite. Throws billiards::invalid_argument naming the
/// argument (e.g. "ball1.mass"); also when the masses and radii are so far apart that the impulse or a
/// spin change would not be finite. Returns exactly what the unchecked call returns.
template <typename Scalar, typename DN>
[[nodiscard]] Collision<SpinningBall<Scalar>> collide_with_friction(const SpinningBall<Scalar>& ball1,
                                                                    const SpinningBall<Scalar>& ball2,
                                                                    const Eigen::MatrixBase<DN>& n,
                                                                    Scalar restitution, Scalar friction) {
  detail::require_vectors<DN, detail::Vector3<Scalar>>();
  constexpr const char* function = "billiards::checked::collide_with_friction";
  detail::check_spinning_ball(function, "ball1", ball1);
  detail::check_spinning_ball(function, "ball2", ball2);
  detail::check_unit_normal(function, "n", n);
  detail::check_restitution(function, restitution);
  detail::check_friction(function, "friction", friction);
  const Collision<SpinningBall<Scalar>> after =
      billiards::collide_with_friction(ball1, ball2, n, restitution, friction);
  if (!detail::is_finite(after.first) || !detail::is_finite(after.second)) {
    throw invalid_argument(function, "ball1, ball2",
                           "masses " + detail::to_text(ball1.mass) + ", " + detail::to_text(ball2.mass) +
                               " and radii " + detail::to_text(ball1.radius) + ", " +
                               detail::to_text(ball2.radius),
                           "balls whose masses and radii keep the impulse and the spin changes finite");
  }
  return after;
}

}  // namespace checked

}  // namespace billiards
