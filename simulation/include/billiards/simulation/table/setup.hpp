/// \file
/// The event-driven table's setup: the balls, the table's size, the validation of a setup (no overlap,
/// every ball on the table) and two setups made in code (balls at random, the break). The engine is in
/// billiards/simulation/table/table.hpp.
#pragma once

#include <billiards/simulation/core/ball.hpp>
#include <billiards/simulation/core/invariants.hpp>

#include <billiards/checked.hpp>
#include <billiards/collision.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace billiards::simulation {

/// Where a setup's values were read, for messages: "FILE:LINE: " prefixes (empty for a setup built in
/// code, or for a value left at its default).
struct SetupOrigin {
  std::string file;                ///< "FILE: ", for what has no line of its own
  std::string table;               ///< "FILE:LINE: " of the table directive
  std::string radius;              ///< "FILE:LINE: " of the radius directive
  std::string mass;                ///< "FILE:LINE: " of the mass directive
  std::vector<std::string> balls;  ///< "FILE:LINE: " of each ball
};

/// A table and the balls on it: the cushions are the lines x = 0, x = width, y = 0 and y = height.
/// All balls have the same radius and mass.
struct TableSetup {
  double width = 2.54;         ///< metres, the playing area of a 9-ft table
  double height = 1.27;        ///< metres
  double radius = 0.028575;    ///< metres (57.15 mm balls)
  double mass = 0.17;          ///< kilograms
  std::vector<Ball<2>> balls;  ///< the balls' centres and velocities
  SetupOrigin origin;          ///< where the values were read (for messages; empty when built in code)
};

/// The most balls a table takes: it predicts every pair at the start (N²/2 predictions, and random
/// placement compares each new ball with every ball placed) and each event's balls against every ball,
/// so 10^5 balls take about a minute and a half to start; beyond that the run would not visibly end
/// (10^9 balls on a 10^6 m table passed every other check and placed balls for hours).
inline constexpr std::size_t largest_ball_count = 100000;

/// The error for a ball count beyond largest_ball_count.
inline std::string too_many_balls(std::size_t count) {
  return "balls is " + std::to_string(count) + ", expected at most " + std::to_string(largest_ball_count) +
         " (the table predicts every pair of balls: N^2/2 predictions at the start)";
}

/// The smallest radius a run can resolve on a table of this size: 16 ε max(width, height) /
/// overlap tolerance (1e-9 of a radius, see Table). Positions on the table round by about
/// ε max(width, height); below this radius that rounding alone would exceed the overlap the run
/// allows. 9.0e-6 m for the default 2.54 × 1.27 m table.
inline double smallest_radius(double width, double height) {
  return 16 * std::numeric_limits<double>::epsilon() * std::max(width, height) / overlap_tolerance;
}

/// The distance of two centres, |a − b|. The square root of the squared distance where that square is
/// a normal number (the fast path at every event), std::hypot elsewhere: on a table of 1e-300 m the
/// square underflowed to 0, and two balls far apart read as lying on each other.
inline double centre_distance(const TableVector& a, const TableVector& b) {
  const TableVector d = a - b;
  const double square = d.squaredNorm();
  if (square >= std::numeric_limits<double>::min() && square <= std::numeric_limits<double>::max()) {
    return std::sqrt(square);
  }
  return std::hypot(d.x(), d.y());
}

/// How far balls i and j overlap: two radii minus the distance of their centres (negative when apart).
inline double overlap(const TableSetup& setup, std::size_t i, std::size_t j) {
  return 2 * setup.radius - centre_distance(setup.balls[i].position, setup.balls[j].position);
}

/// True when a ball centred at `p` is on the table: its centre at least a radius (less `slack`) from
/// every cushion.
inline bool on_table(const TableSetup& setup, const TableVector& p, double slack = 0) {
  const double low = setup.radius - slack;
  return p.x() >= low && p.x() <= setup.width - low && p.y() >= low && p.y() <= setup.height - low;
}

namespace detail {

/// Where ball i of `setup` was read ("FILE:LINE: "), or the file's prefix.
inline std::string ball_origin(const TableSetup& setup, std::size_t i) {
  return i < setup.origin.balls.size() ? setup.origin.balls[i] : setup.origin.file;
}

/// Throws std::invalid_argument with `message` prefixed by `where`.
[[noreturn]] inline void fail_setup(const std::string& where, const std::string& message) {
  throw std::invalid_argument(where + message);
}

/// The table's and each ball's values: see validate(const TableSetup&).
inline void validate_values(const TableSetup& setup) {
  const SetupOrigin& origin = setup.origin;
  const auto ball_origin = [&](std::size_t i) { return detail::ball_origin(setup, i); };
  const auto fail = fail_setup;
  const auto positive = [&](const std::string& where, const char* name, double value) {
    if (!(value > 0) || !std::isfinite(value)) {
      std::ostringstream text;
      text << name << " is " << value << ", expected a positive finite number";
      fail(where, text.str());
    }
  };
  positive(origin.table, "width", setup.width);
  positive(origin.table, "height", setup.height);
  positive(origin.radius, "radius", setup.radius);
  positive(origin.mass, "mass", setup.mass);
  const double r = setup.radius;
  // The radius against the table: the radius's line, or the table's where the radius is the default.
  const std::string& radius_origin = origin.radius.empty() ? origin.table : origin.radius;
  if (const double smallest = smallest_radius(setup.width, setup.height); r < smallest) {
    std::ostringstream text;
    text << "radius is " << r << ", expected at least " << smallest << " on a " << setup.width << " x "
         << setup.height << " table (positions on it round by about "
         << std::numeric_limits<double>::epsilon() * std::max(setup.width, setup.height)
         << ", and the run allows overlaps of 1e-9 of a radius)";
    fail(radius_origin, text.str());
  }
  if (!(2 * r < setup.width && 2 * r < setup.height)) {
    std::ostringstream text;
    text << "radius is " << r << ", expected less than half the table's " << setup.width << " x "
         << setup.height;
    fail(radius_origin, text.str());
  }
  if (setup.balls.empty()) fail(origin.file, "no balls: expected at least one");
  if (setup.balls.size() > largest_ball_count) fail(origin.file, too_many_balls(setup.balls.size()));
  for (std::size_t i = 0; i < setup.balls.size(); ++i) {
    const Ball<2>& ball = setup.balls[i];
    std::ostringstream text;
    if (!ball.position.allFinite() || !ball.velocity.allFinite()) {
      text << "ball " << i << " has a position or velocity that is not finite";
      fail(ball_origin(i), text.str());
    }
    // Beyond the checked calls' limit a collision's v2 − v1 and its dot products may overflow (head-on
    // at 5e307 they did, and the run ended on a ball "off the table" at NaN).
    if (const double limit = billiards::component_limit<double>();
        ball.velocity.cwiseAbs().maxCoeff() > limit) {
      text << "ball " << i << " has velocity (" << ball.velocity.x() << ", " << ball.velocity.y()
           << "), expected components of magnitude at most " << limit
           << " (billiards::component_limit, the checked calls' bound: within it no collision overflows)";
      fail(ball_origin(i), text.str());
    }
    const TableVector& p = ball.position;
    if (!on_table(setup, p)) {
      text << "ball " << i << " at (" << p.x() << ", " << p.y() << ") is outside the table: expected its "
           << "centre within [" << r << ", " << setup.width - r << "] x [" << r << ", " << setup.height - r
           << "] (a radius from every cushion)";
      fail(ball_origin(i), text.str());
    }
  }
}

/// No two balls of `setup` overlap; returns how many pairs it compared. Balls hashed into square cells
/// of side 2r; two balls that overlap lie in the same or in neighbouring cells. Balls that do not overlap fill a cell with at most a few, so each ball is
/// compared with a bounded number of others. The cell indices are small: the radius is at least
/// smallest_radius(), so a side has at most about 10^8 cells.
inline std::size_t check_overlaps(const TableSetup& setup) {
  const double r = setup.radius;
  const double cell = 2 * r;
  const auto key = [](std::int64_t x, std::int64_t y) {
    return (static_cast<std::uint64_t>(x) << 32) ^ static_cast<std::uint64_t>(y);
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;
  std::size_t compared = 0;
  cells.reserve(setup.balls.size());
  for (std::size_t i = 0; i < setup.balls.size(); ++i) {
    const TableVector& p = setup.balls[i].position;
    const auto cx = static_cast<std::int64_t>(std::floor(p.x() / cell)),
               cy = static_cast<std::int64_t>(std::floor(p.y() / cell));
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto found = cells.find(key(cx + dx, cy + dy));
        if (found == cells.end()) continue;
        for (const std::size_t j : found->second) {
          ++compared;
          if (overlap(setup, j, i) > 0) {
            std::ostringstream text;
            text << "balls " << j << " and " << i << " overlap: their centres are "
                 << 2 * r - overlap(setup, j, i) << " apart, expected at least two radii (" << 2 * r << ")";
            fail_setup(ball_origin(setup, i), text.str());
          }
        }
      }
    }
    cells[key(cx, cy)].push_back(i);
  }
  return compared;
}

}  // namespace detail

/// Rejects a setup that is not a valid table: a clear message naming where (FILE:LINE: for a setup
/// read from a file), the ball, the value and what was expected. Throws std::invalid_argument.
/// O(N) expected time: the overlap check hashes the balls into cells of one diameter. Returns how many
/// pairs of balls it compared (a handful per ball; the tests hold it to that).
inline std::size_t validate(const TableSetup& setup) {
  detail::validate_values(setup);
  return detail::check_overlaps(setup);
}

/// `count` balls at random, non-overlapping positions with speeds in [0.5, 1.5] × `speed` in random
/// directions. Random placement jams at about 55 % of the area covered (random sequential adsorption),
/// so more than half is rejected at once. Throws std::invalid_argument when they do not fit.
inline TableSetup random_setup(TableSetup table, std::size_t count, std::uint64_t seed, double speed = 1.0) {
  constexpr double pi = 3.14159265358979323846;
  const double r = table.radius;
  const auto cannot_place = [&](const std::string& why) {
    std::ostringstream text;
    text << "balls is " << count << ": cannot place that many balls of radius " << r << " at random on a "
         << table.width << " x " << table.height << " table (" << why << "), expected fewer";
    throw std::invalid_argument(text.str());
  };
  if (count > largest_ball_count) throw std::invalid_argument(too_many_balls(count));
  const double coverage =
      static_cast<double>(count) * pi * r * r / ((table.width - 2 * r) * (table.height - 2 * r));
  if (!(table.width > 2 * r && table.height > 2 * r) || coverage > 0.5) {
    std::ostringstream why;
    why << "they would cover " << 100 * coverage << " % of it, at most 50 % can be placed at random";
    cannot_place(why.str());
  }
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> x(r, table.width - r), y(r, table.height - r), angle(0, 2 * pi),
      magnitude(0.5 * speed, 1.5 * speed);
  table.balls.clear();
  for (std::size_t failures = 0; table.balls.size() < count;) {
    const TableVector p(x(random), y(random));
    const bool free = std::all_of(table.balls.begin(), table.balls.end(), [&](const Ball<2>& other) {
      return centre_distance(other.position, p) >= 2 * r;
    });
    if (!free) {
      if (++failures > 100000) cannot_place("no free place found in 100000 tries");
      continue;
    }
    failures = 0;
    const double a = angle(random), s = magnitude(random);
    table.balls.push_back({p, TableVector(s * std::cos(a), s * std::sin(a))});
  }
  return table;
}

/// The break: fifteen balls racked in a triangle (a gap of 1e-4 radii between neighbours) at the foot
/// spot, and the cue ball struck from the head string straight at the apex ball at `speed`.
inline TableSetup break_setup(TableSetup table, double speed = 8.0) {
  const double r = table.radius, spacing = 2 * r * (1 + 1e-4);
  const TableVector apex(0.75 * table.width, 0.5 * table.height);
  table.balls.clear();
  table.balls.push_back(
      {TableVector(0.25 * table.width, 0.5 * table.height), TableVector(speed, 0)});  // the cue ball
  for (int row = 0; row < 5; ++row) {
    for (int k = 0; k <= row; ++k) {
      const TableVector p = apex + TableVector(row * spacing * std::sqrt(3.0) / 2, (k - row / 2.0) * spacing);
      table.balls.push_back({p, TableVector(0, 0)});
    }
  }
  return table;
}

}  // namespace billiards::simulation
