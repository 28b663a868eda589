// The cue strike (the shot model's audit, section "The cue strike"), on top of the generated kernels of
// billiards/shot_kernels.hpp: the instantaneous point model of Alciatore's TP A-30 with the tip's
// restitution, for a ball in any state.
#pragma once

#include <billiards/checked.hpp>
#include <billiards/shot_kernels.hpp>
#include <billiards/spin.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

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

}  // namespace checked

}  // namespace billiards
