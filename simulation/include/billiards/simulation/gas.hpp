/// \file
/// A hard-sphere gas, event-driven, on billiards::runtime: N balls (equal, or each of its own radius and
/// mass) in a periodic square (2-D) or cubic (3-D) box, from a configuration of the caller's (GasSetup,
/// gas_setup.hpp) or a square or FCC lattice with random velocities (gas::lattice), run collision by
/// collision with no time step.
///
/// Each ball keeps its position at its own last update (positions are brought forward only when a
/// ball takes part in an event), and has one next event in an event calendar (event_calendar.hpp: a
/// calendar queue, O(1) a step on average). Pairs are predicted by billiards::time_of_impact on their
/// nearest periodic images and resolved by billiards::collide_if_approaching. Collisions are numbered;
/// a collision event records the number of the last collision before its prediction: when the partner
/// has collided since, the event is stale and the ball is predicted again. Two engines find the pairs
/// to predict (GasMethod):
/// - **neighbour lists** (detail/gas_lists.hpp): each ball lists the balls whose centres were within
///   1.5 (r_i + r_j) of its own when the later of the two lists was built; its next event is the
///   earlier of its earliest collision with a ball of its list and the rebuild of its list, due when it
///   has moved 0.5 r_i from where the list was built (no pair can then meet unlisted). A prediction
///   reads only the list: about 12 balls at η = 0.45.
/// - **cells** (detail/gas_cells.hpp, equal balls only): the box cut into cells at least a diameter
///   wide, each ball's next event the earlier of its next cell crossing and its earliest collision with
///   a ball of the 3^D cells around its own; after a crossing only the 3^(D−1) cells that have come
///   around it are searched. In a dilute gas a ball crosses cells more rarely than it would rebuild
///   a list.
/// The automatic choice: neighbour lists for unequal balls, and for equal balls from a packing fraction
/// of gas::neighbour_lists_from(D, N) (measured faster above it); cells below.
/// Both engines renumber the balls by cell every N collisions from 4096 balls, so that balls near in
/// space are near in memory, and report the same physics (tests run both on the same setups).
///
/// Measured over a span (Gas::reset_measurements to now): the collision virial Σ r_ij·Δp_i (r_ij =
/// r_i − r_j at contact, Δp_i ball i's change of momentum), which gives Z = PV/(N kT) = 1 + Σ r_ij·Δp_i/(d
/// N kT t), and the collision count, which gives the mean free time τ = t N/(2 C) and, through the
/// identity Z − 1 = Σ σ_ij √(2π μ_ij kT)/(d N kT t) (for equal balls σ √(π m/kT)/(2 d τ)), a second
/// estimate of Z from the collision rate alone.
#pragma once

#include <billiards/simulation/detail/gas_cells.hpp>
#include <billiards/simulation/detail/gas_lists.hpp>
#include <billiards/simulation/gas_setup.hpp>

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
#include <variant>
#include <vector>

namespace billiards::simulation {

namespace gas {

/// The packing fraction from which GasMethod::automatic runs N equal balls on neighbour lists rather than
/// cells: 0.22 + 0.04 log10(N/4000) for spheres, 0.5 + 0.02 log10(N/4000) for disks. Below it a ball
/// rebuilds its list more often than it crosses a cell; beyond the caches a rebuild's misses weigh more,
/// so the line moves up with N. Measured on billiards-gas, one core, cells against lists side by side:
/// spheres even at N = 4000, η = 0.21; 32 000, 0.25; 256 000, 0.30; at 10^6 and 0.30 cells 1.2× faster;
/// disks even at 4096, 0.5, and at 10^6 lists 1.2× faster from 0.6.
inline double neighbour_lists_from(int dimension, std::size_t balls) {
  const double decades = std::log10(static_cast<double>(std::max<std::size_t>(balls, 2)) / 4000);
  return dimension == 2 ? 0.5 + 0.02 * decades : 0.22 + 0.04 * decades;
}

}  // namespace gas

/// A D-dimensional hard-sphere gas: built from a GasSetup, run for a number of collisions
/// (run_collisions) or until a time (run_until), each collision reported to an optional callback.
template <int D>
class Gas {
 public:
  /// A position or a velocity.
  using Vector = Eigen::Matrix<double, D, 1>;

  /// Validates `setup` (see validate(const GasSetup<D>&)) and predicts every ball's first event, on the
  /// engine `method` names (GasMethod::cells with unequal balls: std::invalid_argument). A run stops with
  /// NoCollisions after `max_events_without_collision` events in a row without a collision (0: 10^6 +
  /// 100 N), so that balls whose paths never meet cannot run forever.
  explicit Gas(const GasSetup<D>& setup, std::uint64_t max_events_without_collision = 0,
               GasMethod method = GasMethod::automatic)
      : engine_(make(setup, max_events_without_collision, method)) {}

  /// Runs `count` more collisions, calling `on_collision(const GasCollision&)` after each, and returns
  /// the number run (`count`). Throws NoCollisions after too many events in a row without a collision
  /// (see the constructor).
  template <typename OnCollision>
  std::uint64_t run_collisions(std::uint64_t count, OnCollision&& on_collision) {
    return std::visit([&](auto& e) { return e.run_collisions(count, on_collision); }, engine_);
  }
  /// Runs `count` more collisions; see the overload with a callback.
  std::uint64_t run_collisions(std::uint64_t count) { return run_collisions(count, ignore_collision); }

  /// Runs until `count` more collisions or the gas's time `until` (+∞: no limit), whichever comes first,
  /// calling `on_collision(const GasCollision&)` after each collision; where it stops at `until`, that is
  /// the time now. Returns the number of collisions run. Throws std::invalid_argument when `until` is
  /// NaN or earlier than time(), and NoCollisions as run_collisions does.
  template <typename OnCollision>
  std::uint64_t run(std::uint64_t count, double until, OnCollision&& on_collision) {
    return std::visit([&](auto& e) { return e.run(count, until, on_collision); }, engine_);
  }
  /// Runs until `count` more collisions or the time `until`; see the overload with a callback.
  std::uint64_t run(std::uint64_t count, double until) { return run(count, until, ignore_collision); }

  /// Runs every collision up to the gas's time `until`, calling `on_collision(const GasCollision&)`
  /// after each, and makes `until` the time now; returns the number of collisions run. Throws
  /// std::invalid_argument when `until` is NaN, infinite or earlier than time().
  template <typename OnCollision>
  std::uint64_t run_until(double until, OnCollision&& on_collision) {
    return std::visit([&](auto& e) { return e.run_until(until, on_collision); }, engine_);
  }
  /// Runs every collision up to the gas's time `until`; see the overload with a callback.
  std::uint64_t run_until(double until) { return run_until(until, ignore_collision); }

  /// Starts a new span of measurement at the time now (see measured()).
  void reset_measurements() {
    std::visit([](auto& e) { e.reset_measurements(); }, engine_);
  }
  /// What was measured from the construction, or the last reset_measurements(), to now.
  GasMeasurement measured() const { return visit([](const auto& e) { return e.measured(); }); }
  /// kT = Σ m v²/(d N), summed in long double.
  double temperature() const { return visit([](const auto& e) { return e.temperature(); }); }
  /// Σ m v, summed in long double.
  Vector momentum() const { return visit([](const auto& e) { return e.momentum(); }); }
  /// The number of balls, N.
  std::size_t size() const { return visit([](const auto& e) { return e.size(); }); }
  /// The box's side.
  double side() const { return visit([](const auto& e) { return e.side(); }); }
  /// The setup's `radius`: every ball's radius where the setup gave no `radii`.
  double radius() const { return visit([](const auto& e) { return e.radius(); }); }
  /// The setup's `mass`: every ball's mass where the setup gave no `masses`.
  double mass() const { return visit([](const auto& e) { return e.mass(); }); }
  /// Whether every ball has the same radius and the same mass.
  bool equal_balls() const { return visit([](const auto& e) { return e.equal_balls(); }); }
  /// Every ball's radius, in the setup's order.
  std::vector<double> radii() const { return visit([](const auto& e) { return e.radii(); }); }
  /// Every ball's mass, in the setup's order.
  std::vector<double> masses() const { return visit([](const auto& e) { return e.masses(); }); }
  /// The engine in use: GasMethod::cells or GasMethod::neighbour_lists.
  GasMethod method() const { return engine_.index() == 0 ? GasMethod::cells : GasMethod::neighbour_lists; }
  /// The gas's time now (0 at the construction).
  double time() const { return visit([](const auto& e) { return e.time(); }); }
  /// Collisions resolved since the construction.
  std::uint64_t collisions() const { return visit([](const auto& e) { return e.collisions(); }); }
  /// Cell crossings since the construction (the cell engine's own events, not reported to callbacks; 0
  /// on neighbour lists).
  std::uint64_t cell_crossings() const { return method() == GasMethod::cells ? own_events() : 0; }
  /// Neighbour lists rebuilt since the construction (the neighbour-list engine's own events, not
  /// reported to callbacks; 0 on cells).
  std::uint64_t list_rebuilds() const { return method() == GasMethod::neighbour_lists ? own_events() : 0; }
  /// The largest overlap at any collision since the construction, relative to the pair's r_i + r_j.
  double largest_overlap() const { return visit([](const auto& e) { return e.largest_overlap(); }); }
  /// How far beyond touching the centres were at any collision since the construction, relative to the
  /// pair's r_i + r_j (a collision taken when it is not due, from a stale prediction, would show here).
  double largest_gap() const { return visit([](const auto& e) { return e.largest_gap(); }); }
  /// The cells per side of the engine's cell grid.
  int cells_per_side() const { return visit([](const auto& e) { return e.cells_per_side(); }); }

  /// Every ball's position now, in the setup's order, each coordinate in [0, side).
  std::vector<Vector> positions() const { return visit([](const auto& e) { return e.positions(); }); }
  /// Every ball's position now, unwrapped: its path followed across the periodic boundaries since the
  /// construction (the setup's position taken into the box, plus every displacement since), in the
  /// setup's order. The mean squared displacement is the mean of |unwrapped now − unwrapped then|².
  std::vector<Vector> unwrapped_positions() const {
    return visit([](const auto& e) { return e.unwrapped_positions(); });
  }
  /// Every ball's velocity, in the setup's order.
  std::vector<Vector> velocities() const { return visit([](const auto& e) { return e.velocities(); }); }
  /// The state now as a setup (positions in [0, side); `radii` and `masses` given where the balls are
  /// not all equal): a gas built from it runs on from here.
  GasSetup<D> setup() const { return visit([](const auto& e) { return e.setup(); }); }
  /// The displacement b − a to the nearest periodic image.
  Vector nearest_image(const Vector& a, const Vector& b) const {
    return visit([&](const auto& e) { return e.nearest_image(a, b); });
  }

 private:
  using Engine = std::variant<detail::CellGas<D>, detail::ListGas<D>>;

  static Engine make(const GasSetup<D>& setup, std::uint64_t quiet, GasMethod method) {
    validate(setup);
    const bool equal = setup.equal_balls();
    if (method == GasMethod::cells && !equal) {
      throw std::invalid_argument(
          "method is GasMethod::cells, expected automatic or neighbour_lists for balls of unequal radii or masses");
    }
    if (method == GasMethod::automatic) {
      const double eta = static_cast<double>(setup.balls.size()) * gas::ball_volume(D) *
                         std::pow(2 * setup.radius_of(0) / setup.side, D);
      method = !equal || eta >= gas::neighbour_lists_from(D, setup.balls.size()) ? GasMethod::neighbour_lists
                                                                                  : GasMethod::cells;
    }
    if (method == GasMethod::cells) return Engine(std::in_place_index<0>, setup, quiet);
    return Engine(std::in_place_index<1>, setup, quiet);
  }
  std::uint64_t own_events() const { return visit([](const auto& e) { return e.own_events(); }); }
  template <class F>
  auto visit(F&& f) const {
    return std::visit(f, engine_);
  }
  // A callback that does nothing: a run without one compiles to the loop it was before.
  static void ignore_collision(const GasCollision&) {}

  Engine engine_;
};

namespace gas {

/// Gives the balls of `setup` (at least two) Gaussian velocities drawn with `seed`, ball i's of
/// variance 1/m_i, less the centre of mass's velocity (total momentum zero), rescaled to kT = 1
/// (Σ m v² = d N).
template <int D>
void thermal_velocities(GasSetup<D>& setup, std::uint64_t seed) {
  using Vector = Eigen::Matrix<double, D, 1>;
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gaussian;
  const std::size_t n = setup.balls.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double spread = 1 / std::sqrt(setup.mass_of(i));
    for (int k = 0; k < D; ++k) setup.balls[i].velocity[k] = gaussian(random) * spread;
  }
  Eigen::Matrix<long double, D, 1> momentum = Eigen::Matrix<long double, D, 1>::Zero();
  long double mass = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto m = static_cast<long double>(setup.mass_of(i));
    momentum += m * setup.balls[i].velocity.template cast<long double>();
    mass += m;
  }
  const Vector mean = momentum.template cast<double>() / static_cast<double>(mass);
  for (Ball<D>& b : setup.balls) b.velocity -= mean;
  long double squares = 0;
  for (std::size_t i = 0; i < n; ++i) {
    squares += static_cast<long double>(setup.mass_of(i)) *
               static_cast<long double>(setup.balls[i].velocity.squaredNorm());
  }
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

/// Z of the equation of state for the balls of `gas`: Henderson's (disks) or Carnahan–Starling's
/// (spheres) for equal balls, BMCSL for spheres of unequal radii, NaN for disks of unequal radii.
template <int D>
double equation_of_state(const Gas<D>& gas) {
  const std::vector<double> radii = gas.radii();
  const double volume = std::pow(gas.side(), D);
  if (std::all_of(radii.begin(), radii.end(), [&](double r) { return r == radii[0]; })) {
    return equation_of_state(D, static_cast<double>(radii.size()) * ball_volume(D) * std::pow(2 * radii[0], D) / volume);
  }
  if constexpr (D == 2) {
    return std::numeric_limits<double>::quiet_NaN();
  } else {
    std::vector<double> diameters(radii.size());
    for (std::size_t i = 0; i < radii.size(); ++i) diameters[i] = 2 * radii[i];
    return boublik_mansoori(diameters, volume);
  }
}

/// The packing fraction of `gas`: the balls' volume (areas in 2-D) over the box's.
template <int D>
double packing_fraction(const Gas<D>& gas) {
  double filled = 0;
  for (double r : gas.radii()) filled += ball_volume(D) * std::pow(2 * r, D);
  return filled / std::pow(gas.side(), D);
}

/// Runs `options.equilibrate` collisions of `gas` unmeasured, then `options.events` measured in
/// `options.blocks` blocks, and returns what was measured, with errors from the scatter of the blocks
/// and the time series block by block (no more blocks than events). Where `options.snapshot_interval`
/// is positive, calls `on_snapshot(gas)` at the measured span's start and every interval of the gas's
/// time after it while the span lasts (the gas brought to that time). Throws std::invalid_argument
/// naming the option where there is no block, or the interval is negative, not finite, or too small to
/// advance the gas's time.
template <int D, typename OnSnapshot>
Result measure(Gas<D>& gas, const Options& options, OnSnapshot&& on_snapshot) {
  if (options.blocks < 1) {
    throw std::invalid_argument("--blocks is " + std::to_string(options.blocks) + ", expected at least 1");
  }
  if (!(options.snapshot_interval >= 0) || !std::isfinite(options.snapshot_interval)) {
    throw std::invalid_argument("--snapshot-every is " + std::to_string(options.snapshot_interval) +
                                ", expected a finite time, 0 or more");
  }
  gas.run_collisions(options.equilibrate);
  // No more blocks than collisions: each block holds at least one.
  const std::uint64_t blocks = std::max<std::uint64_t>(1, std::min<std::uint64_t>(static_cast<std::uint64_t>(options.blocks), options.events));
  const double kT = gas.temperature(), n = static_cast<double>(gas.size());
  const double density = n / std::pow(gas.side(), D);
  Result r;
  r.dimension = D;
  r.balls = gas.size();
  r.packing_fraction = packing_fraction(gas);
  r.equation_of_state = equation_of_state(gas);
  std::vector<double> z_blocks, p_blocks, rate_blocks;
  double total_virial = 0, rate_excess = 0;  // rate_excess: Σ (Z_rate − 1) t over the blocks
  const std::vector<Eigen::Matrix<double, D, 1>> start = gas.unwrapped_positions();
  const double start_time = gas.time();
  const bool snapshots = options.snapshot_interval > 0;
  std::uint64_t snapshot_count = 0;
  double next_snapshot = start_time;
  const auto wall_start = std::chrono::steady_clock::now();
  std::uint64_t done = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t target = options.events * (b + 1) / blocks;
    gas.reset_measurements();
    while (done < target) {
      if (snapshots && next_snapshot <= gas.time()) {
        on_snapshot(static_cast<const Gas<D>&>(gas));
        next_snapshot = start_time + options.snapshot_interval * static_cast<double>(++snapshot_count);
        if (!(next_snapshot > gas.time())) {  // an interval lost in the time's rounding: no progress
          std::ostringstream text;
          text << "--snapshot-every is " << options.snapshot_interval << ", expected an interval the gas's time "
               << gas.time() << " can advance by (at least " << 2 * std::numeric_limits<double>::epsilon() * gas.time()
               << ")";
          throw std::invalid_argument(text.str());
        }
      }
      done += gas.run(target - done, snapshots ? next_snapshot : std::numeric_limits<double>::infinity());
    }
    const GasMeasurement block = gas.measured();
    total_virial += block.virial;
    rate_excess += (block.compressibility_factor_from_collision_rate - 1) * block.time;
    r.time += block.time;
    r.cell_crossings += block.cell_crossings;
    r.list_rebuilds += block.list_rebuilds;
    const double temperature = gas.temperature();
    r.largest_temperature_change = std::max(r.largest_temperature_change, std::fabs(temperature - kT) / kT);
    Block row;
    row.time = gas.time() - start_time;
    row.collisions = block.collisions;
    row.compressibility_factor = block.compressibility_factor;
    row.pressure = block.compressibility_factor * density * block.temperature;
    row.temperature = temperature;
    const std::vector<Eigen::Matrix<double, D, 1>> now = gas.unwrapped_positions();
    long double squares = 0;
    for (std::size_t i = 0; i < now.size(); ++i) squares += static_cast<long double>((now[i] - start[i]).squaredNorm());
    row.mean_squared_displacement = static_cast<double>(squares / static_cast<long double>(now.size()));
    row.collision_rate = block.time > 0 ? 2 * static_cast<double>(block.collisions) / (n * block.time) : 0;
    r.blocks.push_back(row);
    if (block.time > 0 && block.collisions > 0) {
      z_blocks.push_back(block.compressibility_factor);
      p_blocks.push_back(row.pressure);
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
  r.pressure = r.compressibility_factor * density * kT;
  r.mean_free_time =
      done > 0 ? r.time * n / (2 * static_cast<double>(done)) : std::numeric_limits<double>::infinity();
  r.compressibility_factor_from_collision_rate = r.time > 0 ? 1 + rate_excess / r.time : 1;
  r.compressibility_factor_error = standard_error(z_blocks);
  r.pressure_error = standard_error(p_blocks);
  r.compressibility_factor_from_collision_rate_error = standard_error(rate_blocks);
  return r;
}

/// Runs and measures `gas` as above, without snapshots.
template <int D>
Result measure(Gas<D>& gas, const Options& options) {
  return measure(gas, options, [](const Gas<D>&) {});
}

/// Validates `options`, runs the lattice gas of its dimension and returns what it measured.
inline Result measure(const Options& options) {
  validate(options);
  if (options.dimension == 2) {
    Gas<2> gas(lattice<2>(options), options.max_events_without_collision, options.method);
    return measure(gas, options);
  }
  Gas<3> gas(lattice<3>(options), options.max_events_without_collision, options.method);
  return measure(gas, options);
}

}  // namespace gas
}  // namespace billiards::simulation
