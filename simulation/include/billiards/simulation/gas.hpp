/// \file
/// A hard-sphere gas, event-driven, on billiards::runtime: N equal balls of diameter σ and mass m in a
/// periodic square (2-D) or cubic (3-D) box, from a configuration of the caller's (GasSetup) or a square
/// or FCC lattice with random velocities (gas::lattice), run collision by collision with no time step.
///
/// Each ball keeps its position at its own last update (positions are brought forward only when a
/// ball takes part in an event). The box is divided into a grid of cells at least one diameter wide,
/// numbered tile by tile (tiles of 4^D cells, so that neighbouring cells lie near one another in
/// memory); each ball's next event is the earlier of its next cell crossing and its earliest predicted
/// collision with a ball in its own or a neighbouring cell (billiards::time_of_impact on the nearest
/// periodic image), so a prediction costs the same whatever N. After a cell crossing only the cells that
/// have just come around the ball are searched, the earliest collision found before kept beside them
/// (3^(D−1) cells, not 3^D). The balls' next events sit in an event calendar (event_calendar.hpp: a
/// calendar queue, O(1) a step on average). Collisions are numbered; a collision event records the
/// number of the last collision before its prediction: when the partner has collided since, the event
/// is stale and the ball is predicted again. Collisions are resolved by
/// billiards::collide_if_approaching on the nearest images.
///
/// Measured over a span (Gas::reset_measurements to now): the collision virial Σ r_ij·Δp_i (r_ij =
/// r_i − r_j at contact, Δp_i ball i's change of momentum), which gives Z = PV/(N kT) = 1 + Σ r_ij·Δp_i/(d
/// N kT t), and the collision count, which gives the mean free time τ = t N/(2 C) and, through the
/// identity Z − 1 = σ √(π m/kT)/(2 d τ), a second estimate of Z from the collision rate alone.
#pragma once

#include <billiards/simulation/detail/large_array.hpp>
#include <billiards/simulation/detail/prefetch.hpp>
#include <billiards/simulation/event_calendar.hpp>
#include <billiards/simulation/table_setup.hpp>

#include <billiards/collision.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace billiards::simulation {

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
  /// Stop (throw NoCollisions) after this many events in a row without a collision; 0: 10^6 + 100 N.
  std::uint64_t max_events_without_collision = 0;
};

/// What gas::measure measured (units σ = m = kT = 1).
struct Result {
  int dimension = 0;                        ///< 2 or 3
  std::size_t balls = 0;                    ///< N
  double packing_fraction = 0;              ///< η
  std::uint64_t collisions = 0;             ///< over the measured span
  std::uint64_t cell_crossings = 0;         ///< over the measured span
  double time = 0;                          ///< the measured span, in simulation time
  double compressibility_factor = 0;        ///< Z = PV/(N kT) from the collision virial
  double compressibility_factor_error = 0;  ///< its standard error over ten blocks
  /// Z from the collision rate, 1 + σ √(π m/kT)/(2 d τ).
  double compressibility_factor_from_collision_rate = 0;
  double compressibility_factor_from_collision_rate_error = 0;  ///< its standard error over ten blocks
  double mean_free_time = 0;                                    ///< τ = t N/(2 C)
  double temperature = 0;                                       ///< kT at the end, Σ m v²/(d N)
  double largest_temperature_change = 0;  ///< |kT − kT0|/kT0, the largest over the blocks' ends
  double momentum = 0;                    ///< |Σ m v| at the end
  double largest_overlap = 0;             ///< in diameters, over every collision
  /// In diameters, over every collision: how far apart beyond touching the centres were (a collision
  /// taken when it is not due, from a stale prediction, shows here).
  double largest_gap = 0;
  double events_per_second = 0;  ///< collisions per second of wall time over the measured span
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
inline double largest_box_side() { return 1e-9 / (16 * std::numeric_limits<double>::epsilon()); }

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

/// A gas of N equal balls in a periodic box: the caller's configuration, or gas::lattice's.
template <int D>
struct GasSetup {
  double side = 0;             ///< the box's side: a square (2-D) or a cube (3-D), periodic along every axis
  double radius = 0.5;         ///< every ball's radius (σ = 2 radius, the diameter)
  double mass = 1;             ///< every ball's mass
  std::vector<Ball<D>> balls;  ///< centres (anywhere: taken into [0, side) along each axis) and velocities
};

/// One collision of the gas, as Gas reports it to a callback.
struct GasCollision {
  double time = 0;         ///< the gas's time of the collision
  std::size_t first = 0;   ///< a ball (its index in the setup)
  std::size_t second = 0;  ///< the other ball
};

/// Thrown when a run goes on without collisions (the balls' paths never meet).
struct NoCollisions : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// What a Gas measured over a span: from its start (or Gas::reset_measurements) to now.
struct GasMeasurement {
  double time = 0;                   ///< the span's length, in the gas's time
  std::uint64_t collisions = 0;      ///< collisions resolved in it
  std::uint64_t cell_crossings = 0;  ///< cell crossings in it (the engine's own events)
  double virial = 0;                 ///< Σ r_ij·Δp_i over its collisions
  double temperature = 0;            ///< kT at the span's start, Σ m v²/(d N)
  /// Z = PV/(N kT) from the collision virial, 1 + Σ r_ij·Δp_i/(d N kT t); 1 for an empty span.
  double compressibility_factor = 1;
  /// Z from the collision rate, 1 + σ √(π m/kT)/(2 d τ); 1 without collisions.
  double compressibility_factor_from_collision_rate = 1;
  double mean_free_time = 0;  ///< τ = t N/(2 C); +∞ without collisions
};

/// Throws std::invalid_argument, naming the argument, its value and what was expected, where `setup` is
/// not a gas the engine can run: fewer than 2 balls or more than 2^31, a radius, mass or side that is not
/// positive and finite, a box narrower than 3 diameters or wider than gas::largest_box_side() diameters,
/// a position or velocity that is not finite, a velocity component beyond billiards::component_limit, or
/// two balls closer than a diameter (less 1e-9 of one) on their nearest images.
template <int D>
void validate(const GasSetup<D>& setup);

/// A D-dimensional hard-sphere gas: built from a GasSetup, run for a number of collisions
/// (run_collisions) or until a time (run_until), each collision reported to an optional callback.
template <int D>
class Gas {
 public:
  /// A position or a velocity.
  using Vector = Eigen::Matrix<double, D, 1>;

  /// Validates `setup` (see validate(const GasSetup<D>&)) and predicts every ball's first event. A run
  /// stops with NoCollisions after `max_events_without_collision` events in a row without a collision
  /// (0: 10^6 + 100 N), so that balls whose paths never meet cannot run forever.
  explicit Gas(const GasSetup<D>& setup, std::uint64_t max_events_without_collision = 0)
      : radius_(setup.radius), diameter_(2 * setup.radius), mass_(setup.mass), side_(setup.side) {
    validate(setup);
    const std::size_t n = setup.balls.size();
    quiet_limit_ = max_events_without_collision != 0 ? max_events_without_collision
                                                     : 1000000 + 100 * static_cast<std::uint64_t>(n);
    // Cells at least one diameter wide.
    cells_per_side_ = gas::grid_cells_per_side(D, n, side_ / diameter_);
    cell_width_ = side_ / cells_per_side_;
    lay_out_cells();
    ball_.resize(n);
    own_.resize(n);
    identity_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      ball_[i].position = setup.balls[i].position;
      ball_[i].velocity = setup.balls[i].velocity;
      identity_[i] = static_cast<std::uint32_t>(i);
      for (int k = 0; k < D; ++k) {
        double& x = ball_[i].position[k];
        x = into_box(x);
        own_[i].coordinates[k] = std::min(cells_per_side_ - 1, static_cast<int>(x / cell_width_));
      }
      own_[i].cell = static_cast<std::uint32_t>(cell_index(own_[i].coordinates));
      insert(i);
    }
    check_no_overlap();
    for (std::size_t i = 0; i < n; ++i) predict_in_full(i);
    calendar_.defer_filings(n >= look_ahead_from);
    refile();
    reset_measurements();
  }

  /// Runs `count` more collisions, calling `on_collision(const GasCollision&)` after each, and returns
  /// the number run (`count`). Throws NoCollisions after too many events in a row without a collision
  /// (see the constructor).
  template <typename OnCollision>
  std::uint64_t run_collisions(std::uint64_t count, OnCollision&& on_collision) {
    return advance(count, infinity, on_collision);
  }
  /// Runs `count` more collisions; see the overload with a callback.
  std::uint64_t run_collisions(std::uint64_t count) { return advance(count, infinity, ignore_collision); }

  /// Runs every collision up to the gas's time `until`, calling `on_collision(const GasCollision&)`
  /// after each, and makes `until` the time now; returns the number of collisions run. Throws
  /// std::invalid_argument when `until` is NaN, infinite or earlier than time().
  template <typename OnCollision>
  std::uint64_t run_until(double until, OnCollision&& on_collision) {
    if (!(until >= now_) || !std::isfinite(until)) {
      std::ostringstream text;
      text << "billiards::simulation::Gas::run_until: until is " << until
           << ", expected a finite time at or after " << now_ << " (the gas's time now)";
      throw std::invalid_argument(text.str());
    }
    const std::uint64_t done = advance(std::numeric_limits<std::uint64_t>::max(), until, on_collision);
    now_ = until;
    return done;
  }
  /// Runs every collision up to the gas's time `until`; see the overload with a callback.
  std::uint64_t run_until(double until) { return run_until(until, ignore_collision); }

  /// Starts a new span of measurement at the time now (see measured()).
  void reset_measurements() {
    span_start_ = now_;
    span_collisions_ = collisions_;
    span_crossings_ = crossings_;
    virial_ = 0;
    span_temperature_ = temperature();
  }

  /// What was measured from the construction, or the last reset_measurements(), to now.
  GasMeasurement measured() const {
    GasMeasurement m;
    const double n = static_cast<double>(ball_.size()), kT = span_temperature_;
    m.time = now_ - span_start_;
    m.collisions = collisions_ - span_collisions_;
    m.cell_crossings = crossings_ - span_crossings_;
    m.virial = mass_ * virial_;
    m.temperature = kT;
    if (m.time > 0 && kT > 0) m.compressibility_factor = 1 + m.virial / (D * n * kT * m.time);
    m.mean_free_time = m.collisions > 0 ? m.time * n / (2 * static_cast<double>(m.collisions))
                                        : std::numeric_limits<double>::infinity();
    if (m.collisions > 0 && kT > 0) {
      m.compressibility_factor_from_collision_rate =
          1 + diameter_ * std::sqrt(std::numbers::pi * mass_ / kT) / (2 * D * m.mean_free_time);
    }
    return m;
  }

  /// kT = Σ m v²/(d N), summed in long double.
  double temperature() const {
    long double sum = 0;
    for (const Ball& b : ball_) sum += static_cast<long double>(b.velocity.squaredNorm());
    return static_cast<double>(mass_ * sum / (D * static_cast<long double>(ball_.size())));
  }
  /// Σ m v, summed in long double.
  Vector momentum() const {
    Eigen::Matrix<long double, D, 1> sum = Eigen::Matrix<long double, D, 1>::Zero();
    for (const Ball& b : ball_) sum += b.velocity.template cast<long double>();
    return (static_cast<long double>(mass_) * sum).template cast<double>();
  }
  /// The number of balls, N.
  std::size_t size() const { return ball_.size(); }
  /// The box's side.
  double side() const { return side_; }
  /// Every ball's radius.
  double radius() const { return radius_; }
  /// Every ball's mass.
  double mass() const { return mass_; }
  /// The gas's time now (0 at the construction).
  double time() const { return now_; }
  /// Collisions resolved since the construction.
  std::uint64_t collisions() const { return collisions_; }
  /// Cell crossings since the construction (the engine's own events, not reported to callbacks).
  std::uint64_t cell_crossings() const { return crossings_; }
  /// The largest overlap at any collision since the construction, in diameters.
  double largest_overlap() const { return largest_overlap_; }
  /// How far beyond touching the centres were at any collision since the construction, in diameters
  /// (a collision taken when it is not due, from a stale prediction, would show here).
  double largest_gap() const { return largest_gap_; }
  /// The cells per side of the cell grid.
  int cells_per_side() const { return cells_per_side_; }

  /// Every ball's position now, in the setup's order, each coordinate in [0, side).
  std::vector<Vector> positions() const {
    std::vector<Vector> out(ball_.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
      Vector& p = out[identity_[i]];
      p = ball_[i].position + ball_[i].velocity * (now_ - ball_[i].updated);
      for (int k = 0; k < D; ++k) p[k] = into_box(p[k]);
    }
    return out;
  }
  /// Every ball's velocity, in the setup's order.
  std::vector<Vector> velocities() const {
    std::vector<Vector> out(ball_.size());
    for (std::size_t i = 0; i < out.size(); ++i) out[identity_[i]] = ball_[i].velocity;
    return out;
  }
  /// The state now as a setup (positions in [0, side)): a gas built from it runs on from here.
  GasSetup<D> setup() const {
    GasSetup<D> out{side_, radius_, mass_, std::vector<simulation::Ball<D>>(ball_.size())};
    const std::vector<Vector> p = positions(), v = velocities();
    for (std::size_t i = 0; i < p.size(); ++i) out.balls[i] = {p[i], v[i]};
    return out;
  }
  /// The displacement b − a to the nearest periodic image.
  Vector nearest_image(const Vector& a, const Vector& b) const {
    Vector p = b - a;
    for (int k = 0; k < D; ++k) {
      if (p[k] > side_ / 2) p[k] -= side_;
      if (p[k] < -side_ / 2) p[k] += side_;
    }
    return p;
  }

 private:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  using Cell = Eigen::Matrix<int, D, 1>;
  // The cells a prediction searches and their lists' first balls, asked of memory by gather() for the
  // search() that follows.
  struct Gathered {
    std::uint32_t first[D == 2 ? 9 : 27];
    int cells = 0;
  };

  static constexpr double infinity = std::numeric_limits<double>::infinity();

  // A coordinate taken into [0, side): fmod is exact, so a coordinate inside is kept bit for bit and
  // one far outside (−1.02e17 in a box of 5) lands inside too; −1e-20 + side rounds to side itself.
  double into_box(double x) const {
    x = std::fmod(x, side_);
    if (x < 0) x += side_;
    return x < side_ ? x : 0;
  }

  // A callback that does nothing: a run without one compiles to the loop it was before.
  static void ignore_collision(const GasCollision&) {}

  // No two balls closer than a diameter (less 1e-9 of one) on their nearest images: each ball against
  // the balls of the 3^D cells around its own, which hold every ball within a diameter of it.
  void check_no_overlap() const {
    const double closest = diameter_ * (1 - 1e-9);
    for (std::size_t i = 0; i < ball_.size(); ++i) {
      Gathered around;
      gather(own_[i].coordinates, all_axes, 0, around);
      for (int n = 0; n < around.cells; ++n) {
        for (std::uint32_t j = around.first[n]; j != none; j = ball_[j].next) {
          if (j <= i) continue;
          const double distance = nearest_image(ball_[i].position, ball_[j].position).norm();
          if (distance < closest) {
            std::ostringstream text;
            text << "balls " << i << " and " << j << " overlap: their centres are " << distance
                 << " apart on their nearest images, expected at least a diameter (" << diameter_ << ")";
            throw std::invalid_argument(text.str());
          }
        }
      }
    }
  }

  // The cells' numbering, in tiles of tile^D cells: tile after tile, the first axis fastest, and
  // within a tile the first axis fastest too. A ball's neighbourhood then spans few tiles, whose list
  // heads share cache lines and whose balls (renumbered by cell) lie near one another in memory.
  // The number is a sum of one term an axis, axis_offset_[k][c_k], so the cells around a ball come
  // from three terms an axis. Tiles at the far edges may be partial: their missing cells keep numbers
  // that no ball ever takes.
  void lay_out_cells() {
    const std::size_t per_side = static_cast<std::size_t>(cells_per_side_);
    const std::size_t tiles = (per_side + tile - 1) / tile;
    std::size_t tile_cells = 1, count = 1;
    for (int k = 0; k < D; ++k) tile_cells *= tile, count *= tiles * tile;
    if (count >= none) throw std::invalid_argument("Gas<D>: more cells than 32-bit numbers");
    std::size_t tile_stride = tile_cells, inner_stride = 1;
    for (int k = 0; k < D; ++k) {
      axis_offset_[k].resize(per_side);
      for (std::size_t c = 0; c < per_side; ++c)
        axis_offset_[k][c] = static_cast<std::uint32_t>(c / tile * tile_stride + c % tile * inner_stride);
      tile_stride *= tiles;
      inner_stride *= tile;
    }
    head_.assign(count, none);
  }

  // A cell coordinate at most two cells beyond the box, wrapped into it (validate() makes every box at
  // least three cells wide, so one turn is enough).
  std::size_t wrapped(int x) const {
    return static_cast<std::size_t>(x < 0                  ? x + cells_per_side_
                                    : x >= cells_per_side_ ? x - cells_per_side_
                                                           : x);
  }

  std::size_t cell_index(const Cell& c) const {
    std::size_t index = 0;
    for (int k = 0; k < D; ++k) index += axis_offset_[k][static_cast<std::size_t>(c[k])];
    return index;
  }
  void insert(std::size_t i) {
    const std::size_t c = own_[i].cell;
    ball_[i].previous = none;
    ball_[i].next = head_[c];
    if (head_[c] != none) ball_[head_[c]].previous = static_cast<std::uint32_t>(i);
    head_[c] = static_cast<std::uint32_t>(i);
  }
  void remove(std::size_t i) {
    if (ball_[i].previous != none)
      ball_[ball_[i].previous].next = ball_[i].next;
    else
      head_[own_[i].cell] = ball_[i].next;
    if (ball_[i].next != none) ball_[ball_[i].next].previous = ball_[i].previous;
  }

  void bring_to_now(std::size_t i) {
    ball_[i].position += ball_[i].velocity * (now_ - ball_[i].updated);
    ball_[i].updated = now_;
  }

  // Ball i's next event, predicted in full, and its place in the calendar.
  void predict(std::size_t i) {
    predict_in_full(i);
    calendar_.update(static_cast<std::uint32_t>(i), own_[i].event_time());
  }

  // Beyond the caches: asks memory for what filing ball i at its event time will read, so that the
  // calendar's miss overlaps the work before the filing instead of following it.
  void prefetch_filing(std::size_t i) {
    if (ball_.size() >= look_ahead_from)
      calendar_.prefetch_update(static_cast<std::uint32_t>(i), own_[i].event_time());
  }

  // Ball i's next crossing and its earliest collision with a ball of the 3^D cells around it, any
  // candidate it had forgotten; `gathered`, where given, holds the 3^D cells around it, gathered earlier.
  void predict_in_full(std::size_t i, const Gathered* gathered = nullptr) {
    predict_crossing(i);
    own_[i].collision_time = infinity;
    own_[i].partner = none;
    if (gathered != nullptr)
      search(i, *gathered);
    else
      predict_collisions(i, all_axes, 0);
  }

  // After ball i crossed into a new cell along `axis` by `step`: its next crossing, and collisions with
  // the balls of the cells that have just come around it (3^(D−1), not 3^D: the rest were around it
  // before). The earliest collision found before stays a candidate: its pair was predicted on the
  // same paths, and a pair first around it now lies in the new cells. (A ball of the new cells that
  // predicted ball i on its own paths since keeps that event itself.)
  // `gathered`, where given, holds those cells, gathered earlier.
  void predict_after_crossing(std::size_t i, int axis, int step, const Gathered* gathered = nullptr) {
    predict_crossing(i);
    prefetch_filing(i);  // its time, unless the new cells hold an earlier collision
    if (gathered != nullptr)
      search(i, *gathered);
    else
      predict_collisions(i, axis, step);
    calendar_.update(static_cast<std::uint32_t>(i), own_[i].event_time());
  }

  // Ball i's next cell crossing: the earliest time it reaches a face of its cell.
  void predict_crossing(std::size_t i) {
    bring_to_now(i);
    Own& own = own_[i];
    own.crossing_time = infinity;
    for (int k = 0; k < D; ++k) {
      const double v = ball_[i].velocity[k];
      if (v == 0) continue;
      const double bound = (own.coordinates[k] + (v > 0 ? 1 : 0)) * cell_width_;
      const double t = now_ + std::max(0.0, (bound - ball_[i].position[k]) / v);
      if (t < own.crossing_time) {
        own.crossing_time = t;
        own.axis = static_cast<std::int8_t>(k);
        own.step = static_cast<std::int8_t>(v > 0 ? 1 : -1);
      }
    }
  }

  static constexpr int all_axes = -1;

  // Ball i's earliest collision with a ball of the cells around its own (every one of the 3^D when
  // `axis` is all_axes, else those one step beyond it along `axis`), kept where earlier than the
  // candidate it has. Ball i is at now.
  void predict_collisions(std::size_t i, int axis, int step) {
    Gathered gathered;
    gather(own_[i].coordinates, axis, step, gathered);
    search(i, gathered);
  }

  // The cells around `centre` (every one of the 3^D when `axis` is all_axes, else those one step beyond
  // it along `axis`) and their lists' first balls. The cells, their heads and their first balls are
  // asked of memory all at once before any is read: beyond the caches the misses then overlap instead
  // of following one another.
  void gather(const Cell& centre, int axis, int step, Gathered& gathered) const {
    constexpr int around = D == 2 ? 9 : 27;
    std::uint32_t* first = gathered.first;
    int cells = 0;
    {
      // Along each axis the cell coordinates to search, wrapped around the box, as the axis's terms
      // of cell_index: three (one step either side and the ball's own), or the one beyond.
      std::size_t part[D][3];
      int count[D];
      for (int k = 0; k < D; ++k) {
        const int c = centre[k];
        const std::uint32_t* offset = axis_offset_[k].data();
        if (k == axis) {
          part[k][0] = offset[wrapped(c + step)];
          count[k] = 1;
        } else {
          part[k][0] = offset[wrapped(c - 1)];
          part[k][1] = offset[c];
          part[k][2] = offset[wrapped(c + 1)];
          count[k] = 3;
        }
      }
      std::size_t cell[around];
      const auto add = [&](std::size_t index) {
        detail::prefetch(&head_[index]);
        cell[cells++] = index;
      };
      // The first axis fastest (cell_index's order within a tile; where ties between equal times are
      // broken, always the same way).
      if constexpr (D == 2) {
        for (int b = 0; b < count[1]; ++b)
          for (int a = 0; a < count[0]; ++a) add(part[1][b] + part[0][a]);
      } else {
        for (int c = 0; c < count[2]; ++c)
          for (int b = 0; b < count[1]; ++b)
            for (int a = 0; a < count[0]; ++a) add(part[2][c] + part[1][b] + part[0][a]);
      }
      for (int n = 0; n < cells; ++n) {
        first[n] = head_[cell[n]];
        if (first[n] != none) detail::prefetch(&ball_[first[n]]);
      }
    }
    gathered.cells = cells;
  }

  // Ball i's earliest collision with a ball of the gathered cells, kept where earlier than the candidate
  // it has. Ball i is at now; the cells' lists are as they were gathered.
  void search(std::size_t i, const Gathered& gathered) {
    const std::uint32_t* first = gathered.first;
    const int cells = gathered.cells;
    Own& own = own_[i];
    const double before = own.collision_time;
    for (int n = 0; n < cells; ++n) {
      for (std::uint32_t j = first[n]; j != none; j = ball_[j].next) {
        if (j == i) continue;
        const Vector other = ball_[j].position + ball_[j].velocity * (now_ - ball_[j].updated);
        const Vector p = nearest_image(ball_[i].position, other);
        // A pair moving apart never meets (time_of_impact would say +∞): skip the call.
        if (p.dot(ball_[j].velocity - ball_[i].velocity) >= 0) continue;
        const double t = billiards::time_of_impact(Vector::Zero().eval(), ball_[i].velocity, p,
                                                   ball_[j].velocity, diameter_);
        if (now_ + t < own.collision_time) {
          own.collision_time = now_ + t;
          own.partner = j;
        }
      }
    }
    if (own.collision_time < before) own.predicted_after = collision_number_;
  }

  // Asks memory for what the next events will read, so that their misses overlap this event's work
  // instead of following it (the calendar's look ahead): the records of the balls two buckets ahead,
  // and for those one bucket ahead, whose records were asked for before, their partners' records and
  // (2-D) the list heads of the cells their predictions will search and, for a crossing, the records
  // its removal from its cell's list writes.
  void prefetch_next_events() {
    calendar_.look_ahead(2, [this](std::uint32_t k, int ahead) {
      if (ahead > 1) {
        detail::prefetch(&own_[k]);
        detail::prefetch(&ball_[k]);
      } else if (const Own& own = own_[k]; !own.crossing_first()) {
        detail::prefetch(&own_[own.partner]);
        detail::prefetch(&ball_[own.partner]);
        calendar_.prefetch_record(own.partner);
        if constexpr (D == 2) {  // the 5 × 5 cells around ball k hold both balls' neighbourhoods
          const int low[D] = {own.coordinates[0] - 2, own.coordinates[1] - 2};
          const int high[D] = {own.coordinates[0] + 2, own.coordinates[1] + 2};
          prefetch_heads(low, high);
        }
      } else if constexpr (D == 2) {  // a crossing (in 3-D neither prefetch below measured faster)
        const Ball& ball = ball_[k];  // its neighbours in its cell's list, which its removal writes
        if (ball.previous != none) detail::prefetch(&ball_[ball.previous]);
        if (ball.next != none) detail::prefetch(&ball_[ball.next]);
        int low[D] = {own.coordinates[0] - 1, own.coordinates[1] - 1};  // the cells that come around it
        int high[D] = {own.coordinates[0] + 1, own.coordinates[1] + 1};
        low[own.axis] = high[own.axis] = own.coordinates[own.axis] + 2 * own.step;
        prefetch_heads(low, high);
      }
    });
  }

  // Asks memory for the list heads of a block of cells, low[a] to high[a] along each axis (at most five
  // cells, wrapped around the box): those of its 2^D corners, which lie in every tile the block meets
  // (a tile is four cells wide). In 2-D a tile's heads fill one cache line, so these are all the
  // block's lines. (In 3-D a tile's take four, and asking for the heads of the cells around the next
  // events measured no faster: 10^6 spheres 1–3 % slower; in 2-D, 10^6 disks 12 % faster.)
  void prefetch_heads(const int (&low)[D], const int (&high)[D]) {
    for (int corner = 0; corner < (1 << D); ++corner) {
      std::size_t index = 0;
      for (int a = 0; a < D; ++a)
        index += axis_offset_[a][wrapped((corner >> a & 1) != 0 ? high[a] : low[a])];
      detail::prefetch(&head_[index]);
    }
  }

  // Files every ball's next event in the calendar anew, its bucket width chosen from the times now.
  void refile() {
    event_times_.resize(own_.size());
    for (std::size_t i = 0; i < event_times_.size(); ++i) event_times_[i] = own_[i].event_time();
    calendar_.reset(event_times_, now_);
  }

  // Renumbers the balls in the order of their cells, so that balls near in space are near in memory
  // (a gas mixes them, and beyond the caches every prediction would otherwise miss them). Nothing
  // physical changes: every ball is brought to now on its own line, and the events keep their times,
  // with partners renumbered, filed anew in the calendar.
  //
  // The records move in place, one cycle of the renumbering at a time, and the pass's index arrays are
  // kept from one pass to the next: no fresh memory, whose first touch costs a page fault a page (at
  // 10^6 disks a pass that copied the records into new arrays took about 0.6 s, most of it faults;
  // in place, about 0.1 s).
  void reorder() {
    const std::size_t n = ball_.size();
    for (std::size_t i = 0; i < n; ++i) bring_to_now(i);
    std::vector<std::uint32_t>& order = order_;  // order[k]: the ball that becomes ball k
    order.clear();
    for (std::size_t c = 0; c < head_.size(); ++c) {
      for (std::uint32_t i = head_[c]; i != none; i = ball_[i].next) order.push_back(i);
    }
    std::vector<std::uint32_t>& renumbered = renumbered_;  // the inverse: ball i becomes renumbered[i]
    renumbered.resize(n);
    for (std::size_t k = 0; k < n; ++k) renumbered[order[k]] = static_cast<std::uint32_t>(k);
    // Each cycle k → order[k] → order[order[k]] … : place k takes the records of place order[k], which
    // the cycle has not yet overwritten, and the cycle's last place the first place's, kept aside.
    placed_.assign(n, false);
    for (std::size_t start = 0; start < n; ++start) {
      if (placed_[start]) continue;
      const Ball first_ball = ball_[start];
      const Own first_own = own_[start];
      const std::uint32_t first_identity = identity_[start];
      for (std::size_t k = start;;) {
        placed_[k] = true;
        const std::size_t from = order[k];
        if (from == start) {
          ball_[k] = first_ball;
          own_[k] = first_own;
          identity_[k] = first_identity;
          break;
        }
        ball_[k] = ball_[from];
        own_[k] = own_[from];
        identity_[k] = identity_[from];
        k = from;
      }
    }
    for (Own& o : own_) {
      if (o.partner != none) o.partner = renumbered[o.partner];
    }
    std::fill(head_.begin(), head_.end(), none);
    for (std::size_t k = n; k-- > 0;) insert(k);
    refile();
  }

  // Runs events until `collisions` more collisions or until the next event lies beyond `until`, calling
  // `on_collision` after each collision; returns the collisions run.
  template <typename OnCollision>
  std::uint64_t advance(std::uint64_t collisions, double until, OnCollision& on_collision) {
    if (ball_.size() >= look_ahead_from) return advance_beyond_caches(collisions, until, on_collision);
    return run_events<false>(collisions, until, on_collision);
  }

  // Beyond the caches, each event gathers the cells its predictions will search at its start, before
  // the work that needs none of them (a crossing's move between lists, a collision's resolution and the
  // first ball's search), so that their misses overlap that work; a crossing's new cells do not include
  // the two whose lists its move changes (the box is at least three cells wide), and a collision changes
  // no list. The same events bit for bit. And the loop is compiled as one function with everything it
  // calls inlined (flatten), kept out of the loop of smaller gases, whose code stays as it was. 10^6
  // disks 17 % more collisions a second (9 % of it the flattening), 10^6 spheres 10 %, 10^5 disks 13 %,
  // 1024 balls even (alternating separate processes on one core).
  template <typename OnCollision>
  [[gnu::noinline, gnu::flatten]] std::uint64_t advance_beyond_caches(std::uint64_t collisions, double until,
                                                                      OnCollision& on_collision) {
    return run_events<true>(collisions, until, on_collision);
  }

  template <bool beyond_caches, typename OnCollision>
  std::uint64_t run_events(std::uint64_t collisions, double until, OnCollision& on_collision) {
    std::uint64_t quiet = 0, done = 0;
    while (done < collisions) {
      const std::uint32_t earliest = calendar_.earliest();
      if (earliest == EventCalendar::none) {
        if (until < infinity) break;  // no event ever: the run reaches `until` all the same
        throw NoCollisions("no ball has a next event");
      }
      const std::size_t i = earliest;
      Own& own = own_[i];
      if (own.event_time() > until) break;
      if constexpr (beyond_caches) prefetch_next_events();
      now_ = own.event_time();
      if (own.crossing_first()) {  // a cell crossing
        Gathered gathered;
        if constexpr (beyond_caches) {
          Cell next = own.coordinates;
          next[own.axis] = static_cast<int>(wrapped(next[own.axis] + own.step));
          gather(next, own.axis, own.step, gathered);
        }
        bring_to_now(i);
        remove(i);
        const int axis = own.axis, step = own.step;
        int& c = own.coordinates[axis];
        c += step;
        if (c == cells_per_side_) c = 0, ball_[i].position[axis] -= side_;
        if (c < 0) c = cells_per_side_ - 1, ball_[i].position[axis] += side_;
        own.cell = static_cast<std::uint32_t>(cell_index(own.coordinates));
        insert(i);
        ++crossings_;
        predict_after_crossing(i, axis, step, beyond_caches ? &gathered : nullptr);
      } else if (own_[own.partner].last_collision > own.predicted_after) {
        predict(i);  // stale: the partner has collided since
      } else {
        const std::size_t j = own.partner;
        Gathered around_i, around_j;
        if constexpr (beyond_caches) {
          gather(own_[i].coordinates, all_axes, 0, around_i);
          gather(own_[j].coordinates, all_axes, 0, around_j);
        }
        // The partner leaves its place in the calendar's lists: asked of memory now, written below.
        if constexpr (beyond_caches) calendar_.prefetch_removal(static_cast<std::uint32_t>(j));
        bring_to_now(i);
        bring_to_now(j);
        const Vector image = ball_[i].position + nearest_image(ball_[i].position, ball_[j].position);
        const double distance = (image - ball_[i].position).norm();
        largest_overlap_ = std::max(largest_overlap_, (diameter_ - distance) / diameter_);
        largest_gap_ = std::max(largest_gap_, (distance - diameter_) / diameter_);
        const auto [vi, vj] = billiards::collide_if_approaching(1.0, ball_[i].position, ball_[i].velocity,
                                                                1.0, image, ball_[j].velocity);
        const Vector impulse = vi - ball_[i].velocity;
        const bool changed = !(vi.array() == ball_[i].velocity.array()).all();
        ball_[i].velocity = vi;
        ball_[j].velocity = vj;
        own_[i].last_collision = own_[j].last_collision = ++collision_number_;
        // Both predicted before either is filed, each filing asked of memory ahead of it: the
        // calendar's misses overlap the other ball's prediction (10^6 balls: 6–9 % more collisions a
        // second with the prefetches above and in the look ahead).
        predict_in_full(i, beyond_caches ? &around_i : nullptr);
        prefetch_filing(i);
        predict_in_full(j, beyond_caches ? &around_j : nullptr);
        prefetch_filing(j);
        calendar_.update(static_cast<std::uint32_t>(i), own_[i].event_time());
        calendar_.update(static_cast<std::uint32_t>(j), own_[j].event_time());
        if (changed) {
          virial_ += (ball_[i].position - image).dot(impulse);
          ++done;
          ++collisions_;
          quiet = 0;
          on_collision(GasCollision{now_, identity_[i], identity_[j]});
          // Every N collisions: the calendar's width fitted to the times again, and for large gases
          // the balls renumbered by cell.
          if (++since_refile_ >= ball_.size()) {
            since_refile_ = 0;
            if (ball_.size() >= reorder_from)
              reorder();
            else
              refile();
          }
        }
      }
      if (++quiet > quiet_limit_) {
        throw NoCollisions("stopped after " + std::to_string(quiet_limit_) +
                           " events in a row without a collision: the balls' paths do not meet");
      }
    }
    return done;
  }

  double radius_ = 0.5, diameter_ = 1, mass_ = 1;
  double side_ = 0, cell_width_ = 0, now_ = 0;
  std::uint64_t quiet_limit_ = 0;
  int cells_per_side_ = 0;
  // What a prediction reads of each neighbour, in one place, one cache line (a disk's record is 64 bytes
  // without the alignment too: Eigen aligns a 2-vector to 16 bytes, so its velocity starts at byte 32):
  // its position at its last update, that time, its velocity, and its links in its cell's list.
  struct alignas(64) Ball {
    Vector position = Vector::Zero();
    double updated = 0;
    Vector velocity = Vector::Zero();
    std::uint32_t next = none, previous = none;
  };
  detail::Array<Ball> ball_;
  detail::Array<std::uint32_t> head_;          ///< each cell's first ball (a tile's heads share cache lines)
  static constexpr std::size_t tile = 4;       ///< cells a tile has along each axis
  std::vector<std::uint32_t> axis_offset_[D];  ///< cell_index's term for each axis and coordinate
  // What an event reads of its own ball, in one place (one cache line): its next crossing, its earliest
  // predicted collision (the partner, and the number of the last collision before it was predicted),
  // its cell, the number of its own last collision. Its next event is the earlier of the two (the
  // crossing where they tie). A prediction reads nothing of the partner's record: the event checks, when
  // it comes, that the partner's last collision is not a later one.
  struct alignas(64) Own {
    double crossing_time = infinity, collision_time = infinity;
    std::uint64_t predicted_after = 0, last_collision = 0;
    std::uint32_t partner = none;
    std::uint32_t cell = 0;
    Cell coordinates = Cell::Zero();
    std::int8_t axis = 0, step = 0;  ///< the crossing: along which axis, +1 or −1
    double event_time() const { return std::min(crossing_time, collision_time); }
    bool crossing_first() const { return !(collision_time < crossing_time); }
  };
  detail::Array<Own> own_;
  // Kept between passes of reorder() and refile(), so that they touch no fresh memory.
  std::vector<std::uint32_t> order_, renumbered_;
  std::vector<bool> placed_;
  std::vector<double> event_times_;
  EventCalendar calendar_;
  detail::Array<std::uint32_t>
      identity_;  ///< each ball's index in the setup (the balls are renumbered by cell)
  std::uint64_t crossings_ = 0, since_refile_ = 0, collisions_ = 0;
  std::uint64_t collision_number_ = 0;               ///< collisions resolved so far, every event's included
  static constexpr std::size_t reorder_from = 4096;  ///< fewer balls stay in the caches anyway
  /// From here the balls lie beyond the caches and the look ahead pays (10^4 disks: 2 % slower with it,
  /// 10^5: 12–16 % faster; at 1024 it costs 10 %).
  static constexpr std::size_t look_ahead_from = std::size_t{1} << 15;
  // Σ r_ij·Δv_i over the span's collisions (times the mass, the virial), and where the span began.
  double virial_ = 0, span_start_ = 0, span_temperature_ = 0;
  std::uint64_t span_collisions_ = 0, span_crossings_ = 0;
  double largest_overlap_ = 0, largest_gap_ = 0;
};

/// Validates a gas's setup; see the declaration above.
template <int D>
void validate(const GasSetup<D>& setup) {
  const auto fail = [](const std::string& text) { throw std::invalid_argument("gas setup: " + text); };
  const auto positive = [&](const char* name, double value) {
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
  const double diameters = setup.side / (2 * setup.radius);
  if (!(diameters >= 3) || !(diameters <= gas::largest_box_side())) {
    std::ostringstream text;
    text << "side is " << setup.side << ", " << diameters
         << " diameters, expected from 3 diameters (the cell "
         << "grid's neighbours distinct) to " << gas::largest_box_side()
         << " (wider boxes round positions by more than 1e-9 of a diameter)";
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

namespace gas {

/// Gives the balls of `setup` (at least two) Gaussian velocities drawn with `seed`, of total momentum
/// zero, rescaled to kT = 1 for balls of mass 1 (Σ v² = d N).
template <int D>
void thermal_velocities(GasSetup<D>& setup, std::uint64_t seed) {
  using Vector = Eigen::Matrix<double, D, 1>;
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gaussian;
  for (Ball<D>& b : setup.balls) {
    for (int k = 0; k < D; ++k) b.velocity[k] = gaussian(random);
  }
  const auto n = static_cast<double>(setup.balls.size());
  Eigen::Matrix<long double, D, 1> momentum = Eigen::Matrix<long double, D, 1>::Zero();
  for (const Ball<D>& b : setup.balls) momentum += b.velocity.template cast<long double>();
  const Vector mean = momentum.template cast<double>() / n;
  for (Ball<D>& b : setup.balls) b.velocity -= mean;
  long double squares = 0;
  for (const Ball<D>& b : setup.balls) squares += static_cast<long double>(b.velocity.squaredNorm());
  const double scale = 1 / std::sqrt(static_cast<double>(squares / (D * static_cast<long double>(n))));
  for (Ball<D>& b : setup.balls) b.velocity *= scale;
}

/// The lattice start of `options` (validated: std::invalid_argument naming the option): N balls of
/// diameter 1 and mass 1 on a square (2-D) or FCC (3-D) lattice filling the box of packing fraction η,
/// with Gaussian velocities of total momentum zero, rescaled to kT = 1.
template <int D>
GasSetup<D> lattice(const Options& options) {
  validate(options);
  if (options.dimension != D) {
    throw std::invalid_argument("--dimension is " + std::to_string(options.dimension) + ", expected " +
                                std::to_string(D) + " for gas::lattice<" + std::to_string(D) + ">");
  }
  using Vector = Eigen::Matrix<double, D, 1>;
  GasSetup<D> setup;
  setup.side = box_side(D, options.balls, options.packing_fraction);
  setup.balls.resize(options.balls);
  const std::size_t n = lattice_cells(D, options.balls);
  const double spacing = setup.side / static_cast<double>(n);
  std::size_t placed = 0;
  if constexpr (D == 2) {
    for (std::size_t i = 0; i < n && placed < options.balls; ++i) {
      for (std::size_t j = 0; j < n && placed < options.balls; ++j) {
        setup.balls[placed++].position =
            Vector((static_cast<double>(i) + 0.5) * spacing, (static_cast<double>(j) + 0.5) * spacing);
      }
    }
  } else {
    const double basis[4][3] = {
        {0.25, 0.25, 0.25}, {0.75, 0.75, 0.25}, {0.75, 0.25, 0.75}, {0.25, 0.75, 0.75}};
    for (std::size_t i = 0; i < n && placed < options.balls; ++i) {
      for (std::size_t j = 0; j < n && placed < options.balls; ++j) {
        for (std::size_t k = 0; k < n && placed < options.balls; ++k) {
          for (int b = 0; b < 4 && placed < options.balls; ++b) {
            setup.balls[placed++].position = Vector((static_cast<double>(i) + basis[b][0]) * spacing,
                                                    (static_cast<double>(j) + basis[b][1]) * spacing,
                                                    (static_cast<double>(k) + basis[b][2]) * spacing);
          }
        }
      }
    }
  }
  thermal_velocities(setup, options.seed);
  return setup;
}

/// The standard error of the mean of `x` (0 for fewer than two values).
inline double standard_error(const std::vector<double>& x) {
  if (x.size() < 2) return 0;
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  double squares = 0;
  for (double v : x) squares += (v - mean) * (v - mean);
  return std::sqrt(squares / static_cast<double>(x.size() - 1) / static_cast<double>(x.size()));
}

/// Runs `options.equilibrate` collisions of `gas` unmeasured, then `options.events` measured in ten
/// blocks, and returns what was measured, with errors from the scatter of the blocks.
template <int D>
Result measure(Gas<D>& gas, const Options& options) {
  gas.run_collisions(options.equilibrate);
  constexpr int blocks = 10;
  const double kT = gas.temperature(), n = static_cast<double>(gas.size());
  Result r;
  r.dimension = D;
  r.balls = gas.size();
  r.packing_fraction = options.packing_fraction;
  std::vector<double> z_blocks, rate_blocks;
  double total_virial = 0;
  const auto wall_start = std::chrono::steady_clock::now();
  std::uint64_t done = 0;
  for (int b = 0; b < blocks; ++b) {
    const std::uint64_t target = options.events * static_cast<std::uint64_t>(b + 1) / blocks;
    gas.reset_measurements();
    gas.run_collisions(target - done);
    done = target;
    const GasMeasurement block = gas.measured();
    total_virial += block.virial;
    r.time += block.time;
    r.cell_crossings += block.cell_crossings;
    r.largest_temperature_change =
        std::max(r.largest_temperature_change, std::fabs(gas.temperature() - kT) / kT);
    if (block.time > 0 && block.collisions > 0) {
      z_blocks.push_back(block.compressibility_factor);
      rate_blocks.push_back(block.compressibility_factor_from_collision_rate);
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  r.collisions = done;
  r.temperature = gas.temperature();
  r.momentum = gas.momentum().norm();
  r.largest_overlap = gas.largest_overlap();
  r.largest_gap = gas.largest_gap();
  r.events_per_second = seconds > 0 ? static_cast<double>(done) / seconds : 0;
  r.compressibility_factor = r.time > 0 ? 1 + total_virial / (D * n * kT * r.time) : 1;
  r.mean_free_time =
      done > 0 ? r.time * n / (2 * static_cast<double>(done)) : std::numeric_limits<double>::infinity();
  r.compressibility_factor_from_collision_rate =
      done > 0
          ? 1 + 2 * gas.radius() * std::sqrt(std::numbers::pi * gas.mass() / kT) / (2 * D * r.mean_free_time)
          : 1;
  r.compressibility_factor_error = standard_error(z_blocks);
  r.compressibility_factor_from_collision_rate_error = standard_error(rate_blocks);
  return r;
}

/// Validates `options`, runs the lattice gas of its dimension and returns what it measured.
inline Result measure(const Options& options) {
  validate(options);
  if (options.dimension == 2) {
    Gas<2> gas(lattice<2>(options), options.max_events_without_collision);
    return measure(gas, options);
  }
  Gas<3> gas(lattice<3>(options), options.max_events_without_collision);
  return measure(gas, options);
}

}  // namespace gas
}  // namespace billiards::simulation
