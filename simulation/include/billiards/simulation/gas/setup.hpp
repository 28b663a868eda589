/// \file
/// The hard-sphere gas's setup and what it reports: the lattice start's options and the equations of
/// state (namespace gas), the caller's configuration (GasSetup) and its validation, a collision as a
/// callback sees it, a span's measurements. The engine is in gas.hpp.
#pragma once

#include <billiards/simulation/core/ball.hpp>
#include <billiards/simulation/core/errors.hpp>
#include <billiards/simulation/core/invariants.hpp>

#include <billiards/checked.hpp>
#include <billiards/collision.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace billiards::simulation {

/// How a Gas finds the pairs it predicts (see the file's description).
enum class GasMethod {
  automatic,        ///< neighbour lists for unequal balls or a dense gas, cells for a dilute gas of equal balls
  cells,            ///< cells and their crossings (equal balls only)
  neighbour_lists,  ///< neighbour lists and their rebuilds
};

/// Everything about the gas that is not the engine: the lattice start and its options, the
/// measurement of the equation of state, the equations of state themselves.
namespace gas {

/// A lattice start and a measurement of its equation of state (the command line of billiards-gas),
/// in units of σ = m = kT = 1.
struct Options {
  int dimension = 3;                  ///< 2 (disks) or 3 (spheres)
  std::size_t balls = 1000;           ///< N
  double packing_fraction = 0.3;      ///< η: π ρ σ²/4 in 2-D, π ρ σ³/6 in 3-D
  std::uint64_t events = 100000;      ///< collisions measured
  std::uint64_t equilibrate = 10000;  ///< collisions run first, not measured
  std::uint64_t seed = 1;             ///< the seed of the random velocities
  /// Stop (throw EventLimitReached) after this many events in a row without a collision; 0: 10^6 + 100 N.
  std::uint64_t max_events_without_collision = 0;
  GasMethod method = GasMethod::automatic;  ///< the engine (see gas.hpp)
  int blocks = 10;  ///< blocks the measured collisions are cut into (at least 1; at most one a collision)
  /// Simulation time between snapshots over the measured span (gas::measure's callback); 0: none.
  double snapshot_interval = 0;
};

/// One block of a measured run: a row of its time series.
struct Block {
  double time = 0;                   ///< the block's end, in the gas's time from the measured span's start
  std::uint64_t collisions = 0;      ///< collisions in the block
  double compressibility_factor = 1; ///< Z = PV/(N kT) from the block's collision virial
  double pressure = 0;               ///< P = Z ρ kT, ρ = N/V, kT at the block's start
  double temperature = 0;            ///< kT at the block's end
  /// The mean of |r(t) − r(0)|² over the balls at the block's end, r their unwrapped positions and 0
  /// the measured span's start.
  double mean_squared_displacement = 0;
  double collision_rate = 0;  ///< collisions a ball a unit of time in the block, 2 C/(N t)
};

/// What gas::measure measured (units σ = m = kT = 1).
struct Result {
  int dimension = 0;                        ///< 2 or 3
  std::size_t balls = 0;                    ///< N
  double packing_fraction = 0;              ///< η
  std::uint64_t collisions = 0;             ///< over the measured span
  std::uint64_t cell_crossings = 0;         ///< over the measured span (the cell engine's own events)
  std::uint64_t list_rebuilds = 0;          ///< over the measured span (the neighbour-list engine's own events)
  double time = 0;                          ///< the measured span, in simulation time
  double compressibility_factor = 0;        ///< Z = PV/(N kT) from the collision virial
  double compressibility_factor_error = 0;  ///< its standard error over the blocks
  double pressure = 0;                      ///< P = Z ρ kT
  double pressure_error = 0;                ///< its standard error over the blocks
  /// Z from the collision rate, 1 + Σ σ_ij √(2π μ_ij kT)/(d N kT t) (1 + σ √(π m/kT)/(2 d τ) for equal
  /// balls).
  double compressibility_factor_from_collision_rate = 0;
  double compressibility_factor_from_collision_rate_error = 0;  ///< its standard error over the blocks
  /// Z of the equation of state for the gas's balls (see gas::equation_of_state); NaN where there is
  /// none (disks of unequal radii).
  double equation_of_state = 0;
  double mean_free_time = 0;                                    ///< τ = t N/(2 C)
  double temperature = 0;                                       ///< kT at the end, Σ m v²/(d N)
  double largest_temperature_change = 0;  ///< |kT − kT0|/kT0, the largest over the blocks' ends
  double momentum = 0;                    ///< |Σ m v| at the end
  double largest_overlap = 0;             ///< in diameters, over every collision
  /// In diameters, over every collision: how far apart beyond touching the centres were (a collision
  /// taken when it is not due, from a stale prediction, shows here).
  double largest_gap = 0;
  double events_per_second = 0;  ///< collisions per second of wall time over the measured span
  std::vector<Block> blocks;     ///< the time series, block by block
};

/// The packing fraction of close packing: π/(2√3) for disks, π/(3√2) for spheres.
inline double close_packing(int dimension) {
  return dimension == 2 ? std::numbers::pi / (2 * std::sqrt(3.0)) : std::numbers::pi / (3 * std::sqrt(2.0));
}

/// The volume of one ball of diameter 1: π/4 (a disk's area) or π/6.
inline double ball_volume(int dimension) {
  return dimension == 2 ? std::numbers::pi / 4 : std::numbers::pi / 6;
}

/// Henderson's equation of state for hard disks, (1 + η²/8)/(1 − η)².
inline double henderson(double eta) { return (1 + eta * eta / 8) / ((1 - eta) * (1 - eta)); }

/// Carnahan and Starling's for hard spheres, (1 + η + η² − η³)/(1 − η)³.
inline double carnahan_starling(double eta) {
  return (1 + eta + eta * eta - eta * eta * eta) / std::pow(1 - eta, 3);
}

/// Boublík's and Mansoori, Carnahan, Starling and Leland's (BMCSL) for a mixture of hard spheres of
/// `diameters` (one a ball) in a volume `volume`: with ξ_k = (π/6) (N/V) ⟨σ^k⟩,
/// Z = 1/(1 − ξ3) + 3 ξ1 ξ2/(ξ0 (1 − ξ3)²) + (3 − ξ3) ξ2³/(ξ0 (1 − ξ3)³); Carnahan–Starling's for equal
/// spheres.
inline double boublik_mansoori(const std::vector<double>& diameters, double volume) {
  double xi[4] = {0, 0, 0, 0};
  for (double sigma : diameters) {
    double power = 1;
    for (double& x : xi) x += power, power *= sigma;
  }
  for (double& x : xi) x *= std::numbers::pi / 6 / volume;
  const double free = 1 - xi[3];
  return 1 / free + 3 * xi[1] * xi[2] / (xi[0] * free * free) +
         (3 - xi[3]) * xi[2] * xi[2] * xi[2] / (xi[0] * free * free * free);
}

/// The equation of state of the dimension: Henderson's (2-D) or Carnahan–Starling (3-D).
inline double equation_of_state(int dimension, double eta) {
  return dimension == 2 ? henderson(eta) : carnahan_starling(eta);
}

/// The box's side for N balls at packing fraction η.
inline double box_side(int dimension, std::size_t balls, double eta) {
  return std::pow(static_cast<double>(balls) * ball_volume(dimension) / eta, 1.0 / dimension);
}

/// The widest box, in diameters, whose positions round by at most 1e-9 of a diameter: 16 ε side ≤ 1e-9,
/// about 2.8e5 (the table example's rule for its radius). The runs hold overlaps and gaps below 1e-9.
inline double largest_box_side() { return overlap_tolerance / (16 * std::numeric_limits<double>::epsilon()); }

/// The smallest packing fraction with a box no wider than largest_box_side(): N v/side^D.
inline double smallest_packing_fraction(int dimension, std::size_t balls) {
  return static_cast<double>(balls) * ball_volume(dimension) / std::pow(largest_box_side(), dimension);
}

/// Cells per side of the cell grid: one a diameter (the box's side rounded down), but in a dilute gas
/// at most as many as keep the grid within max(2^24, 4 N) cells (and 2^31), so that its memory follows
/// the balls, not the box (1000 disks at η = 1e-8, a box of 2.8e5 diameters, once asked for 7.9e10 cells and
/// aborted). Wider cells only hold more balls each; the events are the same.
inline int grid_cells_per_side(int dimension, std::size_t balls, double side) {
  const double most =
      std::min(std::ldexp(1.0, 31), std::max(std::ldexp(1.0, 24), 4.0 * static_cast<double>(balls)));
  const double widest = std::floor(side);  // at most largest_box_side() (validate), so an int
  const auto cells = [dimension](double k) { return std::pow(k, dimension); };  // exact: k^D < 2^53
  double per_side = std::min(widest, std::floor(std::pow(most, 1.0 / dimension)));
  // pow's root may miss by a bit either way: the largest k with k^D ≤ most, within the box.
  while (per_side + 1 <= widest && cells(per_side + 1) <= most) ++per_side;
  while (per_side > 3 && cells(per_side) > most) --per_side;
  return static_cast<int>(per_side);
}

/// Lattice sites per side of the start: a square lattice of n² ≥ N sites, or an FCC lattice of 4 k³.
inline std::size_t lattice_cells(int dimension, std::size_t balls) {
  std::size_t n = 1;
  while ((dimension == 2 ? n * n : 4 * n * n * n) < balls) ++n;
  return n;
}

/// Throws std::invalid_argument, naming the argument, its value and what was expected, where the run
/// cannot be made: a dimension other than 2 or 3, fewer than 2 balls, η not in (0, close packing), a
/// box narrower than 3 diameters (too few balls for the cell grid's neighbours to be distinct), or a
/// lattice start whose nearest neighbours would overlap.
inline void validate(const Options& o) {
  if (o.dimension != 2 && o.dimension != 3) {
    throw std::invalid_argument("--dimension is " + std::to_string(o.dimension) + ", expected 2 or 3");
  }
  if (o.balls < 2) {
    throw std::invalid_argument("--balls is " + std::to_string(o.balls) + ", expected at least 2");
  }
  if (o.balls > (std::size_t(1) << 31)) {
    throw std::invalid_argument("--balls is " + std::to_string(o.balls) + ", expected at most 2^31");
  }
  const double packing = close_packing(o.dimension);
  if (!(o.packing_fraction > 0 && o.packing_fraction < packing)) {
    throw std::invalid_argument("--packing-fraction is " + std::to_string(o.packing_fraction) +
                                ", expected more than 0 and less than close packing, " +
                                std::to_string(packing) + " in " + std::to_string(o.dimension) + "-D");
  }
  if (const double smallest = smallest_packing_fraction(o.dimension, o.balls);
      o.packing_fraction < smallest) {
    std::ostringstream text;
    text << "--packing-fraction is " << o.packing_fraction << ", expected at least " << smallest << " for "
         << o.balls << " balls in " << o.dimension << "-D: a box wider than " << largest_box_side()
         << " diameters rounds positions by more than 1e-9 of a diameter";
    throw std::invalid_argument(text.str());
  }
  const double side = box_side(o.dimension, o.balls, o.packing_fraction);
  if (side < 3) {
    const double needed =
        std::ceil(std::pow(3.0, o.dimension) * o.packing_fraction / ball_volume(o.dimension));
    throw std::invalid_argument("--balls " + std::to_string(o.balls) +
                                " is too few for the box: at packing " + "fraction " +
                                std::to_string(o.packing_fraction) + " its side is " + std::to_string(side) +
                                " diameters, expected at least 3 (at least " +
                                std::to_string(static_cast<long long>(needed)) + " balls)");
  }
  const double spacing = side / static_cast<double>(lattice_cells(o.dimension, o.balls));
  const double nearest = o.dimension == 2 ? spacing : spacing / std::sqrt(2.0);
  if (nearest < 1 + 1e-9) {
    throw std::invalid_argument("--packing-fraction " + std::to_string(o.packing_fraction) +
                                " is too dense for a " + (o.dimension == 2 ? "square" : "FCC") +
                                " lattice start of " + std::to_string(o.balls) + " balls: neighbours " +
                                std::to_string(nearest) + " diameters apart, expected at least 1");
  }
}

}  // namespace gas

/// A gas of N balls in a periodic box: the caller's configuration, or gas::lattice's. The balls are
/// equal (every one of radius `radius` and mass `mass`) unless `radii` or `masses` give each its own.
template <int D>
struct GasSetup {
  double side = 0;             ///< the box's side: a square (2-D) or a cube (3-D), periodic along every axis
  double radius = 0.5;         ///< every ball's radius where `radii` is empty (σ = 2 radius, the diameter)
  double mass = 1;             ///< every ball's mass where `masses` is empty
  std::vector<Ball<D>> balls;  ///< centres (anywhere: taken into [0, side) along each axis) and velocities
  std::vector<double> radii;   ///< each ball's radius, in the order of `balls`; empty: every one `radius`
  std::vector<double> masses;  ///< each ball's mass, in the order of `balls`; empty: every one `mass`

  /// Ball i's radius.
  double radius_of(std::size_t i) const { return radii.empty() ? radius : radii[i]; }
  /// Ball i's mass.
  double mass_of(std::size_t i) const { return masses.empty() ? mass : masses[i]; }
  /// Whether every ball has the same radius and the same mass.
  bool equal_balls() const {
    for (std::size_t i = 1; i < balls.size(); ++i) {
      if (radius_of(i) != radius_of(0) || mass_of(i) != mass_of(0)) return false;
    }
    return true;
  }
};

/// An event of the gas, as Gas reports it: a collision of two balls.
struct GasEvent {
  /// What happened: the gas's only reported kind, two balls meeting.
  enum class Kind { ball };
  double time = 0;         ///< the gas's time of the collision
  Kind kind = Kind::ball;  ///< what the ball met: another ball
  std::size_t first = 0;   ///< a ball (its index in the setup)
  std::size_t second = 0;  ///< the other ball
};

/// The name of a gas event's kind: "ball".
inline const char* kind_name(GasEvent::Kind) noexcept { return "ball"; }

/// What a Gas measured over a span: from its start (or Gas::reset_measurements) to now.
struct GasMeasurement {
  double time = 0;                  ///< the span's length, in the gas's time
  std::uint64_t collisions = 0;     ///< collisions resolved in it
  std::uint64_t cell_crossings = 0;  ///< cell crossings in it (the cell engine's own events)
  std::uint64_t list_rebuilds = 0;   ///< neighbour lists rebuilt in it (the neighbour-list engine's own events)
  double virial = 0;                ///< Σ r_ij·Δp_i over its collisions
  double temperature = 0;           ///< kT at the span's start, Σ m v²/(d N)
  /// Z = PV/(N kT) from the collision virial, 1 + Σ r_ij·Δp_i/(d N kT t); 1 for an empty span.
  double compressibility_factor = 1;
  /// Z from the collision rate alone, 1 + Σ σ_ij √(2π μ_ij kT)/(d N kT t) over the span's collisions
  /// (σ_ij = r_i + r_j, μ_ij the pair's reduced mass): in equilibrium the mean r_ij·Δp_i of a pair's
  /// collisions is σ_ij √(2π μ_ij kT). For equal balls, 1 + σ √(π m/kT)/(2 d τ). 1 without collisions.
  double compressibility_factor_from_collision_rate = 1;
  double mean_free_time = 0;  ///< τ = t N/(2 C); +∞ without collisions
};

/// Throws std::invalid_argument, naming the argument, its value and what was expected, where `setup` is
/// not a gas the engine can run: fewer than 2 balls or more than 2^31, a radius, mass or side that is not
/// positive and finite, `radii` or `masses` neither empty nor one a ball, a box narrower than 3 of the
/// largest diameters or wider than gas::largest_box_side() of the smallest, a position or velocity that
/// is not finite, a velocity component beyond billiards::component_limit, or two balls closer than the
/// sum of their radii (less 1e-9 of it) on their nearest images.
template <int D>
void validate(const GasSetup<D>& setup);

/// Validates a gas's setup; see the declaration above.
template <int D>
void validate(const GasSetup<D>& setup) {
  const auto fail = [](const std::string& text) { throw std::invalid_argument("gas setup: " + text); };
  const auto positive = [&](const std::string& name, double value) {
    if (!(value > 0) || !std::isfinite(value)) {
      std::ostringstream text;
      text << name << " is " << value << ", expected a positive finite number";
      fail(text.str());
    }
  };
  const std::size_t n = setup.balls.size();
  if (n < 2 || n > (std::size_t{1} << 31)) {
    fail("balls holds " + std::to_string(n) + " balls, expected from 2 to 2^31");
  }
  positive("radius", setup.radius);
  positive("mass", setup.mass);
  positive("side", setup.side);
  const auto one_a_ball = [&](const char* name, const std::vector<double>& values) {
    if (!values.empty() && values.size() != n) {
      fail(std::string(name) + " holds " + std::to_string(values.size()) + " values, expected none or " +
           std::to_string(n) + " (one a ball)");
    }
    for (std::size_t i = 0; i < values.size(); ++i) positive(std::string(name) + "[" + std::to_string(i) + "]", values[i]);
  };
  one_a_ball("radii", setup.radii);
  one_a_ball("masses", setup.masses);
  double largest = 0, smallest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    largest = std::max(largest, setup.radius_of(i));
    smallest = std::min(smallest, setup.radius_of(i));
  }
  const double diameters = setup.side / (2 * largest), smallest_diameters = setup.side / (2 * smallest);
  if (!(diameters >= 3) || !(smallest_diameters <= gas::largest_box_side())) {
    std::ostringstream text;
    text << "side is " << setup.side << ", " << diameters << " diameters";
    if (largest != smallest) text << " of the largest ball and " << smallest_diameters << " of the smallest";
    text << ", expected from 3 diameters (of the largest ball: the cell grid's neighbours distinct) to "
         << gas::largest_box_side()
         << " (of the smallest: wider boxes round positions by more than 1e-9 of a diameter)";
    fail(text.str());
  }
  const double limit = billiards::component_limit<double>();
  for (std::size_t i = 0; i < n; ++i) {
    const Ball<D>& ball = setup.balls[i];
    std::ostringstream text;
    if (!ball.position.allFinite()) {
      text << "balls[" << i << "].position is not finite, expected finite coordinates";
      fail(text.str());
    }
    if (!ball.velocity.allFinite() || ball.velocity.cwiseAbs().maxCoeff() > limit) {
      text << "balls[" << i << "].velocity has a component of " << ball.velocity.cwiseAbs().maxCoeff()
           << ", expected finite components of magnitude at most " << limit
           << " (billiards::component_limit)";
      fail(text.str());
    }
  }
}

}  // namespace billiards::simulation
