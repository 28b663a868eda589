// A hard-sphere gas, event-driven, on billiards::runtime: N balls of diameter σ = 1 and mass m = 1 in
// a periodic square (2-D) or cubic (3-D) box, started from a square or FCC lattice with random
// velocities (total momentum zero, kT = 1), run collision by collision with no time step.
//
// Each ball keeps its position at its own last update (positions are brought forward only when a
// ball takes part in an event). The box is divided into a grid of cells at least one diameter wide,
// numbered tile by tile (tiles of 4^D cells, so that neighbouring cells lie near one another in memory);
// each ball's next event is the earlier of its next cell crossing and its earliest predicted
// collision with a ball in its own or a neighbouring cell (billiards::time_of_impact on the nearest
// periodic image), so a prediction costs the same whatever N. After a cell crossing only the cells that
// have just come around the ball are searched, the earliest collision found before kept beside them
// (3^(D−1) cells, not 3^D). The balls' next events sit in an event
// calendar (event_calendar.hpp: a calendar queue, O(1) a step on average). Collisions are numbered; a
// collision event records the number of the last collision before its prediction: when the partner has
// collided since, the event is stale and the ball is predicted again. Collisions are resolved by
// billiards::collide_if_approaching on the nearest images.
//
// Measured over the span after the equilibration: the collision virial Σ r_ij·Δp_i (r_ij = r_i − r_j at
// contact, Δp_i ball i's change of momentum), which gives Z = PV/(N kT) = 1 + Σ r_ij·Δp_i/(d N kT t),
// and the collision count, which gives the mean free time τ = t N/(2 C) and, through the identity
// Z − 1 = σ √(π m/kT)/(2 d τ), a second estimate of Z from the collision rate alone.
#pragma once

#include "event_calendar.hpp"
#include "large_array.hpp"
#include "prefetch.hpp"

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
#include <vector>

namespace billiards_example::gas {

/// What to run: the command line of billiards-gas.
struct Options {
  int dimension = 3;
  std::size_t balls = 1000;
  double packing_fraction = 0.3;
  std::uint64_t events = 100000;      ///< collisions measured
  std::uint64_t equilibrate = 10000;  ///< collisions run first, not measured
  std::uint64_t seed = 1;
  /// Stop (throw NoCollisions) after this many events in a row without a collision; 0: 10^6 + 100 N.
  std::uint64_t max_events_without_collision = 0;
};

/// What a run measured (units σ = m = kT = 1).
struct Result {
  int dimension = 0;
  std::size_t balls = 0;
  double packing_fraction = 0;
  std::uint64_t collisions = 0;  ///< over the measured span
  std::uint64_t cell_crossings = 0;
  double time = 0;  ///< the measured span, in simulation time
  double compressibility_factor = 0, compressibility_factor_error = 0;  ///< Z from the virial
  /// Z from the collision rate, 1 + σ √(π m/kT)/(2 d τ), and its error.
  double compressibility_factor_from_collision_rate = 0, compressibility_factor_from_collision_rate_error = 0;
  double mean_free_time = 0;
  double temperature = 0;                 ///< kT at the end, Σ m v²/(d N)
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

/// Thrown when a run goes on without collisions (the balls' paths never meet).
struct NoCollisions : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A d-dimensional hard-sphere gas.
template <int D>
class Gas {
 public:
  using Vector = Eigen::Matrix<double, D, 1>;

  explicit Gas(const Options& options) : options_(options) {
    validate(options);
    if (options.dimension != D) throw std::invalid_argument("Gas<D>: --dimension differs from D");
    const std::size_t n = options.balls;
    side_ = box_side(D, n, options.packing_fraction);
    cells_per_side_ = grid_cells_per_side(D, n, side_);  // cells at least one diameter wide
    cell_width_ = side_ / cells_per_side_;
    lay_out_cells();
    ball_.resize(n);
    own_.resize(n);
    place_on_lattice();
    draw_velocities();
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < D; ++k) {
        own_[i].coordinates[k] =
            std::min(cells_per_side_ - 1, static_cast<int>(ball_[i].position[k] / cell_width_));
      }
      own_[i].cell = static_cast<std::uint32_t>(cell_index(own_[i].coordinates));
      insert(i);
    }
    for (std::size_t i = 0; i < n; ++i) predict_in_full(i);
    calendar_.defer_filings(n >= look_ahead_from);
    refile();
    initial_temperature_ = temperature();
  }

  /// Runs the equilibration and the measured span and returns what was measured.
  Result run() {
    advance(options_.equilibrate, false);
    virial_ = 0;
    const double start = now_;
    const std::uint64_t crossings_before = crossings_;
    constexpr int blocks = 10;
    std::vector<double> block_virial, block_time;
    std::vector<std::uint64_t> block_collisions;
    const auto wall_start = std::chrono::steady_clock::now();
    std::uint64_t done = 0;
    for (int b = 0; b < blocks; ++b) {
      const std::uint64_t target = options_.events * static_cast<std::uint64_t>(b + 1) / blocks;
      const double block_start = now_;
      virial_ = 0;
      advance(target - done, true);
      block_collisions.push_back(target - done);
      done = target;
      block_virial.push_back(virial_);
      block_time.push_back(now_ - block_start);
      largest_temperature_change_ =
          std::max(largest_temperature_change_,
                   std::fabs(temperature() - initial_temperature_) / initial_temperature_);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    Result r;
    r.dimension = D;
    r.balls = options_.balls;
    r.packing_fraction = options_.packing_fraction;
    r.collisions = done;
    r.cell_crossings = crossings_ - crossings_before;
    r.time = now_ - start;
    r.temperature = temperature();
    r.largest_temperature_change = largest_temperature_change_;
    r.momentum = momentum().norm();
    r.largest_overlap = largest_overlap_;
    r.largest_gap = largest_gap_;
    r.events_per_second = seconds > 0 ? static_cast<double>(done) / seconds : 0;
    const double n = static_cast<double>(options_.balls), kT = initial_temperature_;
    double total_virial = 0;
    for (double w : block_virial) total_virial += w;
    r.compressibility_factor = r.time > 0 ? 1 + total_virial / (D * n * kT * r.time) : 1;
    r.mean_free_time =
        done > 0 ? r.time * n / (2 * static_cast<double>(done)) : std::numeric_limits<double>::infinity();
    const auto from_rate = [&](double time, double collisions) {
      const double tau = time * n / (2 * collisions);
      return 1 + std::sqrt(std::numbers::pi / kT) / (2 * D * tau);
    };
    r.compressibility_factor_from_collision_rate =
        done > 0 ? from_rate(r.time, static_cast<double>(done)) : 1;
    // Errors from the scatter of the blocks' estimates: the standard error of their mean.
    std::vector<double> z_blocks, rate_blocks;
    for (int b = 0; b < blocks; ++b) {
      if (block_time[static_cast<std::size_t>(b)] <= 0 || block_collisions[static_cast<std::size_t>(b)] == 0)
        continue;
      z_blocks.push_back(1 + block_virial[static_cast<std::size_t>(b)] /
                                 (D * n * kT * block_time[static_cast<std::size_t>(b)]));
      rate_blocks.push_back(from_rate(block_time[static_cast<std::size_t>(b)],
                                      static_cast<double>(block_collisions[static_cast<std::size_t>(b)])));
    }
    r.compressibility_factor_error = standard_error(z_blocks);
    r.compressibility_factor_from_collision_rate_error = standard_error(rate_blocks);
    return r;
  }

  /// Runs `count` more collisions without measuring them (the benchmark's step).
  void run_collisions(std::uint64_t count) { advance(count, false); }

  /// kT = Σ m v²/(d N), long double sums.
  double temperature() const {
    long double sum = 0;
    for (const Ball& b : ball_) sum += static_cast<long double>(b.velocity.squaredNorm());
    return static_cast<double>(sum / (D * static_cast<long double>(ball_.size())));
  }
  Vector momentum() const {
    Eigen::Matrix<long double, D, 1> sum = Eigen::Matrix<long double, D, 1>::Zero();
    for (const Ball& b : ball_) sum += b.velocity.template cast<long double>();
    return sum.template cast<double>();
  }
  double side() const { return side_; }
  int cells_per_side() const { return cells_per_side_; }
  /// Every ball brought to the current time (for checks): their positions in [0, side).
  std::vector<Vector> positions_now() const {
    std::vector<Vector> out(ball_.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
      out[i] = ball_[i].position + ball_[i].velocity * (now_ - ball_[i].updated);
      for (int k = 0; k < D; ++k) out[i][k] -= side_ * std::floor(out[i][k] / side_);
    }
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

  static double standard_error(const std::vector<double>& x) {
    if (x.size() < 2) return 0;
    double mean = 0;
    for (double v : x) mean += v;
    mean /= static_cast<double>(x.size());
    double squares = 0;
    for (double v : x) squares += (v - mean) * (v - mean);
    return std::sqrt(squares / static_cast<double>(x.size() - 1) / static_cast<double>(x.size()));
  }

  void place_on_lattice() {
    const std::size_t n = lattice_cells(D, options_.balls);
    const double spacing = side_ / static_cast<double>(n);
    std::size_t placed = 0;
    if constexpr (D == 2) {
      for (std::size_t i = 0; i < n && placed < options_.balls; ++i) {
        for (std::size_t j = 0; j < n && placed < options_.balls; ++j) {
          ball_[placed++].position =
              Vector((static_cast<double>(i) + 0.5) * spacing, (static_cast<double>(j) + 0.5) * spacing);
        }
      }
    } else {
      const double basis[4][3] = {
          {0.25, 0.25, 0.25}, {0.75, 0.75, 0.25}, {0.75, 0.25, 0.75}, {0.25, 0.75, 0.75}};
      for (std::size_t i = 0; i < n && placed < options_.balls; ++i) {
        for (std::size_t j = 0; j < n && placed < options_.balls; ++j) {
          for (std::size_t k = 0; k < n && placed < options_.balls; ++k) {
            for (int b = 0; b < 4 && placed < options_.balls; ++b) {
              ball_[placed++].position = Vector((static_cast<double>(i) + basis[b][0]) * spacing,
                                                (static_cast<double>(j) + basis[b][1]) * spacing,
                                                (static_cast<double>(k) + basis[b][2]) * spacing);
            }
          }
        }
      }
    }
  }

  void draw_velocities() {
    std::mt19937_64 random(options_.seed);
    std::normal_distribution<double> gaussian;
    for (Ball& b : ball_) {
      for (int k = 0; k < D; ++k) b.velocity[k] = gaussian(random);
    }
    const Vector mean = momentum() / static_cast<double>(ball_.size());
    for (Ball& b : ball_) b.velocity -= mean;
    const double scale = 1 / std::sqrt(temperature());
    for (Ball& b : ball_) b.velocity *= scale;
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
  void gather(const Cell& centre, int axis, int step, Gathered& gathered) {
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
        prefetch(&head_[index]);
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
        if (first[n] != none) prefetch(&ball_[first[n]]);
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
        const double t =
            billiards::time_of_impact(Vector::Zero().eval(), ball_[i].velocity, p, ball_[j].velocity, 1.0);
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
        prefetch(&own_[k]);
        prefetch(&ball_[k]);
      } else if (const Own& own = own_[k]; !own.crossing_first()) {
        prefetch(&own_[own.partner]);
        prefetch(&ball_[own.partner]);
        calendar_.prefetch_record(own.partner);
        if constexpr (D == 2) {  // the 5 × 5 cells around ball k hold both balls' neighbourhoods
          const int low[D] = {own.coordinates[0] - 2, own.coordinates[1] - 2};
          const int high[D] = {own.coordinates[0] + 2, own.coordinates[1] + 2};
          prefetch_heads(low, high);
        }
      } else if constexpr (D == 2) {  // a crossing (in 3-D neither prefetch below measured faster)
        const Ball& ball = ball_[k];  // its neighbours in its cell's list, which its removal writes
        if (ball.previous != none) prefetch(&ball_[ball.previous]);
        if (ball.next != none) prefetch(&ball_[ball.next]);
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
      prefetch(&head_[index]);
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
      for (std::size_t k = start;;) {
        placed_[k] = true;
        const std::size_t from = order[k];
        if (from == start) {
          ball_[k] = first_ball;
          own_[k] = first_own;
          break;
        }
        ball_[k] = ball_[from];
        own_[k] = own_[from];
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

  // Runs events until `collisions` more collisions; accumulates the virial where `measure`.
  void advance(std::uint64_t collisions, bool measure) {
    if (ball_.size() >= look_ahead_from)
      advance_beyond_caches(collisions, measure);
    else
      run_events<false>(collisions, measure);
  }

  // Beyond the caches, each event gathers the cells its predictions will search at its start, before
  // the work that needs none of them (a crossing's move between lists, a collision's resolution and the
  // first ball's search), so that their misses overlap that work; a crossing's new cells do not include
  // the two whose lists its move changes (the box is at least three cells wide), and a collision changes
  // no list. The same events bit for bit. And the loop is compiled as one function with everything it
  // calls inlined (flatten), kept out of the loop of smaller gases, whose code stays as it was. 10^6
  // disks 17 % more collisions a second (9 % of it the flattening), 10^6 spheres 10 %, 10^5 disks 13 %,
  // 1024 balls even (alternating separate processes on one core).
  [[gnu::noinline, gnu::flatten]] void advance_beyond_caches(std::uint64_t collisions, bool measure) {
    run_events<true>(collisions, measure);
  }

  template <bool beyond_caches>
  void run_events(std::uint64_t collisions, bool measure) {
    const std::uint64_t quiet_limit = options_.max_events_without_collision != 0
                                          ? options_.max_events_without_collision
                                          : 1000000 + 100 * static_cast<std::uint64_t>(options_.balls);
    std::uint64_t quiet = 0;
    for (std::uint64_t done = 0; done < collisions;) {
      const std::uint32_t earliest = calendar_.earliest();
      if (earliest == EventCalendar::none) throw NoCollisions("no ball has a next event");
      const std::size_t i = earliest;
      if constexpr (beyond_caches) prefetch_next_events();
      Own& own = own_[i];
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
        largest_overlap_ = std::max(largest_overlap_, 1 - distance);
        largest_gap_ = std::max(largest_gap_, distance - 1);
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
          if (measure) virial_ += (ball_[i].position - image).dot(impulse);
          ++done;
          quiet = 0;
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
      if (++quiet > quiet_limit) {
        throw NoCollisions("stopped after " + std::to_string(quiet_limit) +
                           " events in a row without a collision: the balls' paths do not meet");
      }
    }
  }

  Options options_;
  double side_ = 0, cell_width_ = 0, now_ = 0;
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
  Array<Ball> ball_;
  Array<std::uint32_t> head_;                  ///< each cell's first ball (a tile's heads share cache lines)
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
  Array<Own> own_;
  // Kept between passes of reorder() and refile(), so that they touch no fresh memory.
  std::vector<std::uint32_t> order_, renumbered_;
  std::vector<bool> placed_;
  std::vector<double> event_times_;
  EventCalendar calendar_;
  std::uint64_t crossings_ = 0, since_refile_ = 0;
  std::uint64_t collision_number_ = 0;               ///< collisions resolved so far, every event's included
  static constexpr std::size_t reorder_from = 4096;  ///< fewer balls stay in the caches anyway
  /// From here the balls lie beyond the caches and the look ahead pays (10^4 disks: 2 % slower with it,
  /// 10^5: 12–16 % faster; at 1024 it costs 10 %).
  static constexpr std::size_t look_ahead_from = std::size_t{1} << 15;
  double virial_ = 0, largest_overlap_ = 0, largest_gap_ = 0, initial_temperature_ = 1,
         largest_temperature_change_ = 0;
};

/// Validates `options`, runs the gas of its dimension and returns what it measured.
inline Result run(const Options& options) {
  validate(options);
  if (options.dimension == 2) return Gas<2>(options).run();
  return Gas<3>(options).run();
}

}  // namespace billiards_example::gas
