/// \file
/// Detection: when a moving ball next meets a ball, a straight cushion, a jaw or a pocket's capture
/// circle, each the earliest root of a derived event polynomial (billiards::contact_polynomial,
/// billiards::cushion_polynomial) found by billiards::earliest_contact; and the bounds that rule a pair
/// out without solving for it (the box a ball's centre keeps to over a horizon).
///
/// A path is a centre's motion from now within its phase: position r, velocity v and constant
/// acceleration a, all horizontal. Times are from now; `horizon` is the longest time looked at. A
/// contact's time is returned as a number, +∞ where there is none within the horizon (as
/// billiards::time_of_impact does): a number stays in a register in the prediction loop, where an
/// optional would be stored and reloaded through memory.
#pragma once

#include <billiards/simulation/core/invariants.hpp>
#include <billiards/simulation/shot/pool_table.hpp>

#include <billiards/events.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <span>
#include <utility>

namespace billiards::simulation::shot {

/// A centre's motion from now: r + v t + ½ a t².
struct Path {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();      ///< r (m)
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();      ///< v (m/s)
  Eigen::Vector2d acceleration = Eigen::Vector2d::Zero();  ///< a (m/s²)
  /// The centre at time t from now.
  [[nodiscard]] Eigen::Vector2d at(double t) const {
    return position + t * velocity + (0.5 * t * t) * acceleration;
  }
};

/// The x and y ranges a centre keeps to over a horizon.
struct Box {
  double x_low = 0;   ///< the least x (m)
  double x_high = 0;  ///< the greatest x (m)
  double y_low = 0;   ///< the least y (m)
  double y_high = 0;  ///< the greatest y (m)
  /// Whether `centre` lies within `reach` of the box (four comparisons without a branch between them).
  [[nodiscard]] bool near(const Eigen::Vector2d& centre, double reach) const {
    return near(centre.x(), centre.y(), reach);
  }
  /// near() for the centre (x, y).
  [[nodiscard]] bool near(double x, double y, double reach) const {
    return (x >= x_low - reach) & (x <= x_high + reach) & (y >= y_low - reach) & (y <= y_high + reach);
  }
  /// The box grown by `reach` on every side.
  [[nodiscard]] Box widened(double reach) const {
    return {x_low - reach, x_high + reach, y_low - reach, y_high + reach};
  }
  /// Whether this box and `other` share a point (for a box widened by a reach: whether a point of each
  /// may lie within the reach of each other), its four comparisons without a branch between them.
  [[nodiscard]] bool overlaps(const Box& other) const {
    return (other.x_low <= x_high) & (x_low <= other.x_high) & (other.y_low <= y_high) & (y_low <= other.y_high);
  }
};

/// The range of x + v t + ½ a t² over t in [0, horizon] (its extremes at the ends and at the vertex; a
/// point where the centre does not `move`), widened by rounding's share: a millionth of the range and
/// of `radius`.
[[nodiscard]] inline std::pair<double, double> coordinate_range(double x, double v, double a, double horizon,
                                                                bool moves, double radius) {
  double low = x, high = x;
  if (moves) {
    const double end = x + v * horizon + 0.5 * a * horizon * horizon;
    low = std::min(low, end);
    high = std::max(high, end);
    const double vertex = a != 0 ? -v / a : 0;
    if (vertex > 0 && vertex < horizon) {
      const double turn = x + v * vertex + 0.5 * a * vertex * vertex;
      low = std::min(low, turn);
      high = std::max(high, turn);
    }
  }
  const double slack = 1e-6 * (high - low + radius);
  return {low - slack, high + slack};
}

/// The box holding the centre of `path` over [0, horizon] (a point where it does not `move`).
[[nodiscard]] inline Box path_box(const Path& path, double horizon, bool moves, double radius) {
  const auto [x_low, x_high] =
      coordinate_range(path.position.x(), path.velocity.x(), path.acceleration.x(), horizon, moves, radius);
  const auto [y_low, y_high] =
      coordinate_range(path.position.y(), path.velocity.y(), path.acceleration.y(), horizon, moves, radius);
  return {x_low, x_high, y_low, y_high};
}

/// Bodies overlapping by at most overlap_tolerance of a radius (rounding, after a contact) count as
/// touching: the polynomial `p` starts at 0, so that bodies that separate and then approach again meet —
/// from a value just below 0 the polynomial might never reach 0 from above. `scale` is the polynomial's
/// derivative by the gap at contact (1 for a cushion's, 2D for a circle's of diameter D).
inline void touching(std::span<double> p, double scale, double radius) {
  if (p[0] < 0 && p[0] >= -scale * radius * overlap_tolerance) p[0] = 0;
}

/// Whether a cushion's polynomial `q`, apart now and not convex (c2 ≤ 0: a ball moving off the cushion
/// as the cloth slows it), stays above its rounding up to the horizon: its least value on [0, horizon]
/// is at an end. earliest_contact finds the same, after a search for the turning point.
[[nodiscard]] inline bool stays_apart(const std::array<double, 3>& q, double horizon) {
  if (!(q[0] > 0 && q[2] <= 0)) return false;
  const billiards::detail::EventPolynomial<double> p{{q[0], q[1], q[2], 0, 0}, 2};
  return billiards::detail::evaluate(p, horizon) > billiards::detail::evaluation_error(p, horizon);
}

/// Whether every point of `box` lies farther than R (and a billionth of it, for the rounding of the
/// distances) from a cushion's nose line on the table's side, the line given by a point (start_x,
/// start_y) and its unit normal into the table: a centre kept to the box never touches it. Without a
/// branch, so that many cushions run side by side.
[[nodiscard]] inline bool beyond_reach(const Box& box, double start_x, double start_y, double normal_x,
                                       double normal_y, double R) {
  const double x = normal_x >= 0 ? box.x_low : box.x_high;
  const double y = normal_y >= 0 ? box.y_low : box.y_high;
  const double nearest = (x - start_x) * normal_x + (y - start_y) * normal_y;
  return nearest > R * (1 + 1e-9);
}

/// The cushion polynomial of a ball of radius R on `path` and the nose line of `cushion` (its distance
/// from the line less R), a sliver of overlap counted as touching.
[[nodiscard]] inline std::array<double, 3> nose_line_polynomial(const Path& path,
                                                               const CushionSegment& cushion, double R) {
  std::array<double, 3> q =
      cushion_polynomial((path.position - cushion.start).dot(cushion.normal),
                         path.velocity.dot(cushion.normal), path.acceleration.dot(cushion.normal), R);
  touching(q, 1, R);
  return q;
}

/// The earliest root within `horizon` of a nose line's polynomial `q` (nose_line_polynomial); +∞ if none.
[[nodiscard]] inline double nose_line_root(const std::array<double, 3>& q, double horizon) {
  constexpr double none = std::numeric_limits<double>::infinity();
  if (stays_apart(q, horizon)) return none;
  return earliest_contact(q, horizon).value_or(none);
}

/// When a ball of radius R on `path` reaches the nose line of `cushion` within `horizon`: the earliest root
/// of its cushion polynomial; +∞ if none. Cushions on one line share it.
[[nodiscard]] inline double nose_line_contact(const Path& path, const CushionSegment& cushion, double R,
                                              double horizon) {
  return nose_line_root(nose_line_polynomial(path, cushion, R), horizon);
}

/// Times (low, high) between which nose_line_contact's root lies, shown without placing it: for a ball
/// apart from the line and approaching it (q0 > 0 > q1), the closed-form root less and more 2⁻³⁰ of
/// itself, where q as evaluated exceeds twice its rounding bound at `low` and lies below minus that at
/// `high`, and high < horizon. A quadratic falling at 0 is above 0 before its first root and below 0
/// between its roots, so that its first root lies in (low, high), and nose_line_contact, within 16 units
/// in the last place of it, returns a time in there too. {0, 0} where that is not shown (no root before
/// the horizon, one near it, a graze): then only solving tells.
[[nodiscard]] inline std::pair<double, double> nose_line_bracket(const std::array<double, 3>& q,
                                                                 double horizon) {
  if (!(q[0] > 0 && q[1] < 0)) return {0, 0};
  const double root = billiards::detail::falling_quadratic_root(q[0], q[1], q[2]);
  const double low = root * (1 - 0x1p-30), high = root * (1 + 0x1p-30);
  if (!(low > 0 && high < horizon)) return {0, 0};
  const billiards::detail::EventPolynomial<double> p{{q[0], q[1], q[2], 0, 0}, 2};
  using billiards::detail::evaluate, billiards::detail::evaluation_error;
  if (evaluate(p, low) > 2 * evaluation_error(p, low) && evaluate(p, high) < -2 * evaluation_error(p, high))
    return {low, high};
  return {0, 0};
}

/// nose_line_root, faster where nose_line_bracket brackets q's root: for a quadratic falling at 0 (q0 > 0
/// > q1, q2 ≠ 0), the closed form placed exactly (billiards::detail::placed_quadratic_root) at once, as
/// earliest_contact's first step does — the tests of no contact before it (stays_apart's and
/// earliest_contact's own) are sound, and a placed root shows q below 0 within the horizon, so that they
/// would not have ended the search — and elsewhere, or where that placement is not shown, nose_line_root.
[[nodiscard]] inline double bracketed_nose_line_root(const std::array<double, 3>& q, double horizon) {
  if (q[0] > 0 && q[1] < 0 && q[2] != 0) {
    const billiards::detail::EventPolynomial<double> p{{q[0], q[1], q[2], 0, 0}, 2};
    if (const double t = billiards::detail::placed_quadratic_root(p, horizon); !std::isnan(t)) return t;
  }
  return nose_line_root(q, horizon);
}

/// Whether the centre on `path` lies between the ends of `cushion`'s nose at time t (beyond them the
/// jaws take the ball).
[[nodiscard]] inline bool within_nose(const Path& path, const CushionSegment& cushion, double t) {
  const Eigen::Vector2d along = cushion.end - cushion.start;
  const double f = (path.at(t) - cushion.start).dot(along);
  return f >= 0 && f <= along.squaredNorm();
}

/// Where the centre on `path` lies along `cushion`'s nose at time t, with a margin of a billionth of the
/// nose's length squared on the projection (far above its rounding): 1 between the ends, 2 before the
/// start, 3 past the end, 0 within the margin of an end. Where the two ends of a nose_line_bracket give
/// the same side, within_nose gives the same at every time between: the projection, a quadratic in t,
/// lies between its values at the ends, but for its curvature over so short a time, far below the margin.
[[nodiscard]] inline int nose_side(const Path& path, const CushionSegment& cushion, double t) {
  const Eigen::Vector2d along = cushion.end - cushion.start;
  const double f = (path.at(t) - cushion.start).dot(along), length = along.squaredNorm();
  const double margin = 1e-9 * length;
  if (f > margin && f < length - margin) return 1;
  if (f < -margin) return 2;
  if (f > length + margin) return 3;
  return 0;
}

/// Whether cushions a and b lie on one nose line along an axis (a rail's two cushions beside a side
/// pocket), so that nose_line_contact gives the same for both on every path, bit for bit.
[[nodiscard]] inline bool same_nose_line(const CushionSegment& a, const CushionSegment& b) {
  if (a.normal != b.normal) return false;
  if (a.normal.x() == 0) return a.start.y() == b.start.y();
  return a.normal.y() == 0 && a.start.x() == b.start.x();
}

/// When a ball of radius R on `path` meets the straight part of `cushion` within `horizon`: the earliest
/// root of its cushion polynomial where the centre then lies between the nose's ends (beyond them the
/// jaws take the ball); +∞ if none.
[[nodiscard]] inline double cushion_contact(const Path& path, const CushionSegment& cushion, double R,
                                            double horizon) {
  const double t = nose_line_contact(path, cushion, R, horizon);
  return t != std::numeric_limits<double>::infinity() && within_nose(path, cushion, t)
             ? t
             : std::numeric_limits<double>::infinity();
}

/// Whether a centre on `path` (relative to a point) stays farther than `distance` from it over [0,
/// horizon] by a margin no rounding of its contact polynomial reaches: the straight path r + v t comes no
/// nearer than its closest approach on the interval, and the acceleration moves the centre by at most
/// ½ |a| horizon² from it (|a| bounded by |a_x| + |a_y|). The margin, 10⁻⁹ S + 10⁻¹⁴ S²/distance with S
/// = |r| + |v| horizon + ½ |a| horizon² (each length bounded by the sum of its components' sizes), lies
/// far above the polynomial's rounding (a few ε S² against the 2 distance · margin its value keeps above
/// 0). A certificate of no contact that costs a few products, compared squared and without a division:
/// the closest approach at 0 (r·v ≥ 0), at the horizon (−r·v ≥ |v|² horizon), or between, where its
/// square is (r × v)²/|v|² (the cross product's rounding, ε |r| |v|, far below the margin's |v| 10⁻⁹ S).
///
/// Where that fails, the acceleration's part along the velocity is taken into the line: with α = a·v/|v|²
/// (as rounded: any α will do) and a⊥ = a − α v, r + v t + ½ a t² = r + v s(t) + ½ a⊥ t², s(t) = t +
/// ½ α t², so that the centre lies within ½ |a⊥| horizon² (a⊥ bounded with its rounding) of the segment
/// r + v s for s between s's least and greatest values on [0, horizon] (at the ends and at the vertex
/// t = −1/α, widened by their rounding), and the segment's closest approach, found as above, less that
/// drift must clear the same margin. For a rolling ball, a ball sliding without spin, and their paths
/// relative to a ball at rest, a jaw or a pocket, the acceleration lies along the velocity: over a
/// rolling ball's long horizon the first test's drift, ½ |a| horizon², spans much of the table, this
/// one's is at rounding level. Where neither holds, the polynomial decides.
[[nodiscard]] inline bool certainly_apart(const Path& path, double distance, double horizon) {
  if (!(horizon < std::numeric_limits<double>::max())) return false;
  const Eigen::Vector2d &r = path.position, &v = path.velocity, &a = path.acceleration;
  const double drift = 0.5 * (std::fabs(a.x()) + std::fabs(a.y())) * horizon * horizon;
  const double size = std::fabs(r.x()) + std::fabs(r.y()) + (std::fabs(v.x()) + std::fabs(v.y())) * horizon + drift;
  const double needed = distance + drift + 1e-9 * size + 1e-14 * size * (size / distance);
  const double vv = v.squaredNorm(), along = -r.dot(v), cross = r.x() * v.y() - r.y() * v.x();
  // Whether r + v s, s in [from, to], stays farther than `beyond` from the point.
  const auto segment_clears = [&](double from, double to, double beyond) {
    if (!(along > from * vv)) return (r + from * v).squaredNorm() > beyond * beyond;
    if (!(along < to * vv)) return (r + to * v).squaredNorm() > beyond * beyond;
    return cross * cross > beyond * beyond * vv;
  };
  if (segment_clears(0, horizon, needed)) return true;
  if (!(vv > 0 && drift > 0)) return false;  // no α without a velocity; no drift: the same test
  constexpr double epsilon = std::numeric_limits<double>::epsilon();
  const double alpha = a.dot(v) / vv;
  const double off_x = a.x() - alpha * v.x(), off_y = a.y() - alpha * v.y();
  const double rounding =
      4 * epsilon * (std::fabs(a.x()) + std::fabs(a.y()) + std::fabs(alpha) * (std::fabs(v.x()) + std::fabs(v.y())));
  const double side = 0.5 * horizon * horizon * (std::fabs(off_x) + std::fabs(off_y) + rounding);
  const double end = horizon + 0.5 * alpha * horizon * horizon;
  const double widening = 4 * epsilon * (horizon + std::fabs(end));
  double low = std::min(0.0, end), high = std::max(0.0, end);
  if (alpha < 0 && -1 / alpha < horizon) high = std::max(high, -0.5 / alpha);
  return segment_clears(low - widening, high + widening, needed - drift + side);
}

/// A time after 0 before which a contact polynomial p = c0 + c1 t + … + c4 t⁴ (its coefficients as given,
/// c0 > 0 and c4 ≥ 0) stays above 0, so that its first root comes no earlier; +∞ where p stays above 0 up
/// to `horizon`; 0 where no such time is shown (c0 ≤ 0, an unbounded horizon). On [0, T] the cubic term
/// c3 t³ is at least min(c3, 0) T t² and the quartic one at least 0, so that p ≥ q = c0 + c1 t + k t² with
/// k = c2 + min(c3, 0) T there; q, positive at 0, stays so until its least positive root. T is the
/// horizon where c3 ≥ 0 (any T then), else twice the least positive root of the Taylor quadratic (c0, c1,
/// c2) and at most the horizon. Each rounding moves the bound down: k lowered by a bound on its rounding,
/// q's discriminant raised by one on its own (a larger one gives a smaller root) and the root lowered by
/// 2^−40 of itself, far more than the roundings of its square root and quotient and than the 16 units in
/// the last place by which earliest_contact may place the root before its exact value.
[[nodiscard]] inline double contact_lower_bound(const std::array<double, 5>& c, double horizon) {
  constexpr double never = std::numeric_limits<double>::infinity();
  constexpr double epsilon = std::numeric_limits<double>::epsilon();
  if (!(c[0] > 0 && c[4] >= 0 && horizon > 0)) return 0;
  // q's least positive root, from below; +∞ where q has none (where it stays above 0 for t ≥ 0).
  const auto least_root = [&](double k) {
    const double square = c[1] * c[1], product = 4 * c[0] * k;
    const double discriminant = (square - product) + 4 * epsilon * (square + std::fabs(product));
    if (!(discriminant >= 0)) return never;
    const double denominator = std::sqrt(discriminant) - c[1];
    return denominator > 0 ? 2 * c[0] / denominator * (1 - 0x1p-40) : never;
  };
  double T = horizon;
  double k = c[2];
  if (c[3] < 0) {
    const double estimate = least_root(c[2]);
    if (2 * estimate < T) T = 2 * estimate;
    const double cubic = c[3] * T;
    k = (c[2] + cubic) - 4 * epsilon * (std::fabs(c[2]) + std::fabs(cubic));
  }
  const double root = least_root(k);
  if (!(root > 0)) return 0;  // NaN from an infinite T, or a root lost below the least double
  // Past T only where T is the horizon: below it, T is twice the root of a quadratic at or above q (each
  // rounding of least_root is monotone in k), so that q's root comes first.
  return root <= T ? root : never;
}

/// When a ball of radius R on `path` meets `jaw` within `horizon` (its centre R + the jaw's radius from
/// the jaw's axis); +∞ if never.
[[nodiscard]] inline double jaw_contact(const Path& path, const Jaw& jaw, double R, double horizon) {
  const double reach = R + jaw.radius;
  if (certainly_apart({path.position - jaw.centre, path.velocity, path.acceleration}, reach, horizon))
    return std::numeric_limits<double>::infinity();
  std::array<double, 5> p =
      contact_polynomial<double>(path.position - jaw.centre, path.velocity, path.acceleration, reach);
  touching(p, 2 * reach, R);
  return earliest_contact(p, horizon).value_or(std::numeric_limits<double>::infinity());
}

/// When the centre of a ball on `path` enters `pocket`'s capture circle within `horizon`; +∞ if never.
[[nodiscard]] inline double pocket_entry(const Path& path, const Pocket& pocket, double horizon) {
  if (certainly_apart({path.position - pocket.centre, path.velocity, path.acceleration}, pocket.radius, horizon))
    return std::numeric_limits<double>::infinity();
  const std::array<double, 5> p = contact_polynomial<double>(path.position - pocket.centre, path.velocity,
                                                             path.acceleration, pocket.radius);
  return earliest_contact(p, horizon).value_or(std::numeric_limits<double>::infinity());
}

/// The contact polynomial of two balls of radius R, `relative` the second's path less the first's (their
/// centres two radii apart), a sliver of overlap counted as touching.
[[nodiscard]] inline std::array<double, 5> ball_contact_polynomial(const Path& relative, double R) {
  std::array<double, 5> p =
      contact_polynomial<double>(relative.position, relative.velocity, relative.acceleration, 2 * R);
  touching(p, 4 * R, R);
  return p;
}

/// When two balls of radius R meet within `horizon`, `relative` the second's path less the first's
/// (their centres two radii apart); +∞ if never.
[[nodiscard]] inline double ball_contact(const Path& relative, double R, double horizon) {
  if (certainly_apart(relative, 2 * R, horizon)) return std::numeric_limits<double>::infinity();
  return earliest_contact(ball_contact_polynomial(relative, R), horizon)
      .value_or(std::numeric_limits<double>::infinity());
}

}  // namespace billiards::simulation::shot
