// A ball on the cloth: sliding, rolling and spinning (the spinning-ball model's audit, sections
// "Sliding on the cloth", "Rolling on the cloth" and "Spinning on the cloth"), on top of the generated
// kernels of billiards/spin_kernels.hpp. The table is the plane z = 0 with ẑ up; a ball's centre is at
// height R.
#pragma once

#include <billiards/spin.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace billiards {

/// The cloth's friction: sliding friction \f$\mu_s\f$, rolling resistance \f$\mu_r\f$, spinning friction
/// \f$\mu_{sp}\f$ (all \f$\ge 0\f$, dimensionless) and the gravitational acceleration \f$g\f$ (m/s²).
template <typename Scalar>
struct Cloth {
  Scalar sliding_friction;        ///< \f$\mu_s\f$: friction −μ_s m g û at the contact while it slips
  Scalar rolling_friction;        ///< \f$\mu_r\f$: a rolling ball slows at μ_r g
  Scalar spinning_friction;       ///< \f$\mu_{sp}\f$: the spin about ẑ decays at 5 μ_sp g/(2R)
  Scalar gravity = Scalar(9.81);  ///< \f$g > 0\f$
};

/// A ball on the table: its centre (at height `radius`), velocity (horizontal), angular velocity (rad/s)
/// and radius. The mass does not enter the motion on the cloth.
template <typename Scalar>
struct BallOnCloth {
  Eigen::Matrix<Scalar, 3, 1> position;          ///< the centre, at height \f$z = R\f$ on the table
  Eigen::Matrix<Scalar, 3, 1> velocity;          ///< \f$v\f$, horizontal (\f$v_z = 0\f$)
  Eigen::Matrix<Scalar, 3, 1> angular_velocity;  ///< \f$\omega\f$, rad/s
  Scalar radius;                                 ///< \f$R > 0\f$, finite
};

/// The phase of a ball's motion on the cloth.
enum class Motion {
  sliding,     ///< the contact point slips: u = v + ω × (−R ẑ) ≠ 0
  rolling,     ///< no slip, the ball moves
  spinning,    ///< at rest, spinning about ẑ
  stationary,  ///< at rest, no spin about ẑ
};

namespace detail {
/// √(x² + y²) without overflow or underflow of the squares and without a libm call (std::hypot is one,
/// and several times slower than the arithmetic it guards): the 2-vector's scaled_norm().
template <typename Scalar>
[[nodiscard]] Scalar horizontal_length(Scalar x, Scalar y) noexcept {
  return scaled_norm(Eigen::Matrix<Scalar, 2, 1>(x, y));
}
}  // namespace detail

/// The slip of the contact point with the cloth, \f$u = v + \omega \times (-R \hat z)\f$ (horizontal).
template <typename Scalar>
[[nodiscard]] Eigen::Matrix<Scalar, 3, 1> contact_slip(const BallOnCloth<Scalar>& ball) noexcept {
  const Eigen::Matrix<Scalar, 3, 1> contact(0, 0, -ball.radius);
  Eigen::Matrix<Scalar, 3, 1> slip = ball.velocity + ball.angular_velocity.cross(contact);
  slip.z() = 0;
  return slip;
}

/// The slip speed at or below which a ball counts as rolling: 16 ε (|v| + R |ω_h|) with v and ω_h the
/// horizontal velocity and spin. The slip v − R ω × ẑ is a difference of those two terms, so a ball
/// that rolls in exact arithmetic shows a slip of a few ε times their size after rounding (a velocity
/// computed in one step and a spin in another); a slip above 16 times that is real sliding, and the
/// slide that would remove it lasts 2|u|/(7 μ_s g), a time at rounding level of the motion's own.
template <typename Scalar>
[[nodiscard]] Scalar rolling_tolerance(const BallOnCloth<Scalar>& ball) noexcept {
  const Scalar speed = detail::horizontal_length(ball.velocity.x(), ball.velocity.y());
  const Scalar spin = detail::horizontal_length(ball.angular_velocity.x(), ball.angular_velocity.y());
  return Scalar(16) * std::numeric_limits<Scalar>::epsilon() * (speed + ball.radius * spin);
}

namespace detail {

/// The contact slip and its length, computed once for the phase, its duration and the step.
template <typename Scalar>
struct Slip {
  Eigen::Matrix<Scalar, 3, 1> vector;
  Scalar speed;
};
template <typename Scalar>
[[nodiscard]] Slip<Scalar> slip_of(const BallOnCloth<Scalar>& ball) noexcept {
  const Eigen::Matrix<Scalar, 3, 1> slip = contact_slip(ball);
  return {slip, horizontal_length(slip.x(), slip.y())};
}

/// Whether `slip_speed` exceeds rolling_tolerance(ball), decided without its two lengths where bounds
/// of them decide it: each length lies between its largest component's size and the sum of its
/// components' sizes, and the factors 17 and 15 (for 16) leave room for those bounds' rounding, where
/// the bounds are normal numbers far from overflow (elsewhere the lengths decide).
template <typename Scalar>
[[nodiscard]] bool slips(const BallOnCloth<Scalar>& ball, Scalar slip_speed) noexcept {
  using std::fabs;
  const Scalar vx = fabs(ball.velocity.x()), vy = fabs(ball.velocity.y());
  const Scalar wx = fabs(ball.angular_velocity.x()), wy = fabs(ball.angular_velocity.y());
  constexpr Scalar epsilon = std::numeric_limits<Scalar>::epsilon();
  const Scalar least = std::max(vx, vy) + ball.radius * std::max(wx, wy);
  const Scalar most = (vx + vy) + ball.radius * (wx + wy);
  if (least >= Scalar(64) * std::numeric_limits<Scalar>::min() / epsilon &&
      most <= std::numeric_limits<Scalar>::max() / Scalar(64)) {
    if (slip_speed > Scalar(17) * epsilon * most) return true;
    if (slip_speed <= Scalar(15) * epsilon * least) return false;
  }
  return slip_speed > rolling_tolerance(ball);
}

/// motion() given the ball's slip.
template <typename Scalar>
[[nodiscard]] Motion motion_with(const BallOnCloth<Scalar>& ball, const Slip<Scalar>& slip) noexcept {
  if (slips(ball, slip.speed)) return Motion::sliding;
  if (ball.velocity.x() != 0 || ball.velocity.y() != 0) return Motion::rolling;
  if (ball.angular_velocity.z() != 0) return Motion::spinning;
  return Motion::stationary;
}

}  // namespace detail

/// The ball's phase: sliding while its slip exceeds rolling_tolerance(), else rolling while it moves,
/// else spinning while ω_z ≠ 0, else stationary.
template <typename Scalar>
[[nodiscard]] Motion motion(const BallOnCloth<Scalar>& ball, const Cloth<Scalar>& cloth) noexcept {
  static_cast<void>(cloth);  // the phase depends on the ball alone; the cloth decides how long it lasts
  return detail::motion_with(ball, detail::slip_of(ball));
}

namespace detail {

/// How long the phase `phase` of `ball`, whose slip is `slip`, lasts (see transition_time); times
/// `scale` (a power of two, applied exactly to the speed each duration is proportional to), for
/// phase_ends_within.
template <typename Scalar>
[[nodiscard]] Scalar phase_duration(const BallOnCloth<Scalar>& ball, const Cloth<Scalar>& cloth, Motion phase,
                                    const Slip<Scalar>& slip, Scalar scale = 1) noexcept {
  switch (phase) {
    case Motion::sliding:
      return kernels::spin::slide_time(slip.speed * scale, cloth.sliding_friction, cloth.gravity);
    case Motion::rolling:
      return kernels::spin::roll_time(detail::horizontal_length(ball.velocity.x(), ball.velocity.y()) * scale,
                                      cloth.rolling_friction, cloth.gravity);
    case Motion::spinning:
      return kernels::spin::spin_time(std::fabs(ball.angular_velocity.z()) * scale, ball.radius,
                                      cloth.spinning_friction, cloth.gravity);
    case Motion::stationary: break;
  }
  return std::numeric_limits<Scalar>::infinity();
}

/// Whether a duration that rounded to exactly `remaining` ends within it. Where the duration is below
/// the smallest normal number it has lost digits (a slide of 1.4 × the smallest subnormal rounds to
/// 1 ×), so the tie is decided again with the duration computed 2^digits times larger — its speed
/// scaled exactly, the duration then a normal number — against remaining · 2^digits (exact). Found by
/// the fuzzer: a slide taken to its end, and on to rolling, at a time before the end.
template <typename Scalar, typename Duration>
[[nodiscard]] bool ends_within(Scalar duration, Scalar remaining, Duration scaled_duration) noexcept {
  if (duration != remaining) return duration < remaining;
  if (!(duration < std::numeric_limits<Scalar>::min())) return true;
  const Scalar scale = std::ldexp(Scalar(1), std::numeric_limits<Scalar>::digits);
  return scaled_duration(scale) <= remaining * scale;
}

}  // namespace detail

/// The time until the ball's phase changes: the slide time \f$2|u|/(7 \mu_s g)\f$ while sliding
/// (`sliding.slide_time`), the stop time \f$|v|/(\mu_r g)\f$ while rolling
/// (`rolling.stop_time`), the spin's stop time \f$2 R |\omega_z|/(5 \mu_{sp} g)\f$ while spinning
/// (`spinning.stop_time`); +∞ when stationary or when the phase's friction coefficient is 0.
/// The spin about ẑ may stop within a sliding or rolling phase without changing it.
template <typename Scalar>
[[nodiscard]] Scalar transition_time(const BallOnCloth<Scalar>& ball, const Cloth<Scalar>& cloth) noexcept {
  const detail::Slip<Scalar> slip = detail::slip_of(ball);
  return detail::phase_duration(ball, cloth, detail::motion_with(ball, slip), slip);
}

namespace detail {

/// The spin about ẑ after `t` (at most its stop time): |ω_z| decays at 5 μ_sp g/(2R)
/// (`spinning.angular_velocity`), to 0 at the stop time.
template <typename Scalar>
[[nodiscard]] Scalar spin_after(Scalar spin, Scalar radius, const Cloth<Scalar>& cloth, Scalar t,
                                bool stops) noexcept {
  if (stops || spin == 0) return Scalar(0);
  // μ_sp g t first: the angular deceleration's factor 5/(2R) last, so that a large g or a small R
  // cannot overflow a product the decay itself stays below (and t = 0 decays by exactly 0).
  const Scalar decay =
      t > 0 ? Scalar(5) * (cloth.spinning_friction * cloth.gravity * t) / (Scalar(2) * radius) : Scalar(0);
  const Scalar magnitude = std::max(std::fabs(spin) - decay, Scalar(0));
  return std::copysign(magnitude, spin);
}

/// The ball, whose slip is `slip`, after `t` within one phase; `ends` when t is the phase's end (the state
/// is then set to the next phase's exactly: rolling without slip, or at rest), `spin_stops` when the spin
/// about ẑ stops at t.
template <typename Scalar>
[[nodiscard]] BallOnCloth<Scalar> advance(const BallOnCloth<Scalar>& ball, const Cloth<Scalar>& cloth,
                                          Motion phase, const Slip<Scalar>& contact, Scalar t, bool ends,
                                          bool spin_stops) noexcept {
  using Vector = Eigen::Matrix<Scalar, 3, 1>;
  BallOnCloth<Scalar> later = ball;
  const Vector up(0, 0, 1);
  const Scalar g = cloth.gravity, radius = ball.radius;
  const Vector horizontal_velocity(ball.velocity.x(), ball.velocity.y(), 0);
  if (phase == Motion::sliding) {
    // sliding.velocity, .angular_velocity, .position: û constant (.slip_direction_constant).
    const Vector& slip = contact.vector;
    const Vector direction = slip / contact.speed;
    // |Δv| = μ_s g t, at most (2/7)|u0| within the phase: every term below is built from it, so none
    // overflows where the result does not (5 μ_s g alone may), and t = 0 changes nothing.
    const Scalar speed_change = t > 0 ? cloth.sliding_friction * g * t : Scalar(0);
    later.position = ball.position + horizontal_velocity * t - (speed_change * t / Scalar(2)) * direction;
    if (ends) {
      // sliding.rolling_velocity: v0 − (2/7) u0 (the 5/7 rule), from the slip itself rather than from
      // the slide time, which may round to 0 or lose digits where μ_s g is huge beside the slip.
      later.velocity = horizontal_velocity - (Scalar(2) / Scalar(7)) * slip;
      // sliding.rolls_at_slide_time: the rolling condition, exactly.
      const Vector rolling_spin = up.cross(later.velocity) / radius;
      later.angular_velocity.x() = rolling_spin.x();
      later.angular_velocity.y() = rolling_spin.y();
    } else {
      later.velocity = horizontal_velocity - speed_change * direction;
      const Vector turn = (Scalar(5) * speed_change / (Scalar(2) * radius)) * up.cross(direction);
      later.angular_velocity.x() += turn.x();
      later.angular_velocity.y() += turn.y();
    }
  } else if (phase == Motion::rolling) {
    // rolling.velocity, .position (assumption.rolling_resistance).
    const Vector direction =
        horizontal_velocity / detail::horizontal_length(ball.velocity.x(), ball.velocity.y());
    const Scalar speed_change = t > 0 ? cloth.rolling_friction * g * t : Scalar(0);  // at most |v0|
    later.velocity = ends ? Vector::Zero() : Vector(horizontal_velocity - speed_change * direction);
    later.position = ball.position + horizontal_velocity * t - (speed_change * t / Scalar(2)) * direction;
    const Vector rolling_spin = up.cross(later.velocity) / radius;
    later.angular_velocity.x() = rolling_spin.x();
    later.angular_velocity.y() = rolling_spin.y();
  }
  later.position.z() = ball.position.z();
  later.angular_velocity.z() = spin_after(ball.angular_velocity.z(), radius, cloth, t, spin_stops);
  return later;
}

}  // namespace detail

/// The ball after time `t` ≥ 0 on the cloth, across as many phases as `t` spans: sliding until the slip
/// vanishes, then rolling until it stops, then spinning until the spin about ẑ stops, the spin about ẑ
/// decaying in every phase. Each phase follows its derived closed form (position, velocity, angular
/// velocity as functions of time); at a phase's end the state is set to the next phase's exactly.
/// A zero friction coefficient keeps its phase forever (μ_r = 0: the ball rolls on at constant
/// velocity). Preconditions, asserted in debug builds: the ball on the table (velocity horizontal),
/// radius positive and finite, friction coefficients ≥ 0, gravity > 0, t ≥ 0.
template <typename Scalar>
[[nodiscard]] BallOnCloth<Scalar> evolve(const BallOnCloth<Scalar>& ball, const Cloth<Scalar>& cloth,
                                         Scalar t) noexcept {
  assert(detail::is_finite_positive(ball.radius) && "billiards: the radius must be positive and finite");
  assert(detail::is_friction(cloth.sliding_friction) && detail::is_friction(cloth.rolling_friction) &&
         detail::is_friction(cloth.spinning_friction) && "billiards: friction coefficients must be >= 0");
  assert(detail::is_finite_positive(cloth.gravity) && "billiards: gravity must be positive and finite");
  assert(t >= 0 && "billiards: the time must be >= 0");
  BallOnCloth<Scalar> current = ball;
  Scalar remaining = t;
  // At most four phase ends (sliding, rolling, the spin, and one to spare): every pass ends a phase
  // or uses up the time, so the loop ends.
  for (int pass = 0; pass < 5 && remaining > 0; ++pass) {
    const detail::Slip<Scalar> slip = detail::slip_of(current);
    const Motion phase = detail::motion_with(current, slip);
    if (phase == Motion::stationary) break;
    // Each duration times `scale` (1, or 2^digits for a tie below the smallest normal: ends_within).
    const auto phase_duration = [&](Scalar scale) {
      return detail::phase_duration(current, cloth, phase, slip, scale);
    };
    const Scalar spin = std::fabs(current.angular_velocity.z());
    const auto spin_duration = [&](Scalar scale) {
      return kernels::spin::spin_time(spin * scale, current.radius, cloth.spinning_friction, cloth.gravity);
    };
    const Scalar phase_end = phase_duration(1);
    const Scalar spin_end = spin > 0 ? spin_duration(1) : std::numeric_limits<Scalar>::infinity();
    const Scalar step = std::min({remaining, phase_end, spin_end});
    const bool phase_ends = step == phase_end && detail::ends_within(phase_end, remaining, phase_duration);
    const bool spin_ends = step == spin_end && detail::ends_within(spin_end, remaining, spin_duration);
    current = detail::advance(current, cloth, phase, slip, step, phase_ends, spin_ends);
    if (step == remaining) break;
    remaining -= step;
  }
  return current;
}

namespace detail {

template <typename Scalar>
void check_cloth(const char* function, const Cloth<Scalar>& cloth) {
  check_friction(function, "cloth.sliding_friction", cloth.sliding_friction);
  check_friction(function, "cloth.rolling_friction", cloth.rolling_friction);
  check_friction(function, "cloth.spinning_friction", cloth.spinning_friction);
  check_positive_finite(function, "cloth.gravity", cloth.gravity, "gravitational acceleration");
}

/// A ball on the table: radius positive and finite, components finite within component_limit(), the
/// centre at height R and the velocity horizontal (each to 64 ε of the ball's own scale).
template <typename Scalar>
void check_ball_on_cloth(const char* function, const BallOnCloth<Scalar>& ball) {
  check_positive_finite(function, "ball.radius", ball.radius, "radius");
  check_components(function, "ball.position", ball.position, "a position");
  check_components(function, "ball.velocity", ball.velocity, "a velocity");
  check_components(function, "ball.angular_velocity", ball.angular_velocity, "an angular velocity");
  const Scalar tolerance = Scalar(64) * std::numeric_limits<Scalar>::epsilon();
  const Scalar height_scale = std::max(ball.radius, ball.position.cwiseAbs().maxCoeff());
  if (!(std::fabs(ball.position.z() - ball.radius) <= tolerance * height_scale)) {
    throw invalid_argument(function, "ball.position", to_text(ball.position),
                           "a ball on the table: position.z equal to the radius " + to_text(ball.radius));
  }
  if (!(std::fabs(ball.velocity.z()) <= tolerance * ball.velocity.cwiseAbs().maxCoeff())) {
    throw invalid_argument(function, "ball.velocity", to_text(ball.velocity),
                           "a ball on the table: a horizontal velocity (velocity.z = 0)");
  }
  const Scalar contact_speed = ball.radius * ball.angular_velocity.cwiseAbs().maxCoeff();
  if (!(contact_speed <= component_limit<Scalar>())) {
    throw invalid_argument(
        function, "ball.angular_velocity", to_text(ball.angular_velocity),
        "an angular velocity with radius × |ω| at most " + to_text(component_limit<Scalar>()));
  }
}

}  // namespace detail

namespace checked {

/// billiards::motion with the ball and the cloth validated (see billiards::checked::evolve).
template <typename Scalar>
[[nodiscard]] Motion motion(const BallOnCloth<Scalar>& ball, const Cloth<Scalar>& cloth) {
  constexpr const char* function = "billiards::checked::motion";
  detail::check_ball_on_cloth(function, ball);
  detail::check_cloth(function, cloth);
  return billiards::motion(ball, cloth);
}

/// billiards::transition_time with the ball and the cloth validated (see billiards::checked::evolve).
template <typename Scalar>
[[nodiscard]] Scalar transition_time(const BallOnCloth<Scalar>& ball, const Cloth<Scalar>& cloth) {
  constexpr const char* function = "billiards::checked::transition_time";
  detail::check_ball_on_cloth(function, ball);
  detail::check_cloth(function, cloth);
  return billiards::transition_time(ball, cloth);
}

/// billiards::evolve with every argument validated first: the ball on the table (centre at height R,
/// velocity horizontal), radius positive and finite, components finite within component_limit(), friction
/// coefficients ≥ 0 and finite, gravity positive and finite, t ≥ 0 and finite. Throws
/// billiards::invalid_argument naming the argument (e.g. "cloth.gravity"), also when t is so long that the
/// position would not be finite. Returns exactly what the unchecked call returns.
template <typename Scalar>
[[nodiscard]] BallOnCloth<Scalar> evolve(const BallOnCloth<Scalar>& ball, const Cloth<Scalar>& cloth,
                                         Scalar t) {
  constexpr const char* function = "billiards::checked::evolve";
  detail::check_ball_on_cloth(function, ball);
  detail::check_cloth(function, cloth);
  if (!(t >= 0) || !std::isfinite(t))
    throw invalid_argument(function, "t", detail::to_text(t), "a time >= 0, finite");
  const BallOnCloth<Scalar> later = billiards::evolve(ball, cloth, t);
  if (!later.position.allFinite() || !later.velocity.allFinite() || !later.angular_velocity.allFinite()) {
    throw invalid_argument(function, "t", detail::to_text(t),
                           "a time short enough that the ball's state stays finite");
  }
  return later;
}

}  // namespace checked

}  // namespace billiards
