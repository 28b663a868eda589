// What the gas's two engines (detail/gas_cells.hpp, detail/gas_lists.hpp) share: the clock, the balls'
// numbers in the setup, the periodic box and its cell grid, the event calendar, the measurements and
// the state as the caller sees it. Each engine keeps its own records of the balls and runs its own
// events; this base reads the records through the engine's accessors (CRTP).
#pragma once

#include <billiards/simulation/core/event_calendar.hpp>
#include <billiards/simulation/gas/setup.hpp>

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
#include <type_traits>
#include <vector>

namespace billiards::simulation::detail {

// The callback of a run without one.
struct NoCallback {
  void operator()(const GasEvent&) const {}
};

template <int D, class Engine>
class GasEngine {
 public:
  using Vector = Eigen::Matrix<double, D, 1>;

  template <typename OnCollision>
  std::uint64_t run_collisions(std::uint64_t count, OnCollision& on_collision) {
    return run_events(count, infinity, on_collision);
  }
  template <typename OnCollision>
  std::uint64_t run_until(double until, OnCollision& on_collision) {
    check_until("run_until", until, true);
    return run(std::numeric_limits<std::uint64_t>::max(), until, on_collision, "run_until");
  }
  template <typename OnCollision>
  std::uint64_t run(std::uint64_t count, double until, OnCollision& on_collision, const char* name = "run") {
    check_until(name, until, false);
    const std::uint64_t done = run_events(count, until, on_collision);
    if (done < count && until < infinity) now_ = until;
    return done;
  }

  void reset_measurements() {
    span_start_ = now_;
    span_collisions_ = collisions_;
    span_own_events_ = own_events_;
    virial_ = 0;
    rate_sum_ = 0;
    span_temperature_ = temperature();
  }
  GasMeasurement measured() const {
    GasMeasurement m;
    const double n = static_cast<double>(size()), kT = span_temperature_;
    m.time = now_ - span_start_;
    m.collisions = collisions_ - span_collisions_;
    (Engine::lists ? m.list_rebuilds : m.cell_crossings) = own_events_ - span_own_events_;
    m.virial = virial_;
    m.temperature = kT;
    if (m.time > 0 && kT > 0) {
      m.compressibility_factor = 1 + m.virial / (D * n * kT * m.time);
      if (m.collisions > 0) {
        m.compressibility_factor_from_collision_rate =
            1 + rate_sum_ * std::sqrt(2 * std::numbers::pi * kT) / (D * n * kT * m.time);
      }
    }
    m.mean_free_time = m.collisions > 0 ? m.time * n / (2 * static_cast<double>(m.collisions))
                                        : std::numeric_limits<double>::infinity();
    return m;
  }

  double energy() const {
    long double sum = 0;
    for (std::size_t i = 0; i < size(); ++i) {
      sum += static_cast<long double>(engine().mass_of(i)) *
             static_cast<long double>(engine().velocity(i).squaredNorm());
    }
    return static_cast<double>(sum / 2);
  }
  double temperature() const {
    long double sum = 0;
    for (std::size_t i = 0; i < size(); ++i) {
      sum += static_cast<long double>(engine().mass_of(i)) *
             static_cast<long double>(engine().velocity(i).squaredNorm());
    }
    return static_cast<double>(sum / (D * static_cast<long double>(size())));
  }
  Vector momentum() const {
    Eigen::Matrix<long double, D, 1> sum = Eigen::Matrix<long double, D, 1>::Zero();
    for (std::size_t i = 0; i < size(); ++i) {
      sum += static_cast<long double>(engine().mass_of(i)) * engine().velocity(i).template cast<long double>();
    }
    return sum.template cast<double>();
  }

  std::size_t size() const { return identity_.size(); }
  double side() const { return side_; }
  double radius() const { return radius_; }
  double mass() const { return mass_; }
  bool equal_balls() const { return equal_; }
  double time() const { return now_; }
  std::uint64_t collisions() const { return collisions_; }
  std::uint64_t own_events() const { return own_events_; }
  double largest_overlap() const { return largest_overlap_; }
  double largest_gap() const { return largest_gap_; }
  int cells_per_side() const { return cells_per_side_; }

  std::vector<double> radii() const {
    std::vector<double> out(size());
    for (std::size_t i = 0; i < out.size(); ++i) out[identity_[i]] = engine().radius_of(i);
    return out;
  }
  std::vector<double> masses() const {
    std::vector<double> out(size());
    for (std::size_t i = 0; i < out.size(); ++i) out[identity_[i]] = engine().mass_of(i);
    return out;
  }
  std::vector<Vector> positions() const {
    std::vector<Vector> out(size());
    for (std::size_t i = 0; i < out.size(); ++i) {
      Vector& p = out[identity_[i]];
      p = engine().position_now(i);
      for (int k = 0; k < D; ++k) p[k] = into_box(p[k]);
    }
    return out;
  }
  std::vector<Vector> unwrapped_positions() const {
    std::vector<Vector> out(size());
    for (std::size_t i = 0; i < out.size(); ++i) {
      out[identity_[i]] = engine().position_now(i) + side_ * wraps_[i].template cast<double>();
    }
    return out;
  }
  std::vector<Vector> velocities() const {
    std::vector<Vector> out(size());
    for (std::size_t i = 0; i < out.size(); ++i) out[identity_[i]] = engine().velocity(i);
    return out;
  }
  GasSetup<D> setup() const {
    GasSetup<D> out{side_, radius_, mass_, std::vector<simulation::Ball<D>>(size()), {}, {}};
    const std::vector<Vector> p = positions(), v = velocities();
    for (std::size_t i = 0; i < p.size(); ++i) out.balls[i] = {p[i], v[i]};
    if (!equal_ || engine().radius_of(0) != radius_ || engine().mass_of(0) != mass_) {
      out.radii = radii();
      out.masses = masses();
    }
    return out;
  }
  Vector nearest_image(const Vector& a, const Vector& b) const {
    Vector p = b - a;
    for (int k = 0; k < D; ++k) {
      if (p[k] > side_ / 2) p[k] -= side_;
      if (p[k] < -side_ / 2) p[k] += side_;
    }
    return p;
  }

 protected:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  static constexpr double infinity = std::numeric_limits<double>::infinity();
  using Cell = Eigen::Matrix<int, D, 1>;
  using Wraps = Eigen::Matrix<std::int64_t, D, 1>;

  // Takes what every engine keeps of `setup` (validated by Gas): the box, the balls' numbers, the limit
  // on events without a collision.
  GasEngine(const GasSetup<D>& setup, std::uint64_t max_events_without_collision)
      : radius_(setup.radius), mass_(setup.mass), side_(setup.side), equal_(setup.equal_balls()) {
    const std::size_t n = setup.balls.size();
    quiet_limit_ = max_events_without_collision != 0 ? max_events_without_collision
                                                     : 1000000 + 100 * static_cast<std::uint64_t>(n);
    identity_.resize(n);
    for (std::size_t i = 0; i < n; ++i) identity_[i] = static_cast<std::uint32_t>(i);
    wraps_.assign(n, Wraps::Zero());
  }

  // Runs the engine's events (its run_all) until `collisions` more collisions or until the next event
  // lies beyond `until`. From Engine::look_ahead_from balls, beyond the caches, the engine's loop that
  // asks memory ahead, compiled as one function with everything it calls inlined (flatten) and kept
  // out of the loop of smaller gases. That function is large, so it is compiled twice at most: for a
  // run without a callback, and for every callback behind a pointer (an indirect call a collision,
  // beside the microsecond a collision costs there), not once for each caller's type.
  template <typename OnCollision>
  std::uint64_t run_events(std::uint64_t collisions, double until, OnCollision& on_collision) {
    if (size() < Engine::look_ahead_from)
      return engine().template run_all<false>(collisions, until, on_collision);
    if constexpr (std::is_same_v<std::remove_cv_t<OnCollision>, NoCallback>) {
      return run_beyond_caches(collisions, until, on_collision);
    } else {
      auto forward = [&on_collision](const GasEvent& e) { on_collision(e); };
      const auto call = [](void* f, const GasEvent& e) { (*static_cast<decltype(forward)*>(f))(e); };
      ErasedCallback erased{&forward, call};
      return run_beyond_caches(collisions, until, erased);
    }
  }
  // A callback behind a pointer: `call(callback, event)`.
  struct ErasedCallback {
    void* callback;
    void (*call)(void*, const GasEvent&);
    void operator()(const GasEvent& event) const { call(callback, event); }
  };
  // Defined below the class, not inline, so that a program may take the loops compiled once (gas.hpp's
  // end, BILLIARDS_GAS_LOOPS_COMPILED) instead of compiling them itself.
  template <typename OnCollision>
  [[gnu::noinline, gnu::flatten]] std::uint64_t run_beyond_caches(std::uint64_t collisions, double until,
                                                                  OnCollision& on_collision);

  // After a collision: every N collisions the calendar's width fitted to the times again, and from
  // reorder_from balls the balls renumbered by cell (the engine's reorder, which refiles).
  void refile_now_and_then() {
    if (++since_refile_ < size()) return;
    since_refile_ = 0;
    if (size() >= reorder_from)
      engine().reorder();
    else
      refile();
  }
  static constexpr std::size_t reorder_from = 4096;  ///< fewer balls stay in the caches anyway

  // Throws std::invalid_argument where `until` is NaN, earlier than now or (`finite`) infinite.
  void check_until(const char* name, double until, bool finite) const {
    if (!(until >= now_) || (finite && !std::isfinite(until))) {
      std::ostringstream text;
      text << "billiards::simulation::Gas::" << name << ": until is " << until << ", expected a "
           << (finite ? "finite " : "") << "time at or after " << now_ << " (the gas's time now)";
      throw std::invalid_argument(text.str());
    }
  }

  Engine& engine() { return static_cast<Engine&>(*this); }
  const Engine& engine() const { return static_cast<const Engine&>(*this); }

  // A coordinate taken into [0, side): fmod is exact, so a coordinate inside is kept bit for bit and
  // one far outside (−1.02e17 in a box of 5) lands inside too; −1e-20 + side rounds to side itself.
  double into_box(double x) const {
    x = std::fmod(x, side_);
    if (x < 0) x += side_;
    return x < side_ ? x : 0;
  }

  // The cell grid, `per_side` cells a side, numbered in tiles of tile^D cells: tile after tile, the
  // first axis fastest, and within a tile the first axis fastest too. A ball's neighbourhood then spans
  // few tiles, whose list heads share cache lines and whose balls (renumbered by cell) lie near one
  // another in memory. The number is a sum of one term an axis, axis_offset_[k][c_k], so the cells
  // around a ball come from three terms an axis. Tiles at the far edges may be partial: their missing
  // cells keep numbers that no ball ever takes.
  void lay_out_cells(int per_side) {
    cells_per_side_ = per_side;
    cell_width_ = side_ / per_side;
    const std::size_t cells = static_cast<std::size_t>(per_side);
    const std::size_t tiles = (cells + tile - 1) / tile;
    std::size_t tile_cells = 1, count = 1;
    for (int k = 0; k < D; ++k) tile_cells *= tile, count *= tiles * tile;
    if (count >= none) throw std::invalid_argument("Gas<D>: more cells than 32-bit numbers");
    std::size_t tile_stride = tile_cells, inner_stride = 1;
    for (int k = 0; k < D; ++k) {
      axis_offset_[k].resize(cells);
      for (std::size_t c = 0; c < cells; ++c)
        axis_offset_[k][c] = static_cast<std::uint32_t>(c / tile * tile_stride + c % tile * inner_stride);
      tile_stride *= tiles;
      inner_stride *= tile;
    }
    head_.assign(count, none);
  }
  // A cell coordinate at most two cells beyond the box, wrapped into it (every box is at least three
  // cells wide, so one turn is enough).
  int wrapped(int x) const { return x < 0 ? x + cells_per_side_ : x >= cells_per_side_ ? x - cells_per_side_ : x; }
  // The cell coordinate of a coordinate in [0, side).
  int coordinate_cell(double x) const { return std::min(cells_per_side_ - 1, static_cast<int>(x / cell_width_)); }
  Cell cell_coordinates(const Vector& x) const {
    Cell c;
    for (int k = 0; k < D; ++k) c[k] = coordinate_cell(x[k]);
    return c;
  }
  std::size_t cell_index(const Cell& c) const {
    std::size_t index = 0;
    for (int k = 0; k < D; ++k) index += axis_offset_[k][static_cast<std::size_t>(c[k])];
    return index;
  }

  // Files every ball's next event in the calendar anew, its bucket width chosen from the times now.
  void refile() {
    event_times_.resize(size());
    for (std::size_t i = 0; i < event_times_.size(); ++i) event_times_[i] = engine().event_time(i);
    calendar_.reset(event_times_, now_);
  }

  // The largest overlap and gap, from a collision's centres `distance` apart, `contact` the sum of the
  // radii.
  void measure_contact(double distance, double contact) {
    largest_overlap_ = std::max(largest_overlap_, (contact - distance) / contact);
    largest_gap_ = std::max(largest_gap_, (distance - contact) / contact);
  }
  // A collision counted: the virial term of ball i's change of velocity `change` (mass mi) along
  // `separation` = x_i − x_j at contact, and the collision-rate term σ_ij √μ_ij.
  void count_collision(const Vector& separation, const Vector& change, double mi, double mj, double contact) {
    virial_ += mi * separation.dot(change);
    rate_sum_ += contact * std::sqrt(mi * mj / (mi + mj));
    ++collisions_;
  }
  // Counts an event; throws EventLimitReached when there have been too many in a row without a collision.
  void count_quiet(std::uint64_t& quiet) const {
    if (++quiet > quiet_limit_) {
      throw EventLimitReached("billiards::simulation::Gas: stopped after " + std::to_string(quiet_limit_) +
                              " events in a row without a collision: the balls' paths do not meet");
    }
  }

  double radius_ = 0.5, mass_ = 1;
  double side_ = 0, cell_width_ = 0, now_ = 0;
  bool equal_ = true;
  std::uint64_t quiet_limit_ = 0;
  int cells_per_side_ = 0;
  static constexpr std::size_t tile = 4;       ///< cells a tile has along each axis
  std::vector<std::uint32_t> axis_offset_[D];  ///< cell_index's term for each axis and coordinate
  detail::Array<std::uint32_t> head_;          ///< each cell's first ball (a tile's heads share cache lines)
  detail::Array<std::uint32_t> identity_;      ///< each ball's index in the setup (the balls are renumbered)
  std::vector<Wraps> wraps_;                   ///< the box sides each ball has crossed along each axis
  std::vector<double> event_times_;            ///< kept between refiles, which then touch no fresh memory
  EventCalendar calendar_;
  std::uint64_t collisions_ = 0, own_events_ = 0, since_refile_ = 0;
  std::uint64_t collision_number_ = 0;  ///< collisions resolved so far, every event's included
  // Σ r_ij·Δp_i and Σ σ_ij √μ_ij over the span's collisions, and where the span began.
  double virial_ = 0, rate_sum_ = 0, span_start_ = 0, span_temperature_ = 0;
  std::uint64_t span_collisions_ = 0, span_own_events_ = 0;
  double largest_overlap_ = 0, largest_gap_ = 0;
};

template <int D, class Engine>
template <typename OnCollision>
std::uint64_t GasEngine<D, Engine>::run_beyond_caches(std::uint64_t collisions, double until,
                                                      OnCollision& on_collision) {
  return engine().template run_all<true>(collisions, until, on_collision);
}

}  // namespace billiards::simulation::detail
