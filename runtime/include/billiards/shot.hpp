// The cue strike and the cushion with spin (the shot model's audit, sections "The cue strike" and "The
// cushion with spin"), on top of the generated kernels of billiards/shot_kernels.hpp: the instantaneous
// point model of Alciatore's TP A-30 with the tip's restitution, for a ball in any state, and the
// cushion as the immovable limit of the frictional contact, at its nose (Han 2005 with μ in the
// stick/slip test).
#pragma once

#include <billiards/checked.hpp>
#include <billiards/shot_kernels.hpp>
#include <billiards/spin.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace billiards {

/// A cue at the moment it strikes: mass M, speed V along its axis, aimed at azimuth φ (from x̂ towards ŷ
/// in the table's plane), elevated by θ above the table, meeting the ball a to the right of its centre and
/// b up from it, measured in the plane perpendicular to the cue in units of the ball's radius.
template <typename Scalar>
struct Cue {
  Scalar mass;                 ///< \f$M > 0\f$
  Scalar speed;                ///< \f$V \ge 0\f$, along the cue's axis
  Scalar azimuth = 0;          ///< \f$\varphi\f$ (radians)
  Scalar elevation = 0;        ///< \f$\theta\f$ (radians), \f$0 \le \theta < \pi/2\f$
  Scalar side_offset = 0;      ///< \f$a\f$, right positive, in units of R
  Scalar up_offset = 0;        ///< \f$b\f$, up positive, in units of R; \f$a^2 + b^2 < 1\f$
  Scalar tip_restitution = 1;  ///< \f$e_{tip} \in [0, 1]\f$; TP A-30 is 1
};

/// The cue's frame: d along its axis into the ball, s to its right (horizontal), u = s × d up.
template <typename Scalar>
struct CueFrame {
  Eigen::Matrix<Scalar, 3, 1> along;  ///< d, from the tip into the ball
  Eigen::Matrix<Scalar, 3, 1> side;   ///< s, to the cue's right, horizontal
  Eigen::Matrix<Scalar, 3, 1> up;     ///< u = s × d, up, perpendicular to the cue
};

/// d = (cos θ cos φ, cos θ sin φ, −sin θ), s = (sin φ, −cos φ, 0), u = s × d (`definition.cue`).
template <typename Scalar>
[[nodiscard]] CueFrame<Scalar> cue_frame(const Cue<Scalar>& cue) noexcept {
  const Scalar cp = std::cos(cue.azimuth), sp = std::sin(cue.azimuth);
  const Scalar ct = std::cos(cue.elevation), st = std::sin(cue.elevation);
  return {{ct * cp, ct * sp, -st}, {sp, -cp, 0}, {st * cp, st * sp, ct}};
}

/// The ball after the cue strikes it (`strike.velocity_change`, `strike.spin_in_cue_frame`): the tip meets
/// it at r = R (a s + b u − c d), c = √(1 − a² − b²), with approach speed w = V − (v + ω × r)·d; the
/// ball's velocity changes by (J/m) d and its spin by (5/(2R)) (J/m) (a u − b s), J/m = (1 + e_tip) w/(1 +
/// m/M + (5/2)(a² + b²)). A tip that does not catch the ball (w ≤ 0) leaves it unchanged. The velocity is
/// as derived, with its vertical part for an elevated cue (the table's reaction is not in the model; a
/// ball on the cloth keeps the horizontal part). Mass and radius are the ball's.
template <typename Scalar>
[[nodiscard]] SpinningBall<Scalar> strike(const SpinningBall<Scalar>& ball, const Cue<Scalar>& cue) noexcept {
  using Vector = Eigen::Matrix<Scalar, 3, 1>;
  const CueFrame<Scalar> frame = cue_frame(cue);
  const Scalar a = cue.side_offset, b = cue.up_offset;
  const Scalar depth = std::sqrt(std::max(Scalar(0), Scalar(1) - a * a - b * b));
  const Vector contact = ball.radius * (a * frame.side + b * frame.up - depth * frame.along);
  const Scalar approach = cue.speed - (ball.velocity + ball.angular_velocity.cross(contact)).dot(frame.along);
  if (!(approach > 0)) return ball;
  const Scalar change = kernels::shot::strike_velocity_change(ball.mass, cue.mass, approach, a, b, cue.tip_restitution);
  const kernels::shot::StrikeSpin<Scalar> spin = kernels::shot::strike_spin(change, ball.radius, a, b);
  SpinningBall<Scalar> struck = ball;
  struck.velocity = ball.velocity + change * frame.along;
  struck.angular_velocity = ball.angular_velocity + spin.first * frame.up + spin.second * frame.side;
  return struck;
}

/// A straight cushion as the ball meets it: its unit normal n in the table's plane, pointing from the ball
/// into the cushion; the height h of its nose above the cloth, where it touches the ball (θ_a = asin(h/R −
/// 1) above the ball's equator); restitution e_c and Coulomb friction μ_c at the nose.
template <typename Scalar>
struct Cushion {
  Eigen::Matrix<Scalar, 3, 1> normal;  ///< n, horizontal (n_z = 0), from the ball into the cushion
  Scalar height;                       ///< h, the nose's height above the cloth: R ≤ h < 2R
  Scalar restitution = Scalar(0.85);   ///< \f$e_c \in [0, 1]\f$, along the nose's normal
  Scalar friction = Scalar(0.2);       ///< \f$\mu_c \ge 0\f$, across it
};

namespace detail {
/// sin θ_a and cos θ_a of the angle above a ball's equator (radius `radius`) at which a cushion's nose at
/// height `height` touches it: sin θ_a = h/R − 1.
template <typename Scalar>
[[nodiscard]] std::pair<Scalar, Scalar> nose_angle(Scalar height, Scalar radius) noexcept {
  const Scalar sine = height / radius - 1;
  return {sine, std::sqrt(std::max(Scalar(0), (1 - sine) * (1 + sine)))};
}
}  // namespace detail

/// The ball after it meets the cushion (`cushion.slip_in_cushion_frame`, `cushion.normal_impulse_per_unit_mass`,
/// `cushion.regime`, `cushion.velocity_change`, `cushion.spin_change`). In the cushion's frame (x̂ = n, ŷ =
/// ẑ × n along it, ẑ up) the contact point slips by s_t = v_x sin θ_a + R ω_y down the nose and s_y = v_y +
/// R ω_z cos θ_a − R ω_x sin θ_a along the cushion, σ = |(s_t, s_y)|; the normal impulse per unit mass is
/// p = (1 + e_c) v_x cos θ_a. The impact sticks iff 2σ/7 ≤ μ_c p (friction k = j/(m σ) = 2/7 stops the
/// slip) and slides with k = μ_c p/σ otherwise; then Δv_x = −p cos θ_a − k s_t sin θ_a, Δv_y = −k s_y,
/// and the spin changes by (5k/(2R)) (s_y t − s_t ŷ), t = (sin θ_a, 0, −cos θ_a). The ball's vertical
/// velocity and its position are not changed (the table holds it on the cloth: the model is for v_z = 0);
/// mass drops out. A ball that does not move into the cushion (v·n ≤ 0) is returned unchanged.
template <typename Scalar>
[[nodiscard]] SpinningBall<Scalar> collide_with_cushion(const SpinningBall<Scalar>& ball,
                                                        const Cushion<Scalar>& cushion) noexcept {
  using Vector = Eigen::Matrix<Scalar, 3, 1>;
  const Vector& n = cushion.normal;
  const Vector rail{-n.y(), n.x(), 0};
  const Scalar approach = ball.velocity.x() * n.x() + ball.velocity.y() * n.y();
  if (!(approach > 0)) return ball;
  const auto [sin_nose, cos_nose] = detail::nose_angle(cushion.height, ball.radius);
  const Vector& w = ball.angular_velocity;
  const Scalar along = ball.velocity.dot(rail);
  const kernels::shot::CushionSlip<Scalar> slip = kernels::shot::cushion_slip(
      approach, along, w.dot(n), w.dot(rail), w.z(), ball.radius, cos_nose, sin_nose);
  const Scalar normal_impulse = kernels::shot::cushion_normal_impulse(approach, cos_nose, cushion.restitution);
  const Scalar slip_size = detail::scaled_norm(Eigen::Matrix<Scalar, 2, 1>(slip.first, slip.second));
  const Scalar friction_impulse = cushion.friction * normal_impulse;
  const Scalar ratio = 2 * slip_size <= 7 * friction_impulse ? Scalar(2) / Scalar(7) : friction_impulse / slip_size;
  const kernels::shot::CushionVelocityChange<Scalar> dv =
      kernels::shot::cushion_velocity_change(normal_impulse, ratio, slip.first, slip.second, cos_nose, sin_nose);
  const kernels::shot::CushionSpinChange<Scalar> dw =
      kernels::shot::cushion_spin_change(ratio, slip.first, slip.second, ball.radius);
  const Vector tangent{sin_nose * n.x(), sin_nose * n.y(), -cos_nose};
  SpinningBall<Scalar> after = ball;
  after.velocity += dv.first * n + dv.second * rail;
  after.velocity.z() = ball.velocity.z();
  after.angular_velocity += dw.first * tangent + dw.second * rail;
  return after;
}

namespace checked {

/// billiards::strike with every argument validated: the ball's mass and radius positive and finite, its
/// velocity and spin finite within component_limit(); the cue's mass positive and finite, its speed ≥ 0
/// and finite, its azimuth finite, its elevation in [0, π/2), its offsets with a² + b² < 1, its tip
/// restitution in [0, 1]. Throws billiards::invalid_argument naming the argument ("cue.up_offset", …).
template <typename Scalar>
[[nodiscard]] SpinningBall<Scalar> strike(const SpinningBall<Scalar>& ball, const Cue<Scalar>& cue) {
  constexpr const char* function = "billiards::checked::strike";
  using detail::to_text;
  const auto positive = [&](const char* name, Scalar x) {
    if (!(x > 0) || !std::isfinite(x)) throw invalid_argument(function, name, to_text(x), "a positive finite number");
  };
  positive("ball.mass", ball.mass);
  positive("ball.radius", ball.radius);
  detail::check_components(function, "ball.velocity", ball.velocity, "a velocity");
  detail::check_components(function, "ball.angular_velocity", ball.angular_velocity, "an angular velocity");
  positive("cue.mass", cue.mass);
  if (!(cue.speed >= 0) || !std::isfinite(cue.speed))
    throw invalid_argument(function, "cue.speed", to_text(cue.speed), "a speed >= 0, finite");
  if (!(std::fabs(cue.speed) <= component_limit<Scalar>()))
    throw invalid_argument(function, "cue.speed", to_text(cue.speed),
                           "a speed of at most " + to_text(component_limit<Scalar>()));
  if (!std::isfinite(cue.azimuth))
    throw invalid_argument(function, "cue.azimuth", to_text(cue.azimuth), "a finite angle in radians");
  if (!(cue.elevation >= 0 && cue.elevation < Scalar(1.5707963267948966)))
    throw invalid_argument(function, "cue.elevation", to_text(cue.elevation), "an angle in [0, pi/2) radians");
  if (!std::isfinite(cue.side_offset))
    throw invalid_argument(function, "cue.side_offset", to_text(cue.side_offset), "a finite offset");
  if (!std::isfinite(cue.up_offset) || !(cue.side_offset * cue.side_offset + cue.up_offset * cue.up_offset < 1))
    throw invalid_argument(function, "cue.up_offset", to_text(cue.up_offset),
                           "an offset with side_offset² + up_offset² < 1 (the tip on the ball)");
  if (!(cue.tip_restitution >= 0 && cue.tip_restitution <= 1))
    throw invalid_argument(function, "cue.tip_restitution", to_text(cue.tip_restitution),
                           "a coefficient of restitution in [0, 1]");
  return billiards::strike(ball, cue);
}

/// billiards::collide_with_cushion with every argument validated: the ball's mass and radius positive and
/// finite, its velocity and spin finite within component_limit() (R |ω| too), its velocity on the cloth
/// (v_z = 0); the cushion's normal a unit vector in the table's plane (n_z = 0), its nose's height in [R,
/// 2R) of the ball's radius, its restitution in [0, 1] and its friction ≥ 0 and finite. Throws
/// billiards::invalid_argument naming the argument ("cushion.height", …), also when the ball's radius is so
/// small against its speed that the spin change would not be finite. Returns exactly what the unchecked
/// call returns.
template <typename Scalar>
[[nodiscard]] SpinningBall<Scalar> collide_with_cushion(const SpinningBall<Scalar>& ball, const Cushion<Scalar>& cushion) {
  constexpr const char* function = "billiards::checked::collide_with_cushion";
  using detail::to_text;
  detail::check_spinning_ball(function, "ball", ball);
  if (ball.velocity.z() != 0)
    throw invalid_argument(function, "ball.velocity", to_text(ball.velocity),
                           "a velocity on the cloth (its z component 0)");
  detail::check_unit_normal(function, "cushion.normal", cushion.normal);
  if (cushion.normal.z() != 0)
    throw invalid_argument(function, "cushion.normal", to_text(cushion.normal),
                           "a normal in the table's plane (its z component 0)");
  if (!(cushion.height >= ball.radius && cushion.height < 2 * ball.radius))
    throw invalid_argument(function, "cushion.height", to_text(cushion.height),
                           "a nose height in [R, 2R) for the ball's radius R = " + to_text(ball.radius));
  if (!detail::is_restitution(cushion.restitution))
    throw invalid_argument(function, "cushion.restitution", to_text(cushion.restitution),
                           "a coefficient of restitution in [0, 1]");
  detail::check_friction(function, "cushion.friction", cushion.friction);
  const SpinningBall<Scalar> after = billiards::collide_with_cushion(ball, cushion);
  if (!detail::is_finite(after))
    throw invalid_argument(function, "ball.radius", to_text(ball.radius),
                           "a radius that keeps the spin change finite for the ball's velocity");
  return after;
}


}  // namespace checked

}  // namespace billiards
