/// \file
/// Sustained contact: bodies the cloth's friction presses together, moving as one while it presses them.
///
/// The contact laws are impulses (resolution.hpp). Where the cloth presses two balls together, or a ball
/// into a cushion, those impulses repeat ever faster (inelastic collapse); their limit is a contact
/// force. This header gives that limit where everything lies on the line of the contact — the velocities
/// along the contact's normal n, the spins about ŷ = ẑ × n (follow and draw), no side spin — where it is
/// a sequence of pieces of constant accelerations (docs/simulations.md, "Pressed contacts"):
///
/// - Two balls A (behind) and B (in front), touching, with one speed v along n: the normal force N ≥ 0
///   (per unit mass) keeps v̇_A = v̇_B. Each ball's cloth contact slips (u = v − Rω ≠ 0: friction
///   −μ_s g sgn u) or rolls (u = 0: the friction f that keeps it rolling, f = −(2 s N + 5 T)/7 with s = −1
///   for A and +1 for B, while |f| ≤ μ_s g; the rolling resistance μ_r g acts for the part of the time
///   the impulses' limit leaves it rolling, 1 − |f|/(μ_s g)). Between the balls, the contact points slip
///   vertically by σ = R(ω_A + ω_B): friction T = μ_b N sgn σ, or, where σ = 0, what keeps it 0 while
///   |T| ≤ μ_b N. Then v̇ = s N + f (− the rolling resistance), R ω̇ = −(5/2)(f + T) for each.
/// - A ball pressed into a straight cushion whose nose touches it θ above its equator: at rest there,
///   its spin R ω running down at (5/2)(μ_s g + μ_c P), P = μ_s g/(cos θ + μ_c sin θ) the nose's force.
///
/// A piece ends when a slip or the speed reaches zero; the pair then continues in the next piece where
/// the cloth still presses them, and parts otherwise.
#pragma once

#include <billiards/simulation/shot/evolution.hpp>
#include <billiards/simulation/shot/pool_table.hpp>

#include <billiards/cloth.hpp>
#include <billiards/shot.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace billiards::simulation::shot {

namespace pressing {

/// An affine function c + n N + t T of the normal force N and the friction T between the balls.
struct Affine {
  double c = 0;  ///< the constant
  double n = 0;  ///< the factor of N
  double t = 0;  ///< the factor of T
  /// The sum.
  [[nodiscard]] Affine operator+(const Affine& o) const { return {c + o.c, n + o.n, t + o.t}; }
  /// The difference.
  [[nodiscard]] Affine operator-(const Affine& o) const { return {c - o.c, n - o.n, t - o.t}; }
  /// The multiple by `k`.
  [[nodiscard]] Affine operator*(double k) const { return {k * c, k * n, k * t}; }
  /// The value at N and T.
  [[nodiscard]] double at(double N, double T) const { return c + n * N + t * T; }
};

/// A ball's cloth contact in a piece: slipping with sgn u = `sign`, or rolling with sgn f = `sign`.
struct ClothMode {
  bool rolling;  ///< rolling (u = 0 kept by the friction f), else slipping
  double sign;   ///< sgn u slipping, sgn f rolling
};

/// One ball's accelerations in a mode as functions of N and T.
struct BallRates {
  Affine speed;     ///< v̇ (m/s²)
  Affine spin;      ///< R ω̇ about ẑ × n (m/s²)
  Affine friction;  ///< the cloth's friction f per unit mass (m/s²)
};

/// Ball with normal force's sign `s` (−1 behind, +1 in front), speed `v`, in `mode`.
[[nodiscard]] inline BallRates rates(double s, double v, ClothMode mode, const Cloth<double>& cloth) {
  const double mu_g = cloth.sliding_friction * cloth.gravity;
  const Affine T{0, 0, 1}, N{0, 1, 0};
  BallRates r;
  if (!mode.rolling) {
    r.friction = {-mu_g * mode.sign, 0, 0};
    r.speed = N * s + r.friction;
    r.spin = (r.friction + T) * -2.5;
    return r;
  }
  r.friction = (N * (2 * s) + T * 5) * (-1.0 / 7.0);
  // The rolling resistance, for the part 1 − |f|/(μ_s g) of the time the impulses leave it rolling.
  const double rolling_g = cloth.rolling_friction * cloth.gravity * (v > 0 ? 1.0 : -1.0);
  const Affine resistance = Affine{rolling_g, 0, 0} - r.friction * (mode.sign * rolling_g / mu_g);
  r.speed = N * s + r.friction - resistance;
  r.spin = (r.friction + T) * -2.5 - resistance;
  return r;
}

/// The modes a ball's cloth contact may take, in the order they are tried: its slip's sign where it
/// slips; else rolling (either sign of f, where it moves) before slipping either way. Returns how many.
inline int cloth_modes(double u, double v, std::array<ClothMode, 4>& modes) {
  if (u != 0) {
    modes[0] = {false, u > 0 ? 1.0 : -1.0};
    return 1;
  }
  int count = 0;
  if (v != 0) {
    modes[count++] = {true, 1};
    modes[count++] = {true, -1};
  }
  modes[count++] = {false, 1};
  modes[count++] = {false, -1};
  return count;
}

}  // namespace pressing

/// A piece of a pressed pair: the normal force, the common acceleration along n, each ball's R ω̇ about
/// ẑ × n, whether each rolls, and the piece's length and what ends it.
struct PairPiece {
  double force = 0;                      ///< N per unit mass (m/s²)
  double acceleration = 0;               ///< v̇ of both (m/s²)
  std::array<double, 2> spin_rate{};     ///< R ω̇ of A and B (m/s²)
  std::array<bool, 2> rolling{};         ///< whether A and B roll
  double duration = 0;                   ///< s
  PressedEnd ending = PressedEnd::speed;  ///< what ends it
};

/// The piece in which balls A (behind) and B (in front) pressed together continue, from their common
/// speed `v` along n, their slips `u` (v − R ω, ω about ẑ × n) and the slip σ = R(ω_A + ω_B) between
/// them; empty where no mode of the contacts is consistent with a pressing force N > 0 (the balls part)
/// or the piece would not end.
[[nodiscard]] inline std::optional<PairPiece> pair_piece(double v, std::array<double, 2> u, double sigma,
                                                         const PoolPhysics& physics) {
  using pressing::Affine;
  using pressing::ClothMode;
  const Cloth<double>& cloth = physics.cloth;
  const double mu_g = cloth.sliding_friction * cloth.gravity, mu_b = physics.ball_friction;
  const auto sign = [](double x) { return x > 0 ? 1.0 : -1.0; };
  std::array<std::array<ClothMode, 4>, 2> modes{};
  std::array<int, 2> mode_count{};
  for (int b = 0; b < 2; ++b) mode_count[b] = pressing::cloth_modes(u[b], v, modes[b]);
  // Between the balls: the slip's sign where they slip, else sticking before slipping either way.
  const std::array<double, 3> contact_modes = sigma != 0 ? std::array<double, 3>{sign(sigma), 0, 0}
                                                         : std::array<double, 3>{0, 1, -1};  // 0: sticking
  const int contact_count = sigma != 0 ? 1 : 3;
  for (int ia = 0; ia < mode_count[0]; ++ia) {
    for (int ib = 0; ib < mode_count[1]; ++ib) {
      for (int ic = 0; ic < contact_count; ++ic) {
        const ClothMode ma = modes[0][ia], mb = modes[1][ib];
        const double k = contact_modes[ic];
        const pressing::BallRates a = pressing::rates(-1, v, ma, cloth), b = pressing::rates(1, v, mb, cloth);
        const Affine same = a.speed - b.speed, contact = a.spin + b.spin;
        double N = 0, T = 0;
        if (k != 0) {
          // T = k μ_b N: one equation, v̇_A = v̇_B.
          const double slope = same.n + same.t * k * mu_b;
          if (!(slope != 0)) continue;
          N = -same.c / slope;
          T = k * mu_b * N;
        } else {
          // Sticking: v̇_A = v̇_B and σ̇ = 0.
          const double det = same.n * contact.t - same.t * contact.n;
          if (!(det != 0)) continue;
          N = (-same.c * contact.t + same.t * contact.c) / det;
          T = (-same.n * contact.c + same.c * contact.n) / det;
          if (!(std::fabs(T) <= mu_b * N)) continue;
        }
        if (!(N > 0) || !std::isfinite(N)) continue;
        const auto consistent = [&](const ClothMode& m, const pressing::BallRates& r, double slip) {
          if (m.rolling) {
            const double f = r.friction.at(N, T);
            return std::fabs(f) <= mu_g && (m.sign > 0 ? f >= 0 : f < 0);
          }
          if (slip != 0) return true;
          const double grows = r.speed.at(N, T) - r.spin.at(N, T);
          return m.sign > 0 ? grows > 0 : grows < 0;
        };
        if (!consistent(ma, a, u[0]) || !consistent(mb, b, u[1])) continue;
        const double sigma_rate = contact.at(N, T);
        if (sigma == 0 && k != 0 && !(k > 0 ? sigma_rate > 0 : sigma_rate < 0)) continue;
        PairPiece piece;
        piece.force = N;
        piece.acceleration = a.speed.at(N, T);
        piece.spin_rate = {a.spin.at(N, T), b.spin.at(N, T)};
        piece.rolling = {ma.rolling, mb.rolling};
        // The piece lasts until a slip, the contact's slip or the speed reaches zero.
        piece.duration = std::numeric_limits<double>::infinity();
        const auto ends = [&](double value, double rate, PressedEnd what) {
          if (value != 0 && value * rate < 0 && -value / rate < piece.duration) {
            piece.duration = -value / rate;
            piece.ending = what;
          }
        };
        if (!ma.rolling) ends(u[0], piece.acceleration - piece.spin_rate[0], PressedEnd::first_slip);
        if (!mb.rolling) ends(u[1], piece.acceleration - piece.spin_rate[1], PressedEnd::second_slip);
        if (k != 0) ends(sigma, sigma_rate, PressedEnd::contact_slip);
        ends(v, piece.acceleration, PressedEnd::speed);
        if (!std::isfinite(piece.duration) || !(piece.duration > 0)) return std::nullopt;
        return piece;
      }
    }
  }
  return std::nullopt;
}

/// A ball pressed into a straight cushion: its spin's rate R ω̇ about ẑ × n (n into the cushion) and
/// the piece's length, from its spin R ω > 0 there (the cloth's slip drives it into the cushion) and the
/// nose's angle θ above the equator.
struct CushionPiece {
  double spin_rate = 0;  ///< R ω̇ (m/s²)
  double duration = 0;   ///< s
};

/// The piece of a ball at rest against a cushion whose spin R ω (> 0) presses it there; empty where the
/// spin does not press it.
[[nodiscard]] inline std::optional<CushionPiece> cushion_piece(double spin, double sin_nose, double cos_nose,
                                                               const PoolPhysics& physics) {
  if (!(spin > 0)) return std::nullopt;
  const double mu_g = physics.cloth.sliding_friction * physics.cloth.gravity;
  const double nose_force = mu_g / (cos_nose + physics.cushion_friction * sin_nose);
  CushionPiece piece;
  piece.spin_rate = -2.5 * (mu_g + physics.cushion_friction * nose_force);
  piece.duration = spin / -piece.spin_rate;
  if (!std::isfinite(piece.duration) || !(piece.duration > 0)) return std::nullopt;
  return piece;
}

/// Whether `s`'s motion lies on the line of the unit normal n (horizontal): its velocity along n, its
/// spin about ẑ × n, to within `tolerance` of their sizes; where it does, `s` is set exactly onto it.
[[nodiscard]] inline bool onto_line(BallOnCloth<double>& s, const Eigen::Vector3d& n, double tolerance) {
  const Eigen::Vector3d across{-n.y(), n.x(), 0};
  const double along = s.velocity.dot(n), side = s.velocity.dot(across);
  const double spin = s.angular_velocity.dot(across);
  const double other_spin = std::hypot(s.angular_velocity.dot(n), s.angular_velocity.z());
  const double scale = std::fabs(along) + s.radius * std::fabs(spin);
  if (!(std::fabs(side) <= tolerance * scale) || !(s.radius * other_spin <= tolerance * scale)) return false;
  s.velocity = along * n;
  s.angular_velocity = spin * across;
  return true;
}

/// How far from the line of the contact a pressed contact's motion may lie, relative to its size.
inline constexpr double line_tolerance = 1e-9;
/// How close to zero a slip or speed may be to count as zero, relative to the sizes it is formed from: a
/// few roundings of a piece's evolution.
inline constexpr double zero_tolerance = 1e-13;

/// A pressed piece's start: the ball's phase and what the piece adds to it.
struct PressedStart {
  Phase phase;        ///< the phase (motion, length, the centre's acceleration)
  PressedPiece piece;  ///< the spin's acceleration, what ends it, the partner
};

/// The pieces of balls `a` and `b`, touching along the unit normal `n` (from a to b), pressed together
/// from now on: both set onto the line of n (onto_line) with their speeds along n made one (momentum
/// kept), and each given the pair's piece (pair_piece), a's partner b and b's a. Empty, and the balls
/// unchanged, where their motion is off the line or no pressing piece follows.
[[nodiscard]] inline std::optional<std::array<PressedStart, 2>> pressed_pair(BallOnCloth<double>& a,
                                                                             BallOnCloth<double>& b,
                                                                             std::size_t a_index,
                                                                             std::size_t b_index,
                                                                             const Eigen::Vector3d& n,
                                                                             const PoolPhysics& physics) {
  BallOnCloth<double> pa = a, pb = b;
  if (!onto_line(pa, n, line_tolerance) || !onto_line(pb, n, line_tolerance)) return std::nullopt;
  const Eigen::Vector3d across{-n.y(), n.x(), 0};
  const double R = a.radius;
  double v = 0.5 * (pa.velocity.dot(n) + pb.velocity.dot(n));
  const std::array<double, 2> spin{R * pa.angular_velocity.dot(across), R * pb.angular_velocity.dot(across)};
  if (std::fabs(v) <= zero_tolerance * std::max(std::fabs(spin[0]), std::fabs(spin[1]))) v = 0;
  const auto zero_within = [](double x, double scale) { return std::fabs(x) <= zero_tolerance * scale ? 0.0 : x; };
  const std::array<double, 2> u{zero_within(v - spin[0], std::fabs(v) + std::fabs(spin[0])),
                                zero_within(v - spin[1], std::fabs(v) + std::fabs(spin[1]))};
  const double sigma = zero_within(spin[0] + spin[1], std::fabs(spin[0]) + std::fabs(spin[1]));
  const std::optional<PairPiece> piece = pair_piece(v, u, sigma, physics);
  if (!piece) return std::nullopt;
  pa.velocity = v * n;
  pb.velocity = v * n;
  a = pa;
  b = pb;
  const auto start = [&](int k) {
    PressedStart out;
    out.phase.motion = piece->rolling[k] ? Motion::rolling : Motion::sliding;
    out.phase.duration = piece->duration;
    out.phase.moving = true;
    out.phase.pressed = Pressed::ball;
    out.phase.acceleration = piece->acceleration * Eigen::Vector2d(n.x(), n.y());
    out.piece.partner = k == 0 ? b_index : a_index;
    out.piece.ending = piece->ending;
    out.piece.first = k == 0;
    out.piece.spin_acceleration = (piece->spin_rate[k] / R) * across;
    return out;
  };
  return std::array<PressedStart, 2>{start(0), start(1)};
}

/// The piece of ball `a`, touching straight cushion `cushion` whose unit normal `normal` points from the
/// ball into it, pressed there from now on: its motion set onto the line of the normal, at rest, its spin
/// running down (cushion_piece). Empty, and the ball unchanged, where its motion is off the line or its
/// spin does not press it.
[[nodiscard]] inline std::optional<PressedStart> pressed_on_cushion(BallOnCloth<double>& a, std::size_t cushion,
                                                                    const Eigen::Vector3d& normal,
                                                                    const PoolTable& table,
                                                                    const PoolPhysics& physics) {
  BallOnCloth<double> pa = a;
  if (!onto_line(pa, normal, line_tolerance)) return std::nullopt;
  const Eigen::Vector3d across{-normal.y(), normal.x(), 0};
  const auto [sin_nose, cos_nose] = billiards::detail::nose_angle(table.nose_height, a.radius);
  const std::optional<CushionPiece> piece =
      cushion_piece(a.radius * pa.angular_velocity.dot(across), sin_nose, cos_nose, physics);
  if (!piece) return std::nullopt;
  pa.velocity.setZero();
  a = pa;
  PressedStart out;
  out.phase.motion = Motion::sliding;
  out.phase.duration = piece->duration;
  out.phase.pressed = Pressed::cushion;
  out.piece.partner = cushion;
  out.piece.ending = PressedEnd::spin;
  out.piece.spin_acceleration = (piece->spin_rate / a.radius) * across;
  return out;
}

}  // namespace billiards::simulation::shot
