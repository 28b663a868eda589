/// \file
/// An event-driven billiards table on billiards::runtime: N equal balls on a rectangular table with
/// cushions. No time stepping: the table jumps from one contact to the next, the earliest ball–ball
/// contact (billiards::time_of_impact, the emitted kernel of audit claims beyond.time_of_impact.*) or
/// ball–cushion contact, and resolves it exactly there — billiards::collide_if_approaching for two
/// balls (so rounding can never make a separating pair collide again) and billiards::collide with an
/// infinite mass for a cushion (the immovable-body form). No velocity is ever corrected.
///
/// Cost: each event re-predicts the one or two balls it changed against every other ball, O(N) per
/// event (all-pairs prediction), plus O(log E) for the event queue and O(N) to move every ball to the
/// event's time (docs/simulations.md).
#pragma once

#include <billiards/simulation/core/errors.hpp>
#include <billiards/simulation/core/event_queue.hpp>
#include <billiards/simulation/table/setup.hpp>

#include <billiards/collision.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace billiards::simulation {

/// What an event of the table was.
struct TableEvent {
  /// A contact of two balls, or of a ball and a cushion.
  enum class Kind { ball, cushion };
  double time = 0;         ///< the table time of the event, in seconds since the start
  Kind kind = Kind::ball;  ///< what the ball met
  std::size_t first = 0;   ///< a ball (its index in the setup)
  std::size_t second = 0;  ///< the other ball, or the cushion: 0 left, 1 right, 2 bottom, 3 top
  bool resolved = false;   ///< velocities changed (an approaching contact)
};

/// The name of a table event's kind: "ball", "cushion".
inline const char* kind_name(TableEvent::Kind kind) noexcept {
  return kind == TableEvent::Kind::ball ? "ball" : "cushion";
}

/// The event-driven table: built from a TableSetup, run event by event (step), for a number of events
/// (run_events) or until a time (run_until), each event reported to an optional callback: the engines'
/// common vocabulary (docs/simulations.md).
class Table {
 public:
  /// Validates `setup` (std::invalid_argument on a bad one, naming the ball, the value and what was
  /// expected) and predicts every ball's first event. `check_every_pair`: after each event, check every
  /// pair of balls for overlap (O(N²) per event); otherwise only the balls of the event against all
  /// others (O(N)).
  explicit Table(TableSetup setup, bool check_every_pair = true)
      : setup_(std::move(setup)),
        check_every_pair_(check_every_pair),
        collisions_(setup_.balls.size(), 0),
        predictions_(setup_.balls.size(), 0) {
    validate(setup_);
    for (std::size_t i = 0; i < setup_.balls.size(); ++i) predict(i);
  }

  /// Moves every ball to the next event, resolves it and returns it; empty when no event can happen any
  /// more (every ball at rest, or too slow for any event to fall within the largest finite time: see
  /// why_no_event()). Throws BrokenInvariant if, after it, two balls overlap by more than
  /// overlap_tolerance of a radius or a ball has left the table.
  std::optional<TableEvent> step() {
    if (!next_event_is_due()) return std::nullopt;
    return resolve_next();
  }

  /// Runs at most `count` events, calling `on_event(const TableEvent&)` after each (the balls then at
  /// the event's time), and returns how many ran: fewer than `count` only when no event can happen
  /// any more. Throws BrokenInvariant as step() does.
  template <typename OnEvent>
  std::uint64_t run_events(std::uint64_t count, OnEvent&& on_event) {
    std::uint64_t done = 0;
    for (; done < count && next_event_is_due(); ++done) on_event(resolve_next());
    return done;
  }
  /// Runs at most `count` events; see the overload with a callback.
  std::uint64_t run_events(std::uint64_t count) {
    return run_events(count, [](const TableEvent&) {});
  }

  /// Runs every event up to table time `until` (seconds since the start), calling
  /// `on_event(const TableEvent&)` after each, then moves every ball on to `until`; returns how many
  /// events ran. Throws std::invalid_argument when `until` is NaN, earlier than time() or more than the
  /// largest finite double of seconds after it, and BrokenInvariant as step() does.
  template <typename OnEvent>
  std::uint64_t run_until(double until, OnEvent&& on_event) {
    // Within the largest finite step of now: a run to any time ends, one step of free flight at most.
    const long double largest_step = std::numeric_limits<double>::max();
    if (!(until >= elapsed_) || !(static_cast<long double>(until) - elapsed_ <= largest_step)) {
      std::ostringstream text;
      text << "billiards::simulation::Table::run_until: until is " << until << ", expected a time from "
           << elapsed_ << " s (the table's time now) to " << largest_step << " s after it";
      throw std::invalid_argument(text.str());
    }
    std::uint64_t done = 0;
    while (next_event_is_due() && elapsed_ + static_cast<long double>(queue_.top().time) <= until) {
      on_event(resolve_next());
      ++done;
    }
    // No event before `until`: every ball moves freely to it.
    advance_by(static_cast<double>(until - elapsed_));
    elapsed_ = until;
    return done;
  }
  /// Runs every event up to table time `until`; see the overload with a callback.
  std::uint64_t run_until(double until) {
    return run_until(until, [](const TableEvent&) {});
  }

  /// Table time since the start, in seconds. Summed in long double, rounded to double here: slow balls
  /// on a large table pass the largest double (a table of 1e300 m crossed at 1e-7 m/s reaches the
  /// largest double in 20 000 events), and the table runs on.
  double time() const { return static_cast<double>(elapsed_); }
  /// Table time since the start, in seconds, as summed: in long double, finite where time() has reached
  /// +∞ (past the largest double).
  long double precise_time() const { return elapsed_; }
  /// The setup, its balls at the table's time now.
  const TableSetup& setup() const { return setup_; }
  /// The balls at the table's time now: centres and velocities.
  const std::vector<Ball<2>>& balls() const { return setup_.balls; }
  /// Events processed, including contacts that were already separating (nothing to resolve).
  std::uint64_t event_count() const { return events_; }
  /// Ball–ball contacts resolved (the balls approached and their velocities changed).
  std::uint64_t ball_collisions() const { return ball_collisions_; }
  /// Ball–cushion contacts resolved.
  std::uint64_t cushion_collisions() const { return cushion_collisions_; }
  /// The largest overlap seen at any event so far, as a fraction of the radius (0 if none).
  double largest_overlap() const { return largest_overlap_; }

  /// The kinetic energy Σ ½ m v² (J), summed in long double so that the sum adds no rounding of its
  /// own to the drift.
  double energy() const {
    long double sum = 0;
    for (const Ball<2>& ball : setup_.balls)
      sum += 0.5L * setup_.mass * ball.velocity.cast<long double>().squaredNorm();
    return static_cast<double>(sum);
  }

  /// Why step() finds no event: every ball at rest, or each moving ball's next event further away than
  /// the largest finite time (1e-300 m/s on a table of 1e300 m), which the predictions take as never.
  /// Empty while an event is due.
  std::string why_no_event() {
    return next_event_is_due() ? std::string() : no_event_reason();
  }

 private:
  // Drops superseded predictions from the top of the queue; true when a valid one is left there.
  bool next_event_is_due() {
    while (!queue_.empty()) {
      const Prediction& top = queue_.top();
      if (top.serial == predictions_[top.ball] &&
          !(top.partner_is_ball && top.partner_collisions != collisions_[top.partner])) {
        return true;
      }
      const Prediction stale = queue_.pop();
      // The partner moved differently since: predict this ball again (a superseded one has a newer).
      if (stale.serial == predictions_[stale.ball]) predict(stale.ball);
    }
    return false;
  }

  // Resolves the prediction at the top of the queue (valid: next_event_is_due()).
  TableEvent resolve_next() {
    const Prediction next = queue_.pop();
    advance_by(next.time);
    TableEvent event;
    event.time = static_cast<double>(elapsed_);
    event.first = next.ball;
    event.second = next.partner;
    if (next.partner_is_ball) {
      Ball<2>& a = setup_.balls[next.ball];
      Ball<2>& b = setup_.balls[next.partner];
      const auto [x1, x2] = billiards::collide_if_approaching(setup_.mass, a.position, a.velocity,
                                                              setup_.mass, b.position, b.velocity);
      event.resolved = x1 != a.velocity || x2 != b.velocity;
      a.velocity = x1;
      b.velocity = x2;
      if (event.resolved) ++ball_collisions_;
    } else {
      event.kind = TableEvent::Kind::cushion;
      Ball<2>& a = setup_.balls[next.ball];
      const TableVector n = cushion_normal(next.partner);
      const double wall = std::numeric_limits<double>::infinity();
      if (a.velocity.dot(n) < 0) {  // approaching the cushion
        a.velocity = billiards::collide(setup_.mass, a.velocity, wall, TableVector::Zero().eval(), n).first;
        event.resolved = true;
        ++cushion_collisions_;
      }
    }
    ++events_;
    ++collisions_[next.ball];
    predict(next.ball);
    if (next.partner_is_ball) {
      ++collisions_[next.partner];
      predict(next.partner);
    }
    check(event);
    return event;
  }

  struct Prediction {
    double time;
    std::size_t ball;
    std::size_t partner;
    bool partner_is_ball;
    std::uint64_t serial;              ///< the ball's prediction it belongs to
    std::uint64_t partner_collisions;  ///< the partner's collision count when predicted
    bool operator>(const Prediction& other) const { return time > other.time; }
  };

  static TableVector cushion_normal(std::size_t cushion) {
    switch (cushion) {
      case 0: return TableVector(1, 0);    // left cushion, pointing into the table
      case 1: return TableVector(-1, 0);   // right
      case 2: return TableVector(0, 1);    // bottom
      default: return TableVector(0, -1);  // top
    }
  }

  // The ball's earliest event from now: against every other ball and the four cushions.
  void predict(std::size_t i) {
    const Ball<2>& ball = setup_.balls[i];
    const double r = setup_.radius;
    Prediction best{std::numeric_limits<double>::infinity(), i, 0, false, ++predictions_[i], 0};
    const auto consider = [&](double dt, std::size_t partner, bool is_ball) {
      if (dt < best.time) {
        best.time = dt;
        best.partner = partner;
        best.partner_is_ball = is_ball;
        best.partner_collisions = is_ball ? collisions_[partner] : 0;
      }
    };
    for (std::size_t j = 0; j < setup_.balls.size(); ++j) {
      if (j == i) continue;
      const Ball<2>& other = setup_.balls[j];
      consider(billiards::time_of_impact(ball.position, ball.velocity, other.position, other.velocity, 2 * r),
               j, true);
    }
    // A cushion is met when the centre is a radius from it, moving towards it.
    const double limits[4] = {r, setup_.width - r, r, setup_.height - r};
    for (std::size_t cushion = 0; cushion < 4; ++cushion) {
      const int axis = cushion < 2 ? 0 : 1;
      const double speed = ball.velocity[axis], distance = limits[cushion] - ball.position[axis];
      const bool towards = cushion % 2 == 0 ? speed < 0 : speed > 0;
      if (towards) consider(std::max(0.0, distance / speed), cushion, false);
    }
    if (std::isfinite(best.time)) queue_.push(best);
  }

  // Moves every ball by dt and makes now the origin of the queue's times. Predictions are kept
  // relative to the last event: absolute times would grow without bound and, at 10^5 s of table time,
  // round by more than a ball moves in 1e-9 of a radius. Subtracting one number from every key keeps
  // the heap ordered.
  void advance_by(double dt) {
    for (Ball<2>& ball : setup_.balls) ball.position += dt * ball.velocity;
    queue_.change_all([dt](Prediction& prediction) { prediction.time = std::max(0.0, prediction.time - dt); });
    elapsed_ += dt;
  }

  // Why the queue is empty: every ball at rest, or each moving ball's next event further away than the
  // largest finite time (1e-300 m/s on a table of 1e300 m), which the predictions take as never.
  std::string no_event_reason() const {
    const bool at_rest = std::all_of(setup_.balls.begin(), setup_.balls.end(),
                                     [](const Ball<2>& ball) { return ball.velocity.isZero(0); });
    if (at_rest) return "no event will ever happen: every ball is at rest";
    std::ostringstream text;
    text << "no event will ever happen: every moving ball's next cushion or ball lies further away than "
         << std::numeric_limits<double>::max() << " s (the balls are too slow for the table)";
    return text.str();
  }

  // No two balls overlap by more than overlap_tolerance of a radius, and every ball is on the table.
  void check(const TableEvent& event) {
    const double r = setup_.radius, allowed = overlap_tolerance * r;
    const std::size_t count = setup_.balls.size();
    const auto check_pair = [&](std::size_t i, std::size_t j) {
      const double depth = overlap(setup_, i, j);
      largest_overlap_ = std::max(largest_overlap_, depth / r);
      if (depth > allowed) {
        std::ostringstream text;
        text << "balls " << i << " and " << j << " overlap by " << depth / r
             << " of a radius at t = " << time() << " (event " << events_ << "), more than "
             << overlap_tolerance;
        throw BrokenInvariant(text.str());
      }
    };
    for (std::size_t i = 0; i < count; ++i) {
      const bool involved = i == event.first || (event.kind == TableEvent::Kind::ball && i == event.second);
      if (!check_every_pair_ && !involved) continue;
      for (std::size_t j = 0; j < count; ++j) {
        if (j != i && (check_every_pair_ ? j > i : true)) check_pair(i, j);
      }
      const TableVector& p = setup_.balls[i].position;
      if (!on_table(setup_, p, allowed)) {
        std::ostringstream text;
        text << "ball " << i << " left the table at t = " << time() << ": (" << p.x() << ", " << p.y() << ")";
        throw BrokenInvariant(text.str());
      }
    }
  }

  TableSetup setup_;
  bool check_every_pair_;
  long double elapsed_ = 0;
  std::vector<std::uint64_t> collisions_;   ///< per ball: how often its velocity was resolved
  std::vector<std::uint64_t> predictions_;  ///< per ball: the serial of its current prediction
  detail::EventHeap<Prediction> queue_;     ///< predictions, their times relative to the last event
  std::uint64_t events_ = 0;
  std::uint64_t ball_collisions_ = 0;
  std::uint64_t cushion_collisions_ = 0;
  double largest_overlap_ = 0;
};

}  // namespace billiards::simulation
