/// \file
/// A shot on a pool table, played event by event from the cue to rest: no time stepping. Each ball moves
/// by its phase's closed form on the cloth (billiards::evolve: sliding, rolling, spinning, at rest), with a
/// constant horizontal acceleration within a phase (evolution.hpp), so that each contact's time is the
/// earliest root of a derived event polynomial (detection.hpp). Events: the cue strike, ball–ball and
/// ball–cushion and ball–jaw contacts (resolution.hpp), ball–pocket (the ball leaves play) and each
/// phase's end. After an event only the balls it changed are predicted again. This class keeps the loop
/// and the bookkeeping: the balls' reference states, the predictions, the history.
#pragma once

#include <billiards/simulation/core/errors.hpp>
#include <billiards/simulation/core/event_queue.hpp>
#include <billiards/simulation/core/invariants.hpp>
#include <billiards/simulation/shot/checks.hpp>
#include <billiards/simulation/shot/detection.hpp>
#include <billiards/simulation/shot/event.hpp>
#include <billiards/simulation/shot/evolution.hpp>
#include <billiards/simulation/shot/history.hpp>
#include <billiards/simulation/shot/pool_table.hpp>
#include <billiards/simulation/shot/pressing.hpp>
#include <billiards/simulation/shot/resolution.hpp>

#include <billiards/cloth.hpp>
#include <billiards/shot.hpp>
#include <billiards/spin.hpp>

#include <Eigen/Core>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace billiards::simulation {

namespace detail {

/// A body a shot's prediction leaves out at t = 0: the one of a contact that changed nothing (its bodies no
/// longer approached), which the same rounding would otherwise report again at once.
struct ExcludedContact {
  ShotEvent::Kind kind = ShotEvent::Kind::strike;  ///< the body's kind (strike: none)
  std::size_t index = 0;                           ///< the body's index
  /// Whether a contact with body `other` of kind `k` at `t` from now is the one left out.
  [[nodiscard]] bool operator()(ShotEvent::Kind k, std::size_t other, double t) const {
    return t == 0 && k == kind && other == index;
  }
};

/// A ball as a shot keeps it: its reference state and phase, and what its predictions covered.
struct ShotBall {
  BallOnCloth<double> state;                                   ///< at time `since`
  double since = 0;                                            ///< the reference time (s)
  shot::Phase phase;                                           ///< of `state`
  bool pocketed = false;      ///< out of play
  std::uint64_t version = 0;  ///< how often it changed: a prediction of an older version is stale
  shot::PressedPiece piece;                   ///< where phase.pressed: the pressed piece's rest
  std::optional<shot::PressedStart> next;     ///< the pressed piece it begins at its next change
  std::optional<Motion> unrecorded_from;      ///< a change of motion at its partner's event, to be recorded
  billiards::detail::Slip<double> slip{Eigen::Vector3d::Zero(), 0};  ///< of `state` (a free phase's)
  double spin_end = std::numeric_limits<double>::infinity();  ///< when the spin about ẑ of `state` stops
};

/// What each ball's predictions covered, kept apart from the balls' states, a field at a time (one
/// array each), so that the pairs' first test reads these alone and runs over many balls at once: the
/// range of its centre from its last prediction to their end (a shot::Box), their end (absolute time),
/// whether it is a candidate for a pair (in play) and whether it moves (a ball at rest meets only
/// moving ones).
class ShotReaches {
 public:
  // Eight entries at a time from any first one: the arrays end with seven entries that are no
  // candidates.
  explicit ShotReaches(std::size_t balls = 0)
      : stride_(balls + 7), bounds_(5 * stride_, 0), flags_(2 * stride_, 0) {
    std::fill_n(bounds_.begin() + 4 * stride_, stride_, std::numeric_limits<double>::infinity());
  }
  void assign(std::size_t i, const shot::Box& box, double end, bool candidate, bool moving) {
    bounds_[i] = box.x_low;
    bounds_[stride_ + i] = box.x_high;
    bounds_[2 * stride_ + i] = box.y_low;
    bounds_[3 * stride_ + i] = box.y_high;
    bounds_[4 * stride_ + i] = end;
    flags_[i] = candidate;
    flags_[stride_ + i] = moving;
  }
  [[nodiscard]] shot::Box box(std::size_t i) const {
    return {bounds_[i], bounds_[stride_ + i], bounds_[2 * stride_ + i], bounds_[3 * stride_ + i]};
  }
  [[nodiscard]] double end(std::size_t i) const { return bounds_[4 * stride_ + i]; }
  /// A bit for each ball from `base` on, `count` (at most 64, to the last ball) of them: whether its box
  /// overlaps `reach` (shot::Box::overlaps), it is a candidate, it moves or `moving` does, and its
  /// predictions reach `now`, without a branch, eight balls at a time.
  [[nodiscard]] std::uint64_t near(const shot::Box& reach, bool moving, double now, std::size_t base,
                                   std::size_t count) const {
    static_assert(std::endian::native == std::endian::little, "the flags are read as little-endian words");
    const std::uint64_t any = moving ? 0x0101010101010101ull : 0;
    const std::uint8_t *candidate = flags_.data(), *moves = candidate + stride_;
    std::uint64_t bits = 0;
    for (std::size_t w = 0; 8 * w < count; ++w) {
      const std::size_t j = base + 8 * w;
      // The eight balls' flags (0 or 1, a byte each) read as one word, little end first; the multiply
      // gathers their low bits into its top byte (no carries: each of its bits is the sum of one term).
      std::uint64_t candidates = 0, moving_ones = 0;
      std::memcpy(&candidates, candidate + j, 8);
      std::memcpy(&moving_ones, moves + j, 8);
      const std::uint64_t flags = candidates & (moving_ones | any);
      bits |= (((flags * 0x0102040810204080ull) >> 56) & reaching(reach, now, j)) << (8 * w);
    }
    return bits;
  }

 private:
  // A bit for each of the eight entries from j: whether its box overlaps `reach` and its end is at or
  // after `now`; two entries at a time where the processor compares pairs of doubles (every x86-64),
  // the bits then gathered from the comparisons' sign bits, which are the same comparisons.
  [[nodiscard]] std::uint64_t reaching(const shot::Box& reach, double now, std::size_t j) const {
    const double *x_low = bounds_.data() + j, *x_high = x_low + stride_, *y_low = x_high + stride_,
                 *y_high = y_low + stride_, *end = y_high + stride_;
    std::uint64_t bits = 0;
#if defined(__SSE2__)
    const __m128d reach_x_low = _mm_set1_pd(reach.x_low), reach_x_high = _mm_set1_pd(reach.x_high),
                  reach_y_low = _mm_set1_pd(reach.y_low), reach_y_high = _mm_set1_pd(reach.y_high),
                  from = _mm_set1_pd(now);
    for (std::size_t k = 0; k < 8; k += 2) {
      __m128d m = _mm_cmple_pd(_mm_loadu_pd(x_low + k), reach_x_high);
      m = _mm_and_pd(m, _mm_cmple_pd(reach_x_low, _mm_loadu_pd(x_high + k)));
      m = _mm_and_pd(m, _mm_cmple_pd(_mm_loadu_pd(y_low + k), reach_y_high));
      m = _mm_and_pd(m, _mm_cmple_pd(reach_y_low, _mm_loadu_pd(y_high + k)));
      m = _mm_and_pd(m, _mm_cmple_pd(from, _mm_loadu_pd(end + k)));
      bits |= static_cast<std::uint64_t>(_mm_movemask_pd(m)) << k;
    }
#else
    for (std::size_t k = 0; k < 8; ++k) {
      const bool overlaps = reach.overlaps({x_low[k], x_high[k], y_low[k], y_high[k]});
      bits |= static_cast<std::uint64_t>(overlaps & (end[k] >= now)) << k;
    }
#endif
    return bits;
  }

  std::size_t stride_;               // the balls and seven entries that are no candidates
  std::vector<double> bounds_;       // x_low, x_high, y_low, y_high, end: stride_ entries each
  std::vector<std::uint8_t> flags_;  // candidate, moving: stride_ entries each
};

/// A predicted event of a shot, stale where a ball's version has moved on since. A contact of two balls
/// may be queued before its time is placed: at a time before which the two stay apart, placed when it
/// comes first (the order of events is the same: it comes first no later than the contact would).
struct ShotPrediction {
  double time;                           ///< absolute (s); a bound where `bound`
  ShotEvent::Kind kind;                  ///< what would happen
  bool bound = false;                    ///< the time is a bound of a ball–ball contact's, to be placed
  std::size_t ball, other;               ///< the ball and the other body
  std::uint64_t version, other_version;  ///< the ball's (and the other ball's) version when predicted
  double base = 0, horizon = 0;          ///< where `bound`: when it was predicted, and the pair's horizon
  /// The earliest first; at the same time by kind, then by balls: a deterministic order.
  bool operator>(const ShotPrediction& o) const {
    if (time != o.time) return time > o.time;
    return std::tie(kind, ball, other) > std::tie(o.kind, o.ball, o.other);
  }
};

}  // namespace detail

/// A shot: the table, the physics and the balls; strike() with the cue, then play() until every ball is at
/// rest or pocketed, or step(), run_events() and run_until() in the engines' common vocabulary.
///
/// Events at the same time are resolved in a fixed order: by time, then kind (ShotEvent::Kind's order),
/// then the ball's index, then the other's, so that the same shot gives the same events bit for bit. A
/// ball touching two balls or two cushions at once meets them one after the other in that order, each
/// contact resolved with the state the previous one left; a contact whose bodies no longer approach
/// changes nothing and is not recorded.
///
/// Contacts follow the runtime's laws (resolution.hpp). Bodies that the cloth's friction presses
/// together — a cue ball with follow pushing the ball it met, a ball with topspin driven back into a
/// cushion — would meet again and again, ever faster (inelastic collapse): the collapse is played
/// contact by contact until a contact leaves them separating slower than pressing_speed; then they are
/// in sustained contact, its limit (pressing.hpp: the pair moving as one, or the ball at rest against
/// the cushion, while the cloth presses them) where their motion lies on the line of the contact, and
/// otherwise separating at pressing_speed, the energy taken from their relative motion along the contact
/// plane and then from their spins, so that no energy is added.
class Shot {
 public:
  /// The kinetic energy may grow at an event by at most this fraction of the largest total the shot has
  /// had (rounding of the contact laws, which conserve or dissipate it exactly).
  static constexpr double energy_tolerance = 1e-12;
  /// The default of ShotOptions::pressing_speed (m/s): bodies the cloth presses together that leave a
  /// contact slower than this are in sustained contact from there (see the class's description).
  static constexpr double pressing_speed = ShotOptions{}.pressing_speed;

  /// Validates the physics and the options (billiards::invalid_argument naming the field, shot::validate)
  /// and the balls (std::invalid_argument naming the ball: a state not finite, a velocity not horizontal,
  /// a centre not on the cloth at least a radius inside every cushion's nose, two balls overlapping). A
  /// ball's position.z is set to the radius.
  Shot(PoolTable table, PoolPhysics physics, std::vector<PoolBall> balls, ShotOptions options = {})
      : table_(std::move(table)),
        physics_(std::move(physics)),
        options_(options),
        cushions_(table_.cushions()),
        jaws_(table_.jaws()),
        on_previous_line_(cushions_.size(), false) {
    for (std::size_t k = 1; k < cushions_.size(); ++k)
      on_previous_line_[k] = shot::same_nose_line(cushions_[k - 1], cushions_[k]);
    shot::validate(table_, physics_);
    shot::validate(options_);
    shot::validate(balls, table_, physics_.radius);
    pockets_ = shot::capture_circles(table_, jaws_, physics_.radius);
    lay_out_bodies();
    balls_.reserve(balls.size());
    for (const PoolBall& b : balls) {
      Entry e;
      e.state = {
          {b.position.x(), b.position.y(), physics_.radius}, b.velocity, b.angular_velocity, physics_.radius};
      e.pocketed = b.pocketed;
      if (e.pocketed) {
        e.state.velocity.setZero();
        e.state.angular_velocity.setZero();
      }
      balls_.push_back(e);
    }
    queue_ = detail::OwnedEvents<Predicted>(balls_.size());
    // Most shots' events and keyframes (a break's: some ten a ball) in one allocation each.
    events_.reserve(12 * balls_.size() + 16);
    history_.reserve(balls_.size(), 16 * balls_.size() + 16);
    reach_ = detail::ShotReaches(balls_.size());
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      begin_phase(i);
      keyframe(i);
    }
    // Every ball's own events first (its path's box), then each pair once: none where every ball is at
    // rest (a rack), as a pair meets only where one of its balls moves.
    for (std::size_t i = 0; i < balls_.size(); ++i) predict(i, balls_.size());
    const bool any_moving =
        std::any_of(balls_.begin(), balls_.end(), [](const Entry& e) { return e.phase.moving; });
    for (std::size_t i = 0; any_moving && i < balls_.size(); ++i) {
      if (!balls_[i].pocketed) predict_pairs(i, i + 1, balls_.size(), {});
    }
    energy_scale_ = last_energy_ = energy();
  }

  /// Strikes ball `index` with `cue` now (billiards::checked::strike: the tip's offsets and restitution;
  /// an elevated cue's vertical velocity is dropped, the ball stays on the cloth); the strike is an event
  /// of the shot. Throws std::invalid_argument for an index that is not a ball in play,
  /// billiards::invalid_argument for a bad cue.
  void strike(std::size_t index, const Cue<double>& cue) {
    if (index >= balls_.size() || balls_[index].pocketed)
      throw std::invalid_argument("strike: ball " + std::to_string(index) +
                                  " is not a ball in play (there are " + std::to_string(balls_.size()) +
                                  " balls)");
    release_partner(index, index);
    const BallOnCloth<double> now = at(index, now_);
    const SpinningBall<double> struck = checked::strike(shot::spinning(now, physics_.mass), cue);
    settle(index, now);
    Entry& e = balls_[index];
    const Motion from = motion(e.state, physics_.cloth);
    shot::take(e.state, struck);
    changed(index, balls_.size());
    record(ShotEvent::Kind::strike, index, index, from);
    last_energy_ = energy();
    energy_scale_ = std::max(energy_scale_, last_energy_);
  }

  /// Runs the next event and returns it; empty when every ball is at rest or pocketed. Throws
  /// EventLimitReached when the shot would take more than ShotOptions::event_limit events, and
  /// BrokenInvariant where an invariant checked (ShotOptions::check_invariants) fails: two balls, or a
  /// ball and a cushion or jaw, overlapping by more than overlap_tolerance of a radius; a ball that is
  /// neither on the cloth (inside the noses, or in a pocket's mouth) nor pocketed; the kinetic energy
  /// growing at an event.
  std::optional<ShotEvent> step() {
    if (!advance(std::numeric_limits<double>::infinity())) return std::nullopt;
    return events_.back();
  }

  /// Runs at most `count` events, calling `on_event(const ShotEvent&)` after each, and returns how many
  /// ran: fewer than `count` only when every ball is at rest or pocketed. Throws as step() does.
  template <typename OnEvent>
  std::uint64_t run_events(std::uint64_t count, OnEvent&& on_event) {
    std::uint64_t done = 0;
    for (; done < count && advance(std::numeric_limits<double>::infinity()); ++done) on_event(events_.back());
    return done;
  }
  /// Runs at most `count` events; see the overload with a callback.
  std::uint64_t run_events(std::uint64_t count) {
    return run_events(count, [](const ShotEvent&) {});
  }

  /// Runs every event up to the shot's time `until` (seconds), calling `on_event(const ShotEvent&)` after
  /// each, and makes `until` the time now (balls() then gives the balls there); returns how many events
  /// ran. Throws std::invalid_argument when `until` is NaN, infinite or earlier than time(), and as
  /// step() does.
  template <typename OnEvent>
  std::uint64_t run_until(double until, OnEvent&& on_event) {
    if (!(until >= now_) || !std::isfinite(until))
      throw std::invalid_argument("billiards::simulation::Shot::run_until: until is " +
                                  detail::shortest(until) + ", expected a finite time at or after " +
                                  detail::shortest(now_) + " s (the shot's time now)");
    std::uint64_t done = 0;
    for (; advance(until); ++done) on_event(events_.back());
    now_ = until;
    return done;
  }
  /// Runs every event up to the shot's time `until`; see the overload with a callback.
  std::uint64_t run_until(double until) {
    return run_until(until, [](const ShotEvent&) {});
  }

  /// Plays every event until every ball is at rest or pocketed, calling `on_event(const ShotEvent&)`
  /// after each; returns how many ran. Throws as step() does.
  template <typename OnEvent>
  std::uint64_t play(OnEvent&& on_event) {
    return run_events(std::numeric_limits<std::uint64_t>::max(), on_event);
  }
  /// Plays every event until every ball is at rest or pocketed; see the overload with a callback.
  std::uint64_t play() {
    return play([](const ShotEvent&) {});
  }

  /// Every event so far, in order.
  [[nodiscard]] const std::vector<ShotEvent>& events() const noexcept { return events_; }
  /// How many events so far (the strike included).
  [[nodiscard]] std::uint64_t event_count() const noexcept { return events_.size(); }
  /// The shot's time now (s): the last event's, or the time run_until() stopped at.
  [[nodiscard]] double time() const noexcept { return now_; }
  /// The balls now (at time()).
  [[nodiscard]] std::vector<PoolBall> balls() const { return balls_at(now_); }
  /// The balls as placed, before any event (their centres at the cloth's height R, a pocketed ball at
  /// rest).
  [[nodiscard]] std::vector<PoolBall> placed() const { return history_.first(); }
  /// The balls at any time `t` ≥ 0 of the shot so far, and on beyond its last event (each ball moved by
  /// its phases from its last event at or before `t`): the trajectories, sampled at any rate. At the time
  /// of an event, the states after it.
  [[nodiscard]] std::vector<PoolBall> balls_at(double t) const { return history_.at(t, physics_.cloth); }
  /// The table.
  [[nodiscard]] const PoolTable& table() const noexcept { return table_; }
  /// The physics.
  [[nodiscard]] const PoolPhysics& physics() const noexcept { return physics_; }
  /// The pockets' capture circles as the shot uses them (shot::capture_circles).
  [[nodiscard]] const std::vector<Pocket>& pockets() const noexcept { return pockets_; }
  /// The total kinetic energy (translation and rotation) of the balls in play now (J).
  [[nodiscard]] double energy() const { return energy_at(now_); }

 private:
  using Entry = detail::ShotBall;
  using Predicted = detail::ShotPrediction;

  // Resolves the predictions due up to `until` until one is recorded as an event; false when none is
  // left before `until`.
  bool advance(double until) {
    while (!queue_.empty()) {
      const std::size_t owner = queue_.earliest();
      if (!current(queue_.top(owner))) {
        queue_.pop(owner);
        continue;
      }
      if (queue_.top(owner).time > until) return false;
      if (queue_.top(owner).bound) {
        place(queue_.pop(owner));
        continue;
      }
      if (events_.size() >= options_.event_limit)
        throw EventLimitReached("billiards::simulation::Shot: the shot took more than " +
                                std::to_string(options_.event_limit) +
                                " events (ShotOptions::event_limit) at t = " + detail::shortest(now_) +
                                " s without coming to rest");
      const std::size_t before = events_.size();
      resolve(queue_.pop(owner));
      if (events_.size() > before) return true;
    }
    return false;
  }

  // Ball i at time t ≥ its reference time (within its phase, or beyond it by evolve's own phases).
  [[nodiscard]] BallOnCloth<double> at(std::size_t i, double t) const {
    const Entry& e = balls_[i];
    if (e.pocketed || !(t > e.since)) return e.state;
    const double tau = t - e.since;
    if (e.phase.pressed != shot::Pressed::none)
      return shot::pressed_state(e.state, e.phase.acceleration, e.piece.spin_acceleration, tau);
    // Within the phase and before the spin about ẑ stops: evolve's one step, from what the phase keeps.
    if (tau < e.phase.duration && tau < e.spin_end)
      return billiards::detail::advance(e.state, physics_.cloth, e.phase.motion, e.slip, tau, false, false);
    return evolve(e.state, physics_.cloth, tau);
  }
  [[nodiscard]] double energy_at(double t) const {
    double sum = 0;
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      if (!balls_[i].pocketed)
        sum += shot::kinetic_energy(at(i, std::max(t, balls_[i].since)), physics_.mass);
    }
    return sum;
  }

  // The phase of ball i's reference state: see the definition below the class.
  void begin_phase(std::size_t i, const shot::Phase* known = nullptr,
                   const billiards::detail::Slip<double>* known_slip = nullptr);
  // Ball i's state now becomes its reference state.
  void settle(std::size_t i) {
    if (!balls_[i].pocketed) settle(i, at(i, now_));
  }
  // Ball i's state now, `now` (at(i, now_), already computed), becomes its reference state.
  void settle(std::size_t i, const BallOnCloth<double>& now) {
    balls_[i].state = now;
    balls_[i].since = now_;
  }
  void keyframe(std::size_t i) {
    const Entry& e = balls_[i];
    if (e.phase.pressed == shot::Pressed::none) return history_.add(i, now_, e.state, e.pocketed);
    history_.add(i, now_, e.state, e.pocketed, &e.phase.acceleration, &e.piece.spin_acceleration);
  }

  [[nodiscard]] bool current(const Predicted& p) const {
    if (balls_[p.ball].version != p.version || balls_[p.ball].pocketed) return false;
    if (p.kind == ShotEvent::Kind::ball)
      return balls_[p.other].version == p.other_version && !balls_[p.other].pocketed;
    return true;
  }
  void push(double t, ShotEvent::Kind kind, std::size_t i, std::size_t other) {
    const std::uint64_t other_version = kind == ShotEvent::Kind::ball ? balls_[other].version : 0;
    queue_.push(i, {t, kind, false, i, other, balls_[i].version, other_version});
  }

  // The time left in ball j's phase from now, finite (the largest double for a phase without end).
  [[nodiscard]] double remaining(std::size_t j) const {
    const Entry& e = balls_[j];
    const double left = e.phase.duration - (now_ - e.since);
    return std::isfinite(left) ? std::max(left, 0.0) : std::numeric_limits<double>::max();
  }

  // Ball i's next events from now (its reference time): see the definition below the class.
  void predict(std::size_t i, std::size_t first_other,
               std::size_t skip = std::numeric_limits<std::size_t>::max(),
               detail::ExcludedContact excluded = {});

  // Ball i's contacts with the balls from `first_other` on but `skip`: see the definition below the class.
  void predict_pairs(std::size_t i, std::size_t first_other, std::size_t skip, detail::ExcludedContact excluded);
  // Ball i's centre from its reference state on, in its phase: see the definition below.
  [[nodiscard]] shot::Path own_path(std::size_t i) const;
  // The path of ball j relative to ball i's reference state at time `base`: see the definition below.
  [[nodiscard]] shot::Path relative_path(std::size_t i, std::size_t j, double base) const;
  // A current prediction queued at a bound of its time placed: see the definition below.
  void place(const Predicted& p);
  // Ball i's contact with cushion k queued at the start of a bracket of its root: see the definition below.
  void queue_bracketed_cushion(std::size_t i, std::size_t k, std::pair<double, double> bracket,
                               double solve_horizon, double& horizon, double& first_own);

  // Ball i changed now: its old predictions are stale; its phase begins again and it is predicted against
  // everything but `skip` (the other ball of a ball–ball event, predicted with it already).
  void changed(std::size_t i, std::size_t skip, detail::ExcludedContact excluded = {},
               const shot::Phase* known = nullptr,
               const billiards::detail::Slip<double>* known_slip = nullptr) {
    ++balls_[i].version;
    queue_.clear(i);  // every prediction of i's is stale now
    begin_phase(i, known, known_slip);
    keyframe(i);
    predict(i, 0, skip, excluded);
  }

  void record(ShotEvent::Kind kind, std::size_t i, std::size_t other, Motion from) {
    // Filled in place from the balls' states, nothing read back from where it was just written.
    const Entry &e = balls_[i], &o = balls_[kind == ShotEvent::Kind::ball ? other : i];
    ShotEvent& event = events_.emplace_back();
    event.time = now_;
    event.kind = kind;
    event.first = i;
    event.second = other;
    event.from = from;
    event.to = e.phase.motion;
    event.first_after = shot::as_pool_ball(e.state, e.pocketed);
    event.second_after = shot::as_pool_ball(o.state, o.pocketed);
  }

  void resolve(const Predicted& p) {
    const double energy_before_event = options_.check_invariants ? energy_at(p.time) : 0;
    now_ = p.time;
    const std::size_t i = p.ball;
    Entry& e = balls_[i];
    const Motion from = e.phase.motion;
    if (p.kind == ShotEvent::Kind::transition && (e.unrecorded_from || e.phase.pressed != shot::Pressed::none)) {
      end_pressed(p);
      return;
    }
    release_partner(i, p.kind == ShotEvent::Kind::ball ? p.other : i);
    if (p.kind == ShotEvent::Kind::ball) release_partner(p.other, i);
    std::size_t skip = balls_.size();
    shot::Phase next;  // a transition's next phase, and its state's slip
    billiards::detail::Slip<double> next_slip;
    switch (p.kind) {
      case ShotEvent::Kind::transition:
        // Evolved by the phase's predicted duration from its start (now − since may round a sliver short).
        e.state = shot::end_of_phase(e.state, from, e.phase.duration, physics_.cloth, next, e.slip, e.spin_end,
                                     next_slip);
        e.since = now_;
        break;
      case ShotEvent::Kind::ball: {
        const BallOnCloth<double> a = at(i, now_), b = at(p.other, now_);
        const Eigen::Vector3d n = shot::towards(a, b);
        const auto after = shot::ball_ball(a, b, n, physics_);
        settle(i, a);
        settle(p.other, b);
        if (!after) {
          // No longer approaching (rounding at a graze): nothing changes, but the two are predicted again
          // from here, with each other only after now.
          changed(i, balls_.size(), {ShotEvent::Kind::ball, p.other});
          changed(p.other, i);
          return;
        }
        shot::take(e.state, after->first);
        shot::take(balls_[p.other].state, after->second);
        if (!press_pair(i, p.other, n))
          shot::separate_pressed_pair(e.state, balls_[p.other].state, n, physics_.cloth, options_.pressing_speed);
        skip = p.other;
        break;
      }
      case ShotEvent::Kind::cushion:
      case ShotEvent::Kind::jaw: {
        const BallOnCloth<double> a = at(i, now_);
        const Eigen::Vector3d n = p.kind == ShotEvent::Kind::cushion
                                      ? shot::towards(cushions_[p.other])
                                      : shot::towards(jaws_[p.other], a.position);
        const std::optional<SpinningBall<double>> after = shot::ball_cushion(a, n, table_, physics_);
        settle(i, a);
        if (!after) {
          changed(i, balls_.size(), {p.kind, p.other});
          return;
        }
        shot::take(e.state, *after);
        if (!(p.kind == ShotEvent::Kind::cushion && press_on_cushion(i, p.other, n)))
          shot::separate_pressed_ball(e.state, n, physics_.cloth, options_.pressing_speed);
        break;
      }
      case ShotEvent::Kind::pocket:
        settle(i);
        e.pocketed = true;
        e.state.velocity.setZero();
        e.state.angular_velocity.setZero();
        break;
      case ShotEvent::Kind::strike: break;
    }
    if (p.kind == ShotEvent::Kind::transition)
      changed(i, skip, {}, &next, &next_slip);
    else
      changed(i, skip);
    if (p.kind == ShotEvent::Kind::ball) changed(p.other, balls_.size());
    record(p.kind, i, p.other, from);
    if (options_.check_invariants) check(energy_before_event);
  }

  // The cushions' lines and the jaws' and pockets' circles laid out a field at a time, and which of them
  // a ball's box comes within reach of, many side by side: see the definitions below the class.
  void lay_out_bodies();
  [[nodiscard]] std::uint64_t within_reach(const shot::Box& box) const;
  [[nodiscard]] std::uint64_t near_circles(const shot::Box& box) const;

  // The invariants after an event (every ball, every pair): see step().
  void check(double energy_before_event);
  // Pressed contacts (pressing.hpp): entered at a contact, ended at a piece's end, released by an event.
  bool press_pair(std::size_t i, std::size_t j, const Eigen::Vector3d& n);
  bool press_on_cushion(std::size_t i, std::size_t cushion, const Eigen::Vector3d& n);
  void end_pressed(const Predicted& p);
  void release_partner(std::size_t i, std::size_t also_changing);

  PoolTable table_;
  PoolPhysics physics_;
  ShotOptions options_;
  std::vector<CushionSegment> cushions_;
  std::vector<Jaw> jaws_;
  std::vector<bool> on_previous_line_;  // cushion k on cushion k − 1's nose line (shot::same_nose_line)
  std::vector<Pocket> pockets_;
  std::vector<double> lines_;    // the cushions' nose lines, a field at a time (lay_out_bodies)
  std::vector<double> circles_;  // the jaws' and pockets' circles, likewise
  std::size_t cushion_stride_ = 0;
  std::size_t circle_stride_ = 0;
  std::vector<Entry> balls_;
  detail::ShotReaches reach_;
  shot::History history_;
  std::vector<ShotEvent> events_;
  detail::OwnedEvents<Predicted> queue_;
  double now_ = 0;
  double energy_scale_ = 0;
  double last_energy_ = 0;
};

// The longer members, defined out of the class body.

// Ball i's next events from now (its reference time): its phase's end, the cushions, jaws and pockets,
// and the balls from index `first_other` on (all of them but i and `skip` after an event; those above i
// at the start, so that each pair is predicted once). A ball's events after its first contact with a
// cushion, jaw or pocket are not looked for: it changes there and is predicted again. Its path until
// then (`reach_end`) is bounded by a box, and a ball, jaw or pocket out of the box's reach is passed
// over without solving for its contact.
inline void Shot::predict(std::size_t i, std::size_t first_other, std::size_t skip,
                        detail::ExcludedContact excluded) {
  Entry& e = balls_[i];
  if (e.pocketed) {
    reach_.assign(i, {}, std::numeric_limits<double>::infinity(), false, false);  // no longer a candidate
    return;
  }
  double horizon = remaining(i);
  double first_own = std::numeric_limits<double>::infinity();  // its earliest cushion, jaw or pocket
  const double R = physics_.radius;
  const shot::Path me = own_path(i);
  // A contact at t from now with body k (none: +∞): queued, and the horizon brought in to it.
  const auto found = [&](double t, ShotEvent::Kind kind, std::size_t k) {
    if (t == std::numeric_limits<double>::infinity() || excluded(kind, k, t)) return;
    push(now_ + t, kind, i, k);
    horizon = std::min(horizon, t);
    first_own = std::min(first_own, now_ + t);
  };
  // The box of the centre's path up to the horizon, made again where a contact brings the horizon in.
  shot::Box box = shot::path_box(me, horizon, e.phase.moving, R);
  double boxed = horizon;
  const auto box_to_horizon = [&] {
    if (horizon != boxed) box = shot::path_box(me, horizon, e.phase.moving, R);
    boxed = horizon;
  };
  if (e.phase.moving) {
    // A cushion whose line the centre's box over the whole horizon keeps farther than R from is passed
    // over: its polynomial stays above 0 there. Cushions on one nose line share its root, found once (the
    // horizon it brings in ends at that root). A root bracketed without placing it (most: the ball
    // changes first) is queued at the bracket's start and placed when that comes first (place), with the
    // bracket's end as the horizon.
    double line_root = std::numeric_limits<double>::infinity(), line_horizon = horizon;
    std::array<double, 3> line{};  // the line's polynomial
    std::pair<double, double> bracket{0, 0};
    for (std::uint64_t within = within_reach(box); within != 0; within &= within - 1) {
      // Cushions on one line are within reach together (the test reads the line alone, bit for bit the
      // same): the previous one's root is this one's.
      const auto k = static_cast<std::size_t>(std::countr_zero(within));
      if (!(k > 0 && on_previous_line_[k])) {
        line_horizon = horizon;
        line_root = std::numeric_limits<double>::infinity();
        line = shot::nose_line_polynomial(me, cushions_[k], R);
        bracket = shot::nose_line_bracket(line, horizon);
        if (!(bracket.first > 0)) line_root = shot::nose_line_root(line, horizon);
      }
      if (bracket.first > 0) {
        const int side = shot::nose_side(me, cushions_[k], bracket.first);
        if (side != 0 && side == shot::nose_side(me, cushions_[k], bracket.second)) {
          if (side == 1) queue_bracketed_cushion(i, k, bracket, line_horizon, horizon, first_own);
          continue;
        }
        if (line_root == std::numeric_limits<double>::infinity())
          line_root = shot::bracketed_nose_line_root(line, line_horizon);
      }
      if (line_root != std::numeric_limits<double>::infinity() &&
          shot::within_nose(me, cushions_[k], line_root))
        found(line_root, ShotEvent::Kind::cushion, k);
    }
    box_to_horizon();
    // The jaws, then the pockets, whose circles the box comes within reach of, in order.
    const std::uint64_t near = near_circles(box);
    for (std::uint64_t jaws = near & ((std::uint64_t{1} << jaws_.size()) - 1); jaws != 0; jaws &= jaws - 1) {
      const auto k = static_cast<std::size_t>(std::countr_zero(jaws));
      found(shot::jaw_contact(me, jaws_[k], R, horizon), ShotEvent::Kind::jaw, k);
    }
    for (std::uint64_t pockets = near >> jaws_.size(); pockets != 0; pockets &= pockets - 1) {
      const auto k = static_cast<std::size_t>(std::countr_zero(pockets));
      found(shot::pocket_entry(me, pockets_[k], horizon), ShotEvent::Kind::pocket, k);
    }
  }
  // The phase's end, unless a cushion, jaw or pocket comes first (or at the same time, which orders
  // before a transition): the ball changes there, and a transition queued after it would go stale.
  if (std::isfinite(e.phase.duration) && !(first_own <= now_ + e.phase.duration))
    push(now_ + e.phase.duration, ShotEvent::Kind::transition, i, i);
  box_to_horizon();
  reach_.assign(i, box, e.phase.moving ? now_ + horizon : std::numeric_limits<double>::infinity(), true,
                e.phase.moving);
  predict_pairs(i, first_other, skip, excluded);
}

// Ball i's contacts with the balls from `first_other` on but `skip`, until the earlier of the two's
// predictions' ends (ShotReaches::end, see predict). A pair apart now is queued at a time before which it
// stays apart (shot::contact_lower_bound) and its contact placed only when that comes first (place): most
// pairs' contacts never come, as one of the balls changes before.
inline void Shot::predict_pairs(std::size_t i, std::size_t first_other, std::size_t skip,
                                detail::ExcludedContact excluded) {
  const Entry& e = balls_[i];
  const double R = physics_.radius;
  const std::size_t partner = e.phase.pressed == shot::Pressed::ball ? e.piece.partner : i;  // moving as one
  const shot::Box reach = reach_.box(i).widened(2 * R);
  const double reach_end = reach_.end(i);
  const bool moving = e.phase.moving;
  // 64 balls at a time: a mask of those whose boxes come within reach, in play, moving where this
  // one is not, predicted until now at least (else they change at once), computed without a branch;
  // then this one, the one skipped and the one it moves with taken out.
  for (std::size_t base = first_other; base < balls_.size(); base += 64) {
    const std::size_t count = std::min<std::size_t>(64, balls_.size() - base);
    std::uint64_t near = reach_.near(reach, moving, now_, base, count);
    for (const std::size_t out : {i, skip, partner}) {
      if (out >= base && out - base < count) near &= ~(std::uint64_t{1} << (out - base));
    }
    for (; near != 0; near &= near - 1) {
      const std::size_t j = base + static_cast<std::size_t>(std::countr_zero(near));
      const double end = std::min(reach_end, reach_.end(j));
      const shot::Path relative = relative_path(i, j, now_);
      const double pair_horizon = std::isfinite(end) ? end - now_ : std::numeric_limits<double>::max();
      if (shot::certainly_apart(relative, 2 * R, pair_horizon)) continue;
      const std::array<double, 5> polynomial = shot::ball_contact_polynomial(relative, R);
      // Apart at first: queued at a bound of its time, placed when it comes first, if it still holds.
      const double bound = shot::contact_lower_bound(polynomial, pair_horizon);
      if (bound == std::numeric_limits<double>::infinity()) continue;
      if (bound > 0) {
        queue_.push(i, {now_ + bound, ShotEvent::Kind::ball, true, i, j, e.version, balls_[j].version, now_,
                        pair_horizon});
        continue;
      }
      const std::optional<double> t = earliest_contact(polynomial, pair_horizon);
      if (t && !excluded(ShotEvent::Kind::ball, j, *t)) push(now_ + *t, ShotEvent::Kind::ball, i, j);
    }
  }
}

// The phase of ball i's reference state (`known`, where given, is phase_of's for it, `known_slip` the
// state's slip).
inline void Shot::begin_phase(std::size_t i, const shot::Phase* known,
                              const billiards::detail::Slip<double>* known_slip) {
  Entry& e = balls_[i];
  if (e.next) {
    e.phase = e.next->phase;
    e.piece = e.next->piece;
    e.next.reset();
  } else if (e.pocketed) {
    e.phase = shot::Phase{};
  } else {
    if (known) {
      e.slip = *known_slip;
      e.phase = *known;
    } else {
      e.slip = billiards::detail::slip_of(e.state);
      e.phase = shot::phase_of(e.state, physics_.cloth, e.slip);
    }
    // evolve's end of the spin: the spinning phase's duration, where there is a spin
    e.spin_end = e.state.angular_velocity.z() != 0
                     ? billiards::detail::phase_duration(e.state, physics_.cloth, Motion::spinning, e.slip)
                     : std::numeric_limits<double>::infinity();
  }
  e.unrecorded_from.reset();
}

// Ball i's centre from its reference state on, in its phase.
inline shot::Path Shot::own_path(std::size_t i) const {
  const Entry& e = balls_[i];
  return {{e.state.position.x(), e.state.position.y()}, {e.state.velocity.x(), e.state.velocity.y()},
          e.phase.acceleration};
}

// The path of ball j relative to ball i's reference state at time `base` (i's reference time: when it
// was last predicted).
inline shot::Path Shot::relative_path(std::size_t i, std::size_t j, double base) const {
  const Entry &e = balls_[i], &o = balls_[j];
  const auto [position, velocity] = shot::centre_and_velocity(o.state, o.phase, base - o.since);
  return {position - Eigen::Vector2d(e.state.position.x(), e.state.position.y()),
          velocity - Eigen::Vector2d(e.state.velocity.x(), e.state.velocity.y()),
          o.phase.acceleration - e.phase.acceleration};
}

// A current prediction queued at a bound of its time: its contact placed and queued, if any. The balls'
// versions being those it was predicted with, their reference states are too (every change of a state
// changes its ball's version), so that the polynomial is the one predict or predict_pairs had. A ball's
// cushion was queued at the start of a bracket of its root (shot::nose_line_bracket), which its root lies
// past. Checked where invariants are: a contact placed before its bound would break the order of events.
inline void Shot::place(const Predicted& p) {
  double t = std::numeric_limits<double>::infinity();
  if (p.kind == ShotEvent::Kind::cushion) {
    const shot::Path me = own_path(p.ball);
    t = shot::bracketed_nose_line_root(shot::nose_line_polynomial(me, cushions_[p.other], physics_.radius),
                                       p.horizon);
  } else {
    const shot::Path relative = relative_path(p.ball, p.other, p.base);
    t = earliest_contact(shot::ball_contact_polynomial(relative, physics_.radius), p.horizon)
            .value_or(std::numeric_limits<double>::infinity());
  }
  if (t == std::numeric_limits<double>::infinity()) return;
  if (options_.check_invariants && !(p.base + t >= p.time))
    throw BrokenInvariant("billiards::simulation::Shot: at t = " + detail::shortest(now_) + " s, ball " +
                          std::to_string(p.ball) + "'s " + kind_name(p.kind) + " contact with " +
                          std::to_string(p.other) + " placed at " + detail::shortest(p.base + t) +
                          " s, before its bound " + detail::shortest(p.time) + " s");
  queue_.push(p.ball, {p.base + t, p.kind, false, p.ball, p.other, p.version, p.other_version});
}

// Ball i's contact with cushion k, its root in `bracket` (shot::nose_line_bracket over `solve_horizon`),
// queued at the bracket's start, to be placed when that comes first; the ball's horizon brought in to the
// bracket's end and its first own event to its start.
inline void Shot::queue_bracketed_cushion(std::size_t i, std::size_t k, std::pair<double, double> bracket,
                                          double solve_horizon, double& horizon, double& first_own) {
  queue_.push(i, {now_ + bracket.first, ShotEvent::Kind::cushion, true, i, k, balls_[i].version, 0, now_,
                  solve_horizon});
  horizon = std::min(horizon, bracket.second);
  first_own = std::min(first_own, now_ + bracket.first);
}

// The cushions' nose lines (start, normal) and the jaws' and then the pockets' circles (centre, and the
// reach at which a centre meets them: R and the jaw's radius, the capture radius) a field at a time,
// padded to whole vectors (the lines' padding masked off, the circles' NaN centres that no box comes
// near).
inline void Shot::lay_out_bodies() {
  cushion_stride_ = (cushions_.size() + 7) / 8 * 8;
  lines_.assign(4 * cushion_stride_, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < cushions_.size(); ++k) {
    lines_[k] = cushions_[k].start.x();
    lines_[cushion_stride_ + k] = cushions_[k].start.y();
    lines_[2 * cushion_stride_ + k] = cushions_[k].normal.x();
    lines_[3 * cushion_stride_ + k] = cushions_[k].normal.y();
  }
  const std::size_t n = jaws_.size() + pockets_.size();
  circle_stride_ = (n + 7) / 8 * 8;
  circles_.assign(3 * circle_stride_, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < n; ++k) {
    const bool jaw = k < jaws_.size();
    const TableVector& centre = jaw ? jaws_[k].centre : pockets_[k - jaws_.size()].centre;
    circles_[k] = centre.x();
    circles_[circle_stride_ + k] = centre.y();
    circles_[2 * circle_stride_ + k] =
        jaw ? physics_.radius + jaws_[k].radius : pockets_[k - jaws_.size()].radius;
  }
}
// A bit for each cushion (a table has at most six): whether a centre within `box` may come within R of
// its nose line (not shot::beyond_reach), without a branch, the cushions side by side.
inline std::uint64_t Shot::within_reach(const shot::Box& box) const {
  const double *x = lines_.data(), *y = x + cushion_stride_, *nx = y + cushion_stride_,
               *ny = nx + cushion_stride_;
  std::uint64_t bits = 0;
  for (std::size_t k = 0; k < cushion_stride_; ++k) {
    const bool beyond = shot::beyond_reach(box, x[k], y[k], nx[k], ny[k], physics_.radius);
    bits |= static_cast<std::uint64_t>(!beyond) << k;
  }
  return bits & ((std::uint64_t{1} << cushions_.size()) - 1);
}
// A bit for each circle of lay_out_bodies, the jaws' first (a table has 12 jaws and 6 pockets, or
// none): whether `box` comes within its reach (shot::Box::near), without a branch, side by side.
inline std::uint64_t Shot::near_circles(const shot::Box& box) const {
  const double *x = circles_.data(), *y = x + circle_stride_, *reach = y + circle_stride_;
  std::uint64_t bits = 0;
  for (std::size_t k = 0; k < circle_stride_; ++k)
    bits |= static_cast<std::uint64_t>(box.near(x[k], y[k], reach[k])) << k;
  return bits;
}

// Balls i and j, that have just met along n (from i to j): pressed together from now on (their next
// phases a pressed pair's) where the cloth presses them, they part slower than pressing_speed and
// their motion lies on the line of the contact. Whether they are.
inline bool Shot::press_pair(std::size_t i, std::size_t j, const Eigen::Vector3d& n) {
  BallOnCloth<double>&a = balls_[i].state, &b = balls_[j].state;
  if (!((b.velocity - a.velocity).dot(n) < options_.pressing_speed) || !shot::presses(a, b, n, physics_.cloth))
    return false;
  const auto pieces = shot::pressed_pair(a, b, i, j, n, physics_);
  if (!pieces) return false;
  balls_[i].next = (*pieces)[0];
  balls_[j].next = (*pieces)[1];
  return true;
}

// Ball i, that has just met a cushion along n: pressed on it from now on where the cloth presses it
// there, it leaves slower than pressing_speed and its motion lies on the cushion's normal. Whether it is.
inline bool Shot::press_on_cushion(std::size_t i, std::size_t cushion, const Eigen::Vector3d& n) {
  BallOnCloth<double>& a = balls_[i].state;
  if (!(-a.velocity.dot(n) < options_.pressing_speed) || !shot::presses(a, n, physics_.cloth)) return false;
  balls_[i].next = shot::pressed_on_cushion(a, cushion, n, table_, physics_);
  return balls_[i].next.has_value();
}

// The end of a pressed piece (or the record of a partner's change of motion there): the bodies evolved
// to it, what ended it set to zero, and the next piece begun where the cloth still presses them;
// otherwise they part.
inline void Shot::end_pressed(const Predicted& p) {
  const std::size_t i = p.ball;
  Entry& e = balls_[i];
  if (e.unrecorded_from) {
    const Motion from = *e.unrecorded_from;
    e.unrecorded_from.reset();
    record(ShotEvent::Kind::transition, i, i, from);
    return;
  }
  const shot::Phase phase = e.phase;
  const shot::PressedPiece piece = e.piece;
  const double energy_before_event = options_.check_invariants ? energy_at(p.time) : 0;
  now_ = p.time;
  e.state = shot::pressed_state(e.state, phase.acceleration, piece.spin_acceleration, phase.duration);
  e.since = now_;
  if (phase.pressed == shot::Pressed::cushion) {
    e.state.velocity.setZero();
    e.state.angular_velocity.setZero();
    changed(i, balls_.size());
    record(ShotEvent::Kind::transition, i, i, phase.motion);
    if (options_.check_invariants) check(energy_before_event);
    return;
  }
  const std::size_t k = piece.partner;
  Entry& o = balls_[k];
  const Motion from_k = o.phase.motion;
  o.state = shot::pressed_state(o.state, o.phase.acceleration, o.piece.spin_acceleration, o.phase.duration);
  o.since = now_;
  if (piece.ending == shot::PressedEnd::speed) {
    e.state.velocity.setZero();
    o.state.velocity.setZero();
  }
  const std::size_t a = piece.first ? i : k, b = piece.first ? k : i;
  const Eigen::Vector3d n = shot::towards(balls_[a].state, balls_[b].state);
  std::optional<std::array<shot::PressedStart, 2>> pieces;
  if (shot::presses(balls_[a].state, balls_[b].state, n, physics_.cloth))
    pieces = shot::pressed_pair(balls_[a].state, balls_[b].state, a, b, n, physics_);
  // A piece too short to move the shot's time on (rounding left its end's quantity a sliver from 0):
  // the pair parts instead, so that time always advances.
  if (pieces && !(now_ + (*pieces)[0].phase.duration > now_)) pieces.reset();
  if (pieces) {
    balls_[a].next = (*pieces)[0];
    balls_[b].next = (*pieces)[1];
    changed(i, k);
    changed(k, balls_.size());
  } else {
    changed(i, balls_.size(), {ShotEvent::Kind::ball, k});
    changed(k, i);
  }
  const bool i_changed = e.phase.motion != phase.motion, k_changed = o.phase.motion != from_k;
  if (i_changed) record(ShotEvent::Kind::transition, i, i, phase.motion);
  if (k_changed && !i_changed) record(ShotEvent::Kind::transition, k, k, from_k);
  if (k_changed && i_changed) {
    o.unrecorded_from = from_k;
    push(now_, ShotEvent::Kind::transition, k, k);
  }
  if (options_.check_invariants && (i_changed || k_changed)) check(energy_before_event);
}

// Ball i is about to change at an event (with ball `also_changing`): the ball it was pressed against, if
// any other, goes on free from now.
inline void Shot::release_partner(std::size_t i, std::size_t also_changing) {
  const Entry& e = balls_[i];
  if (e.phase.pressed != shot::Pressed::ball || e.piece.partner == also_changing) return;
  const std::size_t k = e.piece.partner;
  settle(k);
  changed(k, balls_.size());
}

inline void Shot::check(double energy_before_event) {
  const auto fail = [&](std::size_t i, const std::string& what) {
    throw BrokenInvariant("billiards::simulation::Shot: at t = " + detail::shortest(now_) + " s (event " +
                          std::to_string(events_.size()) + ", " + kind_name(events_.back().kind) +
                          "), ball " + std::to_string(i) + " " + what);
  };
  std::vector<Eigen::Vector2d> centres(balls_.size());
  std::vector<bool> in_play(balls_.size());
  for (std::size_t i = 0; i < balls_.size(); ++i) {
    const Eigen::Vector3d r = at(i, now_).position;
    centres[i] = {r.x(), r.y()};
    in_play[i] = !balls_[i].pocketed;
  }
  if (const auto broken =
          shot::broken_invariant(table_, cushions_, jaws_, pockets_, centres, in_play, physics_.radius))
    fail(broken->first, broken->second);
  const double after = energy();
  const double allowed = energy_tolerance * energy_scale_;
  if (!(energy_before_event <= last_energy_ + allowed))
    fail(events_.back().first, "gained kinetic energy between events: " + detail::shortest(last_energy_) +
                                   " J to " + detail::shortest(energy_before_event) + " J");
  if (!(after <= energy_before_event + allowed))
    fail(events_.back().first,
         "gained kinetic energy at the event: " + detail::shortest(energy_before_event) + " J to " +
             detail::shortest(after) + " J");
  last_energy_ = after;
}

}  // namespace billiards::simulation
