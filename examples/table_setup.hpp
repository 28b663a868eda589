// The table of the event-driven example: balls, the table's size, validation of a setup (no overlap,
// every ball on the table) and the two setups the example knows (random balls, the break). The
// simulation is in table.hpp, reading and drawing in table_io.hpp.
#pragma once

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
#include <vector>

namespace billiards_example {

using Vector = Eigen::Vector2d;

struct Ball {
  Vector position;
  Vector velocity;
};

/// A table and the balls on it. All balls have the same radius and mass.
struct Setup {
  double width = 2.54;       ///< metres, the playing area of a 9-ft table
  double height = 1.27;      ///< metres
  double radius = 0.028575;  ///< metres (57.15 mm balls)
  double mass = 0.17;        ///< kilograms
  std::vector<Ball> balls;
};

/// How far balls i and j overlap: two radii minus the distance of their centres (negative when apart).
inline double overlap(const Setup& setup, std::size_t i, std::size_t j) {
  return 2 * setup.radius - (setup.balls[i].position - setup.balls[j].position).norm();
}

/// True when a ball centred at `p` is on the table: its centre at least a radius (less `slack`) from
/// every cushion.
inline bool on_table(const Setup& setup, const Vector& p, double slack = 0) {
  const double low = setup.radius - slack;
  return p.x() >= low && p.x() <= setup.width - low && p.y() >= low && p.y() <= setup.height - low;
}

/// Rejects a setup that is not a valid table: a clear message naming the ball, the value and what was
/// expected. Throws std::invalid_argument.
inline void validate(const Setup& setup) {
  const auto fail = [](const std::string& message) { throw std::invalid_argument(message); };
  const auto positive = [&](const char* name, double value) {
    if (!(value > 0) || !std::isfinite(value)) {
      std::ostringstream text;
      text << name << " is " << value << ", expected a positive finite number";
      fail(text.str());
    }
  };
  positive("width", setup.width);
  positive("height", setup.height);
  positive("radius", setup.radius);
  positive("mass", setup.mass);
  if (setup.balls.empty()) fail("no balls: expected at least one");
  const double r = setup.radius;
  for (std::size_t i = 0; i < setup.balls.size(); ++i) {
    const Ball& ball = setup.balls[i];
    std::ostringstream text;
    if (!ball.position.allFinite() || !ball.velocity.allFinite()) {
      text << "ball " << i << " has a position or velocity that is not finite";
      fail(text.str());
    }
    const Vector& p = ball.position;
    if (!on_table(setup, p)) {
      text << "ball " << i << " at (" << p.x() << ", " << p.y() << ") is outside the table: expected its "
           << "centre within [" << r << ", " << setup.width - r << "] x [" << r << ", " << setup.height - r
           << "] (a radius from every cushion)";
      fail(text.str());
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (overlap(setup, j, i) > 0) {
        text << "balls " << j << " and " << i << " overlap: their centres are "
             << 2 * r - overlap(setup, j, i) << " apart, expected at least two radii (" << 2 * r << ")";
        fail(text.str());
      }
    }
  }
}

/// `count` balls at random, non-overlapping positions with speeds in [0.5, 1.5] × `speed` in random
/// directions. Random placement jams at about 55 % of the area covered (random sequential adsorption),
/// so more than half is rejected at once. Throws std::invalid_argument when they do not fit.
inline Setup random_setup(Setup table, std::size_t count, std::uint64_t seed, double speed = 1.0) {
  constexpr double pi = 3.14159265358979323846;
  const double r = table.radius;
  const auto cannot_place = [&](const std::string& why) {
    std::ostringstream text;
    text << "balls is " << count << ": cannot place that many balls of radius " << r << " at random on a "
         << table.width << " x " << table.height << " table (" << why << "), expected fewer";
    throw std::invalid_argument(text.str());
  };
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
    const Vector p(x(random), y(random));
    const bool free = std::all_of(table.balls.begin(), table.balls.end(),
                                  [&](const Ball& other) { return (other.position - p).norm() >= 2 * r; });
    if (!free) {
      if (++failures > 100000) cannot_place("no free place found in 100000 tries");
      continue;
    }
    failures = 0;
    const double a = angle(random), s = magnitude(random);
    table.balls.push_back({p, Vector(s * std::cos(a), s * std::sin(a))});
  }
  return table;
}

/// The break: fifteen balls racked in a triangle (a gap of 1e-4 radii between neighbours) at the foot
/// spot, and the cue ball struck from the head string straight at the apex ball at `speed`.
inline Setup break_setup(Setup table, double speed = 8.0) {
  const double r = table.radius, spacing = 2 * r * (1 + 1e-4);
  const Vector apex(0.75 * table.width, 0.5 * table.height);
  table.balls.clear();
  table.balls.push_back({Vector(0.25 * table.width, 0.5 * table.height), Vector(speed, 0)});  // the cue ball
  for (int row = 0; row < 5; ++row) {
    for (int k = 0; k <= row; ++k) {
      const Vector p = apex + Vector(row * spacing * std::sqrt(3.0) / 2, (k - row / 2.0) * spacing);
      table.balls.push_back({p, Vector(0, 0)});
    }
  }
  return table;
}

}  // namespace billiards_example
