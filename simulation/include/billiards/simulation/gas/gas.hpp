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

#include <billiards/simulation/gas/cells.hpp>
#include <billiards/simulation/gas/lists.hpp>
#include <billiards/simulation/gas/setup.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
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

/// A D-dimensional hard-sphere gas: built from a GasSetup, run collision by collision (step), for a
/// number of collisions (run_events) or until a time (run_until), each collision reported to an
/// optional callback: the engines' common vocabulary (docs/simulations.md). The engine's own events
/// (cell crossings, list rebuilds) are not reported: an event of the gas is a collision.
template <int D>
class Gas {
 public:
  /// A position or a velocity.
  using Vector = Eigen::Matrix<double, D, 1>;

  /// Validates `setup` (see validate(const GasSetup<D>&)) and predicts every ball's first event, on the
  /// engine `method` names (GasMethod::cells with unequal balls: std::invalid_argument). A run stops with
  /// EventLimitReached after `max_events_without_collision` events in a row without a collision (0:
  /// 10^6 + 100 N), so that balls whose paths never meet cannot run forever.
  explicit Gas(const GasSetup<D>& setup, std::uint64_t max_events_without_collision = 0,
               GasMethod method = GasMethod::automatic)
      : engine_(make(setup, max_events_without_collision, method)) {}

  /// Runs the next collision and returns it; empty when no ball has an event left (every ball at rest).
  /// Throws EventLimitReached as run_events does.
  std::optional<GasEvent> step() {
    std::optional<GasEvent> event;
    run_events(1, [&](const GasEvent& e) { event = e; });
    return event;
  }

  /// Runs at most `count` more collisions, calling `on_event(const GasEvent&)` after each, and returns
  /// how many ran: fewer than `count` only when no ball has an event left. Throws EventLimitReached after
  /// too many events in a row without a collision (see the constructor).
  template <typename OnEvent>
  std::uint64_t run_events(std::uint64_t count, OnEvent&& on_event) {
    return std::visit([&](auto& e) { return e.run_collisions(count, on_event); }, engine_);
  }
  /// Runs at most `count` more collisions; see the overload with a callback.
  std::uint64_t run_events(std::uint64_t count) { return run_events(count, detail::NoCallback{}); }

  /// Runs until `count` more collisions or the gas's time `until` (+∞: no limit), whichever comes first,
  /// calling `on_event(const GasEvent&)` after each collision; where it stops at `until`, that is the
  /// time now. Returns the number of collisions run. Throws std::invalid_argument when `until` is NaN or
  /// earlier than time(), and EventLimitReached as run_events does.
  template <typename OnEvent>
  std::uint64_t run(std::uint64_t count, double until, OnEvent&& on_event) {
    return std::visit([&](auto& e) { return e.run(count, until, on_event); }, engine_);
  }
  /// Runs until `count` more collisions or the time `until`; see the overload with a callback.
  std::uint64_t run(std::uint64_t count, double until) { return run(count, until, detail::NoCallback{}); }

  /// Runs every collision up to the gas's time `until`, calling `on_event(const GasEvent&)` after each,
  /// and makes `until` the time now; returns the number of collisions run. Throws std::invalid_argument
  /// when `until` is NaN, infinite or earlier than time(), and EventLimitReached as run_events does.
  template <typename OnEvent>
  std::uint64_t run_until(double until, OnEvent&& on_event) {
    return std::visit([&](auto& e) { return e.run_until(until, on_event); }, engine_);
  }
  /// Runs every collision up to the gas's time `until`; see the overload with a callback.
  std::uint64_t run_until(double until) { return run_until(until, detail::NoCallback{}); }

  /// Starts a new span of measurement at the time now (see measured()).
  void reset_measurements() {
    std::visit([](auto& e) { e.reset_measurements(); }, engine_);
  }
  /// What was measured from the construction, or the last reset_measurements(), to now.
  GasMeasurement measured() const { return visit([](const auto& e) { return e.measured(); }); }
  /// The kinetic energy Σ ½ m v², summed in long double.
  double energy() const { return visit([](const auto& e) { return e.energy(); }); }
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
  /// The events reported since the construction: the collisions (collisions()).
  std::uint64_t event_count() const { return collisions(); }
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
  /// Every ball now, in the setup's order: its position in [0, side) along each axis and its velocity.
  std::vector<Ball<D>> balls() const {
    const std::vector<Vector> p = positions(), v = velocities();
    std::vector<Ball<D>> out(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) out[i] = {p[i], v[i]};
    return out;
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

  Engine engine_;
};

}  // namespace billiards::simulation

// Where BILLIARDS_GAS_LOOPS_COMPILED is defined, the engines' loops beyond the caches (the largest code
// of the gas: GasEngine::run_beyond_caches, everything it calls inlined) are not compiled here but
// taken from an object that compiles them once (the project's own programs and tests link
// billiards_gas_loops, simulation/gas_loops.cpp, which defines it for them). Nothing changes elsewhere.
#if defined(BILLIARDS_GAS_LOOPS_COMPILED)
namespace billiards::simulation::detail {
extern template std::uint64_t GasEngine<2, CellGas<2>>::run_beyond_caches(std::uint64_t, double, NoCallback&);
extern template std::uint64_t GasEngine<3, CellGas<3>>::run_beyond_caches(std::uint64_t, double, NoCallback&);
extern template std::uint64_t GasEngine<2, ListGas<2>>::run_beyond_caches(std::uint64_t, double, NoCallback&);
extern template std::uint64_t GasEngine<3, ListGas<3>>::run_beyond_caches(std::uint64_t, double, NoCallback&);
extern template std::uint64_t GasEngine<2, CellGas<2>>::run_beyond_caches(
    std::uint64_t, double, GasEngine<2, CellGas<2>>::ErasedCallback&);
extern template std::uint64_t GasEngine<3, CellGas<3>>::run_beyond_caches(
    std::uint64_t, double, GasEngine<3, CellGas<3>>::ErasedCallback&);
extern template std::uint64_t GasEngine<2, ListGas<2>>::run_beyond_caches(
    std::uint64_t, double, GasEngine<2, ListGas<2>>::ErasedCallback&);
extern template std::uint64_t GasEngine<3, ListGas<3>>::run_beyond_caches(
    std::uint64_t, double, GasEngine<3, ListGas<3>>::ErasedCallback&);
}  // namespace billiards::simulation::detail
#endif
