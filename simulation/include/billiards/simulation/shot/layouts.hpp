/// \file
/// The starting positions of the games beyond the pool racks (pool_table.hpp's rack()): the snooker
/// set-up (15 reds, the colours on their spots, the cue ball in the D) and the three-cushion opening
/// position; the snooker table's markings (the baulk line, the D and the spots); and placing a ball by
/// hand: the cue ball in hand (anywhere, behind the head string, in the D), a pool ball respotted on the
/// long string, a snooker colour respotted on its spot or the highest free one.
#pragma once

#include <billiards/simulation/shot/pool_table.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace billiards::simulation {

/// The snooker balls of snooker_setup() by index, and their values.
namespace snooker_ball {
inline constexpr std::size_t cue_ball = 0;     ///< the white
inline constexpr std::size_t first_red = 1;    ///< the first of the reds, 1 to 15
inline constexpr std::size_t last_red = 15;    ///< the last of the reds
inline constexpr std::size_t yellow = 16;      ///< the yellow, worth 2
inline constexpr std::size_t green = 17;       ///< the green, worth 3
inline constexpr std::size_t brown = 18;       ///< the brown, worth 4
inline constexpr std::size_t blue = 19;        ///< the blue, worth 5
inline constexpr std::size_t pink = 20;        ///< the pink, worth 6
inline constexpr std::size_t black = 21;       ///< the black, worth 7
inline constexpr std::size_t ball_count = 22;  ///< the balls of the set-up: the white, 15 reds, 6 colours

/// Whether `ball` is a red.
[[nodiscard]] constexpr bool is_red(std::size_t ball) noexcept { return ball >= first_red && ball <= last_red; }
/// Whether `ball` is a colour (yellow to black).
[[nodiscard]] constexpr bool is_colour(std::size_t ball) noexcept { return ball >= yellow && ball <= black; }
/// A ball's value: a red 1, yellow 2, green 3, brown 4, blue 5, pink 6, black 7; the cue ball 0.
[[nodiscard]] constexpr int value(std::size_t ball) noexcept {
  return is_red(ball) ? 1 : is_colour(ball) ? static_cast<int>(ball - yellow) + 2 : 0;
}
/// A ball's name: "white", "red", "yellow", "green", "brown", "blue", "pink", "black".
[[nodiscard]] inline const char* name(std::size_t ball) noexcept {
  static const char* const colours[] = {"yellow", "green", "brown", "blue", "pink", "black"};
  return ball == cue_ball ? "white" : is_red(ball) ? "red" : is_colour(ball) ? colours[ball - yellow] : "none";
}
}  // namespace snooker_ball

/// The snooker table's markings (WPBSA): the baulk line 29 in (737 mm) from the baulk cushion's face
/// (x = 0), the D a semicircle of 11½ in (292 mm) on it about its middle, behind it; the spots: yellow
/// and green at the D's right and left corners seen from the baulk end (y below and above the middle),
/// brown in the middle of the baulk line, blue at the table's centre, pink midway between the centre and
/// the top cushion's face, black 12¾ in (324 mm) from the top cushion's face.
struct SnookerMarkings {
  double baulk_line = 0;  ///< x of the baulk line (m)
  double d_radius = 0;    ///< the D's radius (m)
  std::array<TableVector, 6> spots{};  ///< the colours' spots, yellow to black

  /// The spot of colour `ball` (snooker_ball::yellow … snooker_ball::black).
  [[nodiscard]] TableVector spot(std::size_t ball) const { return spots.at(ball - snooker_ball::yellow); }
  /// Whether a centre at `at` is in the D (on its line or arc included).
  [[nodiscard]] bool in_d(const TableVector& at, double width) const noexcept {
    const TableVector middle(baulk_line, width / 2);
    return at.x() <= baulk_line && (at - middle).norm() <= d_radius;
  }
};

/// The markings of `table` (its length and width; the distances are the WPBSA's, in metres).
inline SnookerMarkings snooker_markings(const PoolTable& table) {
  SnookerMarkings m;
  m.baulk_line = 0.737;
  m.d_radius = 0.292;
  const double L = table.length, middle = table.width / 2;
  m.spots = {TableVector(m.baulk_line, middle - m.d_radius), TableVector(m.baulk_line, middle + m.d_radius),
             TableVector(m.baulk_line, middle), TableVector(L / 2, middle), TableVector(0.75 * L, middle),
             TableVector(L - 0.324, middle)};
  return m;
}

/// The snooker set-up (snooker_ball:: indices): the cue ball in the D on the baulk line midway between the
/// brown and yellow spots, the colours on their spots, the 15 reds in a triangle (rows of 1 to 5 along
/// +x) whose apex stands as near the pink as it can without touching it (a gap of 1e-3 R). With `jitter`
/// 0 the reds touch (frozen, up to rounding); otherwise spread and moved as rack() does. Throws
/// std::invalid_argument for a jitter outside [0, 1] or a table too short for the set-up.
inline std::vector<PoolBall> snooker_setup(const PoolTable& table, const PoolPhysics& physics, double jitter = 0,
                                           std::uint64_t seed = 0) {
  if (!(jitter >= 0 && jitter <= 1))
    throw std::invalid_argument("jitter is " + std::to_string(jitter) + ", expected a fraction of the radius in [0, 1]");
  const double R = physics.radius, spacing = 2 * R * (1 + jitter);
  const SnookerMarkings m = snooker_markings(table);
  const TableVector apex = m.spot(snooker_ball::pink) + TableVector(2 * R * (1 + 1e-3) + (spacing - 2 * R), 0);
  if (apex.x() + 4 * spacing * std::sqrt(3.0) / 2 + spacing >= m.spot(snooker_ball::black).x())
    throw std::invalid_argument("snooker_setup: the table is " + std::to_string(table.length) +
                                " m long, too short for the reds between the pink and the black");
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<PoolBall> balls(snooker_ball::ball_count);
  const auto put = [&](std::size_t ball, const TableVector& at) { balls[ball].position = {at.x(), at.y(), R}; };
  put(snooker_ball::cue_ball, TableVector(m.baulk_line, table.width / 2 - m.d_radius / 2));
  for (std::size_t colour = snooker_ball::yellow; colour <= snooker_ball::black; ++colour) put(colour, m.spot(colour));
  std::size_t red = snooker_ball::first_red;
  for (int row = 0; row < 5; ++row) {
    for (int j = 0; j <= row; ++j) {
      TableVector at(apex.x() + row * spacing * std::sqrt(3.0) / 2, apex.y() + spacing * (j - row / 2.0));
      if (jitter > 0) {
        const double angle = 2 * M_PI * unit(random), size = jitter * R / 2 * std::sqrt(unit(random));
        at += size * TableVector(std::cos(angle), std::sin(angle));
      }
      put(red++, at);
    }
  }
  return balls;
}

/// The UMB's opening position of three-cushion on `table` (carom_table()): the red (ball 2) on the top
/// spot (a quarter of the length from the foot cushion), the opponent's ball (1, yellow) on the head spot,
/// the breaker's cue ball (0, white) on the head string 182 mm to the side `side` (+1: y above the head
/// spot, −1: below). Throws std::invalid_argument for a side other than ±1.
inline std::vector<PoolBall> three_cushion_setup(const PoolTable& table, const PoolPhysics& physics, int side = 1) {
  if (side != 1 && side != -1)
    throw std::invalid_argument("side is " + std::to_string(side) + ", expected +1 or -1");
  const double R = physics.radius;
  std::vector<PoolBall> balls(3);
  const TableVector head = table.head_spot(), foot = table.foot_spot();
  balls[0].position = {head.x(), head.y() + side * 0.182, R};
  balls[1].position = {head.x(), head.y(), R};
  balls[2].position = {foot.x(), foot.y(), R};
  return balls;
}

/// Where a ball may be placed by hand.
enum class Placement {
  anywhere,            ///< anywhere on the cloth where it overlaps no ball
  behind_head_string,  ///< with its centre no further than a quarter of the length from the head cushion
  in_d,                ///< with its centre in the snooker D (snooker_markings)
};

/// Puts ball `ball` of `balls` at rest at `at` (in play, without spin) if its centre lies on the cloth
/// (a radius inside the noses), in `where`, and it overlaps no other ball in play (centres at least
/// 2R(1 + 1e-9) apart); returns whether it did (the balls are left as they were where not). Throws
/// std::out_of_range for a ball that is not there.
inline bool place_ball(const PoolTable& table, const PoolPhysics& physics, std::vector<PoolBall>& balls,
                       std::size_t ball, const TableVector& at, Placement where = Placement::anywhere) {
  const double R = physics.radius;
  PoolBall& placed = balls.at(ball);
  if (!(std::isfinite(at.x()) && std::isfinite(at.y()))) return false;
  if (!(at.x() >= R && at.x() <= table.length - R && at.y() >= R && at.y() <= table.width - R)) return false;
  if (where == Placement::behind_head_string && !(at.x() <= 0.25 * table.length)) return false;
  if (where == Placement::in_d && !snooker_markings(table).in_d(at, table.width)) return false;
  for (std::size_t k = 0; k < balls.size(); ++k) {
    if (k == ball || balls[k].pocketed) continue;
    const Eigen::Vector3d& c = balls[k].position;
    if (std::hypot(c.x() - at.x(), c.y() - at.y()) < 2 * R * (1 + 1e-9)) return false;
  }
  placed = PoolBall{};
  placed.position = {at.x(), at.y(), R};
  return true;
}

/// The cue ball (ball `cue_ball`) in hand: at `wanted` where place_ball() takes it there, else at the
/// nearest free point to the region's own point (the head spot; the D's middle for Placement::in_d) on
/// rings of R/2 about it. Throws std::runtime_error where no free place is found within the table.
inline void place_cue_ball(const PoolTable& table, const PoolPhysics& physics, std::vector<PoolBall>& balls,
                           std::optional<TableVector> wanted, Placement where, std::size_t cue_ball = 0) {
  if (wanted && place_ball(table, physics, balls, cue_ball, *wanted, where)) return;
  const SnookerMarkings m = snooker_markings(table);
  const TableVector from =
      where == Placement::in_d ? TableVector(m.baulk_line - m.d_radius / 2, table.width / 2) : table.head_spot();
  const double step = physics.radius / 2;
  for (int ring = 0; ring * step <= table.length; ++ring) {
    const int points = 8 * ring + 1;
    for (int k = 0; k < points; ++k) {
      const double angle = 2 * M_PI * k / points;
      if (place_ball(table, physics, balls, cue_ball,
                     from + ring * step * TableVector(std::cos(angle), std::sin(angle)), where))
        return;
    }
  }
  throw std::runtime_error("place_cue_ball: no free place for ball " + std::to_string(cue_ball));
}

/// A pool ball respotted (WPA): on the foot spot, or where that is covered, on the long string behind
/// it as near the spot as it fits, then in front of it, in steps of R/8. Throws std::runtime_error where
/// the long string has no free place.
inline void respot_on_long_string(const PoolTable& table, const PoolPhysics& physics, std::vector<PoolBall>& balls,
                                  std::size_t ball) {
  const TableVector foot = table.foot_spot();
  const double step = physics.radius / 8;
  for (int k = 0; k * step <= table.length; ++k) {
    for (const double x : {foot.x() + k * step, foot.x() - k * step})
      if (place_ball(table, physics, balls, ball, TableVector(x, foot.y()))) return;
  }
  throw std::runtime_error("respot: no free place on the long string for ball " + std::to_string(ball));
}

/// A snooker colour respotted (WPBSA): on its own spot; where that is covered, on the highest valued
/// free spot; where every spot is covered, as near its own spot as it fits on the long axis between the
/// spot and the top cushion, then (for the pink and the black, or where that side is full) towards the
/// baulk cushion, in steps of R/8. Throws std::invalid_argument for a ball that is not a colour and
/// std::runtime_error where the long axis has no free place.
inline void respot_colour(const PoolTable& table, const PoolPhysics& physics, std::vector<PoolBall>& balls,
                          std::size_t colour) {
  if (!snooker_ball::is_colour(colour))
    throw std::invalid_argument("respot_colour: ball " + std::to_string(colour) + " is not a colour, expected " +
                                std::to_string(snooker_ball::yellow) + " to " + std::to_string(snooker_ball::black));
  const SnookerMarkings m = snooker_markings(table);
  if (place_ball(table, physics, balls, colour, m.spot(colour))) return;
  for (std::size_t spot = snooker_ball::black; spot >= snooker_ball::yellow; --spot)
    if (place_ball(table, physics, balls, colour, m.spot(spot))) return;
  const TableVector own = m.spot(colour);
  const double step = physics.radius / 8;
  for (int k = 1; k * step <= table.length; ++k)
    if (place_ball(table, physics, balls, colour, own + TableVector(k * step, 0))) return;
  for (int k = 1; k * step <= table.length; ++k)
    if (place_ball(table, physics, balls, colour, own - TableVector(k * step, 0))) return;
  throw std::runtime_error("respot_colour: no free place on the long axis for ball " + std::to_string(colour));
}

}  // namespace billiards::simulation
