/// \file
/// The tables of the shot engine: the playing surface between the cushions' noses, six pockets
/// (capture circles), the straight cushions between them and the rounded jaws where the cushions end, or
/// no pockets at all (carom); presets after the WPA's (pool), the WPBSA's (snooker) and the UMB's
/// (carom) dimensions; the balls' and the cloth's physical parameters with their sources; and the 8-ball
/// and 9-ball racks.
///
/// Coordinates: x along the table's length, 0 at the head cushion's nose and `length` at the foot
/// cushion's; y across, 0 and `width` at the side cushions' noses; z up, the cloth at z = 0.
#pragma once

#include <billiards/simulation/core/ball.hpp>

#include <billiards/cloth.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace billiards::simulation {

/// A straight cushion between two pockets: its nose a segment of a line at the nose's height, from
/// `start` to `end` (on the cloth's plane), and its unit normal into the table.
struct CushionSegment {
  TableVector start;   ///< one end of the nose, at a jaw
  TableVector end;     ///< the other end, at a jaw
  TableVector normal;  ///< unit, from the cushion into the table
};

/// A jaw: the rounded end of a cushion at a pocket, a vertical cylinder of the nose's radius about
/// `centre`, tangent to the cushion's nose line where the straight part ends.
struct Jaw {
  TableVector centre;  ///< the cylinder's axis on the cloth's plane
  double radius;       ///< metres
};

/// A pocket: a ball whose centre enters the capture circle leaves play.
struct Pocket {
  TableVector centre;  ///< the capture circle's centre, behind the cushions' noses
  double radius;       ///< the capture circle's radius (metres)
};

/// A rectangular table for the shot engine: six pockets (pool, snooker) or none (carom, `has_pockets`
/// false). Lengths in metres; the defaults are the 9-ft pool table's.
struct PoolTable {
  double length = 2.54;   ///< x: between the head and foot cushions' noses
  double width = 1.27;    ///< y: between the side cushions' noses
  double corner_mouth = 0.1159;  ///< between the ends of a corner pocket's two cushions (4 9/16 in)
  double side_mouth = 0.1286;    ///< between the ends of a side pocket's two cushions (5 1/16 in)
  double nose_height = 0.03629;  ///< the cushions' nose above the cloth: 63.5 % of a 57.15 mm ball
  double corner_jaw_radius = 0.02095;  ///< the rounding of a cushion's end at a corner pocket
  double side_jaw_radius = 0.00795;    ///< at a side pocket
  double corner_pocket_radius = 0.062;  ///< a corner pocket's capture circle
  double corner_pocket_depth = 0.0417;  ///< its centre behind the corner where the noses meet, diagonally
  double side_pocket_radius = 0.0645;   ///< a side pocket's capture circle
  double side_pocket_depth = 0.0685;    ///< its centre behind the side cushions' nose line
  /// false: a carom table, four cushions meeting at the corners, no jaws and no pockets (the mouths,
  /// jaws and capture circles above are then not used).
  bool has_pockets = true;

  /// The straight cushions. With pockets, six: the head (x = 0), the foot (x = length), and the two
  /// halves of each side (y = 0, y = width), in that order; without, four: the head, the foot, the side
  /// at y = 0 and the side at y = width, each the whole length of its side.
  [[nodiscard]] std::vector<CushionSegment> cushions() const {
    if (!has_pockets) {
      const double L = length, W = width;
      return {{{0, 0}, {0, W}, {1, 0}}, {{L, 0}, {L, W}, {-1, 0}}, {{0, 0}, {L, 0}, {0, 1}}, {{0, W}, {L, W}, {0, -1}}};
    }
    const double c = corner_mouth / std::sqrt(2.0), s = side_mouth / 2, L = length, W = width;
    return {{{0, c}, {0, W - c}, {1, 0}},
            {{L, c}, {L, W - c}, {-1, 0}},
            {{c, 0}, {L / 2 - s, 0}, {0, 1}},
            {{L / 2 + s, 0}, {L - c, 0}, {0, 1}},
            {{c, W}, {L / 2 - s, W}, {0, -1}},
            {{L / 2 + s, W}, {L - c, W}, {0, -1}}};
  }

  /// The twelve jaws, one at each end of each cushion, in the order of cushions(): each tangent to its
  /// cushion's nose line at the end, behind it. None without pockets.
  [[nodiscard]] std::vector<Jaw> jaws() const {
    std::vector<Jaw> out;
    if (!has_pockets) return out;
    const double side_x = length / 2;
    const std::vector<CushionSegment> segments = cushions();
    out.reserve(2 * segments.size());
    for (const CushionSegment& cushion : segments) {
      for (const TableVector& end : {cushion.start, cushion.end}) {
        const bool at_side_pocket = std::fabs(end.x() - side_x) < side_mouth;
        const double r = at_side_pocket ? side_jaw_radius : corner_jaw_radius;
        out.push_back({end - r * cushion.normal, r});
      }
    }
    return out;
  }

  /// The six pockets: the corners (0, 0), (length, 0), (0, width), (length, width), then the sides
  /// (length/2, 0) and (length/2, width). None without pockets.
  [[nodiscard]] std::vector<Pocket> pockets() const {
    if (!has_pockets) return {};
    const double d = corner_pocket_depth / std::sqrt(2.0), L = length, W = width;
    return {{{-d, -d}, corner_pocket_radius},
            {{L + d, -d}, corner_pocket_radius},
            {{-d, W + d}, corner_pocket_radius},
            {{L + d, W + d}, corner_pocket_radius},
            {{L / 2, -side_pocket_depth}, side_pocket_radius},
            {{L / 2, W + side_pocket_depth}, side_pocket_radius}};
  }

  /// Equal where every field is.
  friend bool operator==(const PoolTable&, const PoolTable&) = default;

  /// The foot spot, where a rack's apex ball stands: a quarter of the length from the foot cushion.
  [[nodiscard]] TableVector foot_spot() const { return {0.75 * length, 0.5 * width}; }
  /// The head spot, where the cue ball stands for a break: a quarter of the length from the head.
  [[nodiscard]] TableVector head_spot() const { return {0.25 * length, 0.5 * width}; }
};

/// The table named by `size`: "9ft" (WPA: 100 × 50 in, 2.54 × 1.27 m), "8ft" (WPA: 92 × 46 in,
/// 2.3368 × 1.1684 m) or "7ft" (not a WPA size; the common bar table of 78 × 39 in, 1.9812 × 0.9906 m).
/// Every preset has the WPA's pocket mouths (corner 4 1/2–4 5/8 in, side 5–5 1/8 in: the middle of each)
/// and nose height (62.5–64.5 % of the ball's height: 63.5 %), and pooltool's jaw and capture-circle
/// geometry. Throws std::invalid_argument naming the size and the ones there are.
inline PoolTable pool_table(std::string_view size) {
  PoolTable table;
  if (size == "9ft") {
    table.length = 2.54;
    table.width = 1.27;
  } else if (size == "8ft") {
    table.length = 2.3368;
    table.width = 1.1684;
  } else if (size == "7ft") {
    table.length = 1.9812;
    table.width = 0.9906;
  } else {
    throw std::invalid_argument("table is '" + std::string(size) + "', expected 7ft, 8ft or 9ft");
  }
  return table;
}

/// The snooker table: the WPBSA's 12-ft match table, its playing area 3569 × 1778 mm between the
/// cushions' faces, with pockets after pooltool's snooker table (the WPBSA's pocket templates are not
/// published): curved facings at the mouths (jaws of 4 in at the corners and 2.5 in at the middle
/// pockets) whose narrowest openings are 83 mm and 87 mm, the corner pockets' capture circles of 4 in
/// 36 mm behind the corner, the middle pockets' of 1.68 in 0.95 in behind the nose line; the cushions'
/// nose 28 mm above the cloth. A mouth (between the straight noses' ends) is its narrowest opening
/// widened by the jaws' curve: the opening + (2 − √2) ρ at a corner, + 2ρ at a middle pocket.
inline PoolTable snooker_table() {
  constexpr double inch = 0.0254;
  PoolTable table;
  table.length = 3.569;
  table.width = 1.778;
  table.corner_jaw_radius = 4 * inch;
  table.side_jaw_radius = 2.5 * inch;
  table.corner_mouth = 0.083 + (2 - std::sqrt(2.0)) * table.corner_jaw_radius;
  table.side_mouth = 0.087 + 2 * table.side_jaw_radius;
  table.nose_height = 0.028;
  table.corner_pocket_radius = 4 * inch;
  table.corner_pocket_depth = 0.036;
  table.side_pocket_radius = 1.68 * inch;
  table.side_pocket_depth = 0.95 * inch;
  return table;
}

/// The carom table: the UMB's match table for three-cushion, its playing area 2.84 × 1.42 m between the
/// cushions' noses, no pockets, the cushions' nose 37 mm above the cloth (UMB: 37 ± 1 mm).
inline PoolTable carom_table() {
  PoolTable table;
  table.length = 2.84;
  table.width = 1.42;
  table.nose_height = 0.037;
  table.has_pockets = false;
  return table;
}

/// The physical parameters of a shot: the balls (all alike), the cloth, ball–ball and ball–cushion
/// contacts. The defaults and their sources are in docs/shot.md.
struct PoolPhysics {
  double radius = 0.028575;           ///< a ball's radius (m): 2 1/4 in balls (WPA)
  double mass = 0.170;                ///< a ball's mass (kg): WPA 5.5–6 oz; pooltool's 0.170
  Cloth<double> cloth{0.2, 0.01, 0.0127, 9.81};  ///< μ_s, μ_r, μ_sp, g: pooltool's defaults
  double ball_restitution = 0.95;     ///< e between balls (pooltool's e_b)
  double ball_friction = 0.06;        ///< μ between balls (Alciatore's throw measurements, TP A-14)
  double cushion_restitution = 0.85;  ///< e_c at a cushion's nose (pooltool's)
  double cushion_friction = 0.2;      ///< μ_c at a cushion's nose (pooltool's)
};

/// The snooker balls: 52.5 mm (WPBSA) and 0.140 kg (pooltool's snooker ball; the WPBSA sets only a
/// tolerance of 3 g within a set); the cloth and the contacts as on the pool table.
inline PoolPhysics snooker_physics() {
  PoolPhysics physics;
  physics.radius = 0.02625;
  physics.mass = 0.140;
  return physics;
}

/// The carom balls and the heated cloth: 61.5 mm balls (UMB: 61–61.5 mm) of 0.210 kg (UMB: 205–220 g);
/// the heated cloth rolls faster than the pool table's: μ_r = 0.005, half the pool cloth's (no published
/// measurement: a choice); the cushions' friction 0.15 (pooltool's carom table); the rest as on the pool
/// table.
inline PoolPhysics carom_physics() {
  PoolPhysics physics;
  physics.radius = 0.03075;
  physics.mass = 0.210;
  physics.cloth.rolling_friction = 0.005;
  physics.cushion_friction = 0.15;
  return physics;
}

/// The tables by name: "7ft", "8ft", "9ft" (pool_table), "snooker" (snooker_table) and "carom"
/// (carom_table). Throws std::invalid_argument naming the name and the ones there are.
inline PoolTable table_preset(std::string_view name) {
  if (name == "snooker") return snooker_table();
  if (name == "carom") return carom_table();
  if (name == "7ft" || name == "8ft" || name == "9ft") return pool_table(name);
  throw std::invalid_argument("table is '" + std::string(name) + "', expected 7ft, 8ft, 9ft, snooker or carom");
}

/// The balls' and the cloth's physics that go with table_preset(name): the pool physics (PoolPhysics{})
/// on the pool tables, snooker_physics() and carom_physics(). Throws as table_preset does.
inline PoolPhysics physics_preset(std::string_view name) {
  if (name == "snooker") return snooker_physics();
  if (name == "carom") return carom_physics();
  (void)table_preset(name);
  return {};
}

/// A ball of a shot: its state on the cloth, and whether it is still in play.
struct PoolBall {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();          ///< centre, z = radius on the cloth
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          ///< horizontal on the cloth
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  ///< rad/s
  bool pocketed = false;  ///< out of play
};

/// The racks of the games.
enum class Rack {
  eight_ball,  ///< 15 object balls in a triangle, the 8 in its middle
  nine_ball,   ///< 9 object balls in a diamond, the 1 at the apex and the 9 in the middle
};

/// The balls of a break: the cue ball (index 0) on the head spot and the object balls racked with the
/// apex on the foot spot, rows along +x. With `jitter` 0 neighbours touch (frozen, up to rounding);
/// otherwise the rack is spread by 1 + jitter and each ball moved by up to jitter/2 of the radius in a
/// direction drawn from `seed`, which keeps every gap ≥ jitter R. 9-ball: a diamond of 9 (rows
/// 1-2-3-2-1), the 1 at the apex and the 9 in the middle; 8-ball: a triangle of 15 (rows 1 to 5), the 8
/// in the middle of the third row; the other balls in order. Index i is ball i. Throws
/// std::invalid_argument for a jitter outside [0, 1].
inline std::vector<PoolBall> rack(const PoolTable& table, const PoolPhysics& physics, Rack kind, double jitter = 0,
                                  std::uint64_t seed = 0) {
  if (!(jitter >= 0 && jitter <= 1))
    throw std::invalid_argument("jitter is " + std::to_string(jitter) + ", expected a fraction of the radius in [0, 1]");
  const double R = physics.radius, spacing = 2 * R * (1 + jitter);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  const std::vector<int> rows =
      kind == Rack::nine_ball ? std::vector<int>{1, 2, 3, 2, 1} : std::vector<int>{1, 2, 3, 4, 5};
  std::vector<TableVector> spots;
  const TableVector apex = table.foot_spot();
  for (std::size_t row = 0; row < rows.size(); ++row) {
    const int count = rows[row];
    for (int j = 0; j < count; ++j) {
      TableVector at(apex.x() + static_cast<double>(row) * spacing * std::sqrt(3.0) / 2,
                     apex.y() + spacing * (j - (count - 1) / 2.0));
      if (jitter > 0) {
        const double angle = 2 * M_PI * unit(random), size = jitter * R / 2 * std::sqrt(unit(random));
        at += size * TableVector(std::cos(angle), std::sin(angle));
      }
      spots.push_back(at);
    }
  }
  // The apex (spot 0) takes the 1 and the middle of the third row (spot 4) the 9 or the 8; the others
  // follow in order.
  constexpr std::size_t middle = 4;
  const int special = kind == Rack::nine_ball ? 9 : 8;
  std::vector<PoolBall> balls(spots.size() + 1);
  const auto place = [&](int ball, const TableVector& at) {
    balls[static_cast<std::size_t>(ball)].position = {at.x(), at.y(), R};
  };
  place(0, table.head_spot());
  place(1, spots[0]);
  place(special, spots[middle]);
  int next = 2;
  for (std::size_t spot = 1; spot < spots.size(); ++spot) {
    if (spot == middle) continue;
    if (next == special) ++next;
    place(next++, spots[spot]);
  }
  return balls;
}

/// `count` balls at rest, placed at random from `seed` on the cloth's straight part (every centre at
/// least a radius inside the noses, away from the pockets' mouths): about a quarter of them frozen to a
/// ball placed before (touching it: centres two radii apart, up to rounding), about a quarter frozen to
/// a cushion (a radius from its nose), the others anywhere free. For random shots and layouts; ball 0 is
/// the cue ball. Throws std::invalid_argument for a count of 0 or above 16, or where the balls do not
/// fit (no place found in 10000 tries).
inline std::vector<PoolBall> scatter(const PoolTable& table, const PoolPhysics& physics, std::size_t count,
                                     std::uint64_t seed) {
  if (count == 0 || count > 16)
    throw std::invalid_argument("count is " + std::to_string(count) + ", expected 1 to 16 balls");
  const double R = physics.radius, L = table.length, W = table.width;
  // Clear of the mouths: a centre's along-rail coordinate beyond the jaws by a radius.
  const double corner = table.has_pockets ? table.corner_mouth / std::sqrt(2.0) + 2 * R : 0;
  const double side = table.has_pockets ? table.side_mouth / 2 + 2 * R : 0;
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  const auto clear_of_mouths = [&](const TableVector& r) {
    const bool near_long_rail = r.y() < 2 * R || r.y() > W - 2 * R;
    const bool near_short_rail = r.x() < 2 * R || r.x() > L - 2 * R;
    if (near_long_rail && (r.x() < corner || r.x() > L - corner || std::fabs(r.x() - L / 2) < side)) return false;
    if (near_short_rail && (r.y() < corner || r.y() > W - corner)) return false;
    return r.x() >= R && r.x() <= L - R && r.y() >= R && r.y() <= W - R;
  };
  std::vector<PoolBall> balls;
  for (std::size_t i = 0; i < count; ++i) {
    bool placed = false;
    for (int attempt = 0; attempt < 10000 && !placed; ++attempt) {
      const double kind = unit(random);
      TableVector r;
      if (kind < 0.25 && !balls.empty()) {
        const std::size_t other = std::min(balls.size() - 1, static_cast<std::size_t>(unit(random) * balls.size()));
        const double angle = 2 * M_PI * unit(random);
        r = TableVector(balls[other].position.x(), balls[other].position.y()) +
            2 * R * TableVector(std::cos(angle), std::sin(angle));
      } else if (kind < 0.5) {
        const int rail = static_cast<int>(unit(random) * 4) % 4;
        const double along = unit(random);
        r = rail == 0   ? TableVector(R, along * W)
            : rail == 1 ? TableVector(L - R, along * W)
            : rail == 2 ? TableVector(along * L, R)
                        : TableVector(along * L, W - R);
      } else {
        r = TableVector(R + unit(random) * (L - 2 * R), R + unit(random) * (W - 2 * R));
      }
      if (!clear_of_mouths(r)) continue;
      bool free = true;
      for (const PoolBall& b : balls) {
        free = free && std::hypot(b.position.x() - r.x(), b.position.y() - r.y()) >= 2 * R;
      }
      if (!free) continue;
      PoolBall ball;
      ball.position = {r.x(), r.y(), R};
      balls.push_back(ball);
      placed = true;
    }
    if (!placed)
      throw std::invalid_argument("scatter: no place for ball " + std::to_string(i) + " of " + std::to_string(count) +
                                  " in 10000 tries");
  }
  return balls;
}

}  // namespace billiards::simulation
