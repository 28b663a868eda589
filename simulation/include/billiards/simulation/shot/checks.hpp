/// \file
/// What a shot checks: its physics and balls before it starts (bad input: std::invalid_argument naming
/// the field or the ball), the pockets' capture circles it plays with, and the positions' invariants
/// after an event (no overlap with a ball, a cushion or a jaw beyond overlap_tolerance of a radius, no
/// ball off the table).
#pragma once

#include <billiards/simulation/core/errors.hpp>
#include <billiards/simulation/core/invariants.hpp>
#include <billiards/simulation/shot/event.hpp>
#include <billiards/simulation/shot/pool_table.hpp>

#include <billiards/checked.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace billiards::simulation::shot {

/// Throws billiards::invalid_argument naming the field where `physics` or the table's nose height is not
/// one a shot can play: radius and mass positive and finite, friction coefficients finite and ≥ 0,
/// gravity positive, restitutions in [0, 1], the nose height in [R, 2R).
inline void validate(const PoolTable& table, const PoolPhysics& p) {
  using detail::shortest;
  const auto require = [](bool ok, const char* name, double value, const char* expected) {
    if (!ok)
      throw billiards::invalid_argument("Shot", std::string("physics.") + name, shortest(value), expected);
  };
  const auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  const auto friction = [](double x) { return std::isfinite(x) && x >= 0; };
  const auto restitution = [](double x) { return x >= 0 && x <= 1; };
  require(positive(p.radius), "radius", p.radius, "a positive, finite length (m)");
  require(positive(p.mass), "mass", p.mass, "a positive, finite mass (kg)");
  require(friction(p.cloth.sliding_friction), "cloth.sliding_friction", p.cloth.sliding_friction,
          "finite and >= 0");
  require(friction(p.cloth.rolling_friction), "cloth.rolling_friction", p.cloth.rolling_friction,
          "finite and >= 0");
  require(friction(p.cloth.spinning_friction), "cloth.spinning_friction", p.cloth.spinning_friction,
          "finite and >= 0");
  require(positive(p.cloth.gravity), "cloth.gravity", p.cloth.gravity, "positive and finite (m/s^2)");
  require(restitution(p.ball_restitution), "ball_restitution", p.ball_restitution, "in [0, 1]");
  require(friction(p.ball_friction), "ball_friction", p.ball_friction, "finite and >= 0");
  require(restitution(p.cushion_restitution), "cushion_restitution", p.cushion_restitution, "in [0, 1]");
  require(friction(p.cushion_friction), "cushion_friction", p.cushion_friction, "finite and >= 0");
  if (!(table.nose_height >= p.radius && table.nose_height < 2 * p.radius))
    throw billiards::invalid_argument(
        "Shot", "table.nose_height", shortest(table.nose_height),
        "a height in [R, 2R) = [" + shortest(p.radius) + ", " + shortest(2 * p.radius) + ")");
}

/// Throws billiards::invalid_argument naming the option where `options` cannot run a shot: a pressing
/// speed that is not positive and finite.
inline void validate(const ShotOptions& options) {
  if (!(std::isfinite(options.pressing_speed) && options.pressing_speed > 0))
    throw billiards::invalid_argument("Shot", "options.pressing_speed",
                                      detail::shortest(options.pressing_speed),
                                      "a positive, finite speed (m/s)");
}

/// The pockets' capture circles a shot plays with: the table's, each widened where needed to reach into
/// both its jaws' reach (a centre comes no nearer a jaw's axis than R + ρ_jaw), so that no ball can pass
/// between a jaw and the pocket (pooltool's geometry leaves a gap of 0.2 mm there at the corners, which
/// its pockets' straight walls behind the jaws close).
[[nodiscard]] inline std::vector<Pocket> capture_circles(const PoolTable& table, const std::vector<Jaw>& jaws,
                                                         double R) {
  std::vector<Pocket> pockets = table.pockets();
  for (Pocket& pocket : pockets) {
    // The two nearest jaws are the pocket's own; 1 µm of overlap past the farther of them.
    double nearest = std::numeric_limits<double>::infinity(), second = nearest;
    for (const Jaw& jaw : jaws) {
      const double gap = (jaw.centre - pocket.centre).norm() - (R + jaw.radius);
      second = std::min(second, std::max(nearest, gap));  // without a branch: the square roots overlap
      nearest = std::min(nearest, gap);
    }
    if (jaws.size() >= 2) pocket.radius = std::max(pocket.radius, second + 1e-6);
  }
  return pockets;
}
/// The same, for the table's own jaws (PoolTable::jaws).
[[nodiscard]] inline std::vector<Pocket> capture_circles(const PoolTable& table, double R) {
  return capture_circles(table, table.jaws(), R);
}

/// The first broken invariant of balls of radius R at `centres` (those `in_play`) on `table`, whose
/// cushions, jaws and capture circles are given: "ball i …" with what is wrong (off the table, inside a
/// cushion or a jaw, overlapping a ball by more than overlap_tolerance of a radius); empty if none.
[[nodiscard]] inline std::optional<std::pair<std::size_t, std::string>> broken_invariant(
    const PoolTable& table, const std::vector<CushionSegment>& cushions, const std::vector<Jaw>& jaws,
    const std::vector<Pocket>& pockets, const std::vector<Eigen::Vector2d>& centres,
    const std::vector<bool>& in_play, double R) {
  using detail::shortest;
  const double slack = R * overlap_tolerance;
  // How far behind a nose line a ball's centre may be: inside a pocket's capture circle, at the most.
  double reach = 0;
  for (const Pocket& pocket : pockets) {
    reach =
        std::max({reach, -pocket.centre.x() + pocket.radius, pocket.centre.x() + pocket.radius - table.length,
                  -pocket.centre.y() + pocket.radius, pocket.centre.y() + pocket.radius - table.width});
  }
  for (std::size_t i = 0; i < centres.size(); ++i) {
    if (!in_play[i]) continue;
    const Eigen::Vector2d& r = centres[i];
    const auto broken = [&](const std::string& what) { return std::pair{i, what}; };
    if (!(r.x() > -reach && r.x() < table.length + reach && r.y() > -reach && r.y() < table.width + reach))
      return broken("left the table at (" + shortest(r.x()) + ", " + shortest(r.y()) + ")");
    for (std::size_t k = 0; k < cushions.size(); ++k) {
      const CushionSegment& c = cushions[k];
      const Eigen::Vector2d along = c.end - c.start;
      const double f = (r - c.start).dot(along);
      if (f >= 0 && f <= along.squaredNorm() && (r - c.start).dot(c.normal) < R - slack)
        return broken("is inside cushion " + std::to_string(k) + ": its centre " +
                      shortest((r - c.start).dot(c.normal)) + " m from the nose line");
    }
    for (std::size_t k = 0; k < jaws.size(); ++k) {
      if ((r - jaws[k].centre).norm() < R + jaws[k].radius - slack)
        return broken("is inside jaw " + std::to_string(k));
    }
    for (std::size_t j = i + 1; j < centres.size(); ++j) {
      if (!in_play[j]) continue;
      const double d = std::hypot(r.x() - centres[j].x(), r.y() - centres[j].y());
      if (d < 2 * R - slack)
        return broken("overlaps ball " + std::to_string(j) + " by " + shortest(2 * R - d) + " m");
    }
  }
  return std::nullopt;
}

/// Throws std::invalid_argument naming the ball where `balls` cannot start a shot on `table` with balls
/// of radius R: a state not finite; a velocity component, or R times a spin component, beyond
/// billiards::component_limit (the checked calls' bound, within which the kinetic energy and every
/// contact stay finite), struck or not; a ball in play whose centre is neither on the cloth at least a
/// radius inside every cushion's nose nor in a pocket's mouth clear of the cushions and jaws (where a
/// shot may leave a ball), or whose velocity is not horizontal; two balls in play overlapping.
inline void validate(const std::vector<PoolBall>& balls, const PoolTable& table, double R) {
  using detail::shortest;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const PoolBall& b = balls[i];
    const auto fail = [&](const std::string& what) {
      throw std::invalid_argument("ball " + std::to_string(i) + " " + what);
    };
    if (!b.position.allFinite() || !b.velocity.allFinite() || !b.angular_velocity.allFinite())
      fail("has a position, velocity or spin that is not finite");
    const double limit = billiards::component_limit<double>();
    const auto bounded = [&](const char* what, const Eigen::Vector3d& v, double scale, const char* unit) {
      if (!(scale * v.cwiseAbs().maxCoeff() <= limit))
        fail("has " + std::string(what) + " (" + shortest(v.x()) + ", " + shortest(v.y()) + ", " +
             shortest(v.z()) + ")" + unit + ", expected components" +
             (scale == 1 ? "" : " times the radius") + " of magnitude at most " + shortest(limit) +
             " (billiards::component_limit: within it the energy and every contact stay finite)");
    };
    bounded("velocity", b.velocity, 1, " m/s");
    bounded("spin", b.angular_velocity, R, " rad/s");
    if (b.pocketed) continue;
    const double x = b.position.x(), y = b.position.y(), slack = R * overlap_tolerance;
    // Beyond a nose's line only in a pocket's mouth, clear of the cushions and the jaws: where a shot
    // may leave a ball at rest (the engine's own invariant), so that a shot's end can start the next.
    const bool inside =
        x >= R - slack && x <= table.length - R + slack && y >= R - slack && y <= table.width - R + slack;
    const auto in_mouth = [&] {
      return !broken_invariant(table, table.cushions(), table.jaws(), capture_circles(table, R), {{x, y}},
                               {true}, R);
    };
    if (!inside && !in_mouth())
      fail("is at (" + shortest(x) + ", " + shortest(y) +
           "), expected a centre on the cloth at least a radius (" + shortest(R) +
           ") inside every cushion's nose, or in a pocket's mouth clear of its jaws");
    if (b.velocity.z() != 0)
      fail("has v_z = " + shortest(b.velocity.z()) + ", expected 0 (a ball on the cloth moves horizontally)");
  }
  for (std::size_t i = 0; i < balls.size(); ++i) {
    for (std::size_t j = i + 1; j < balls.size(); ++j) {
      if (balls[i].pocketed || balls[j].pocketed) continue;
      // The squared distance first (the centres lie on the cloth, so the squares neither overflow nor,
      // short of an overlap, underflow), a little above the limit's square for its rounding; the
      // distance itself only where that leaves an overlap possible.
      const double dx = balls[i].position.x() - balls[j].position.x(),
                   dy = balls[i].position.y() - balls[j].position.y();
      const double limit = 2 * R * (1 - overlap_tolerance);
      if (!(dx * dx + dy * dy < limit * limit * (1 + 1e-12))) continue;
      const double d = std::hypot(dx, dy);
      if (d < limit)
        throw std::invalid_argument("balls " + std::to_string(i) + " and " + std::to_string(j) +
                                    " overlap: their centres are " + shortest(d) +
                                    " m apart, expected at least " + shortest(2 * R) + " (two radii)");
    }
  }
}

}  // namespace billiards::simulation::shot
