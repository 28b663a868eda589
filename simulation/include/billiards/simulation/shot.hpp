/// \file
/// A shot on a pool table, played event by event from the cue to rest: no time stepping. Each ball moves
/// by its phase's closed form on the cloth (billiards::evolve: sliding, rolling, spinning, at rest), with a
/// constant horizontal acceleration within a phase, so that each contact's time is the earliest root of a
/// derived event polynomial (billiards::contact_polynomial for two balls, a ball and a jaw, a ball and a
/// pocket's capture circle; billiards::cushion_polynomial for a ball and a straight cushion), found by
/// billiards::earliest_contact. Events: the cue strike, ball–ball (billiards::collide_with_friction),
/// ball–cushion and ball–jaw (billiards::collide_with_cushion), ball–pocket (the ball leaves play) and
/// each phase's end. After an event only the balls it changed are predicted again.
#pragma once

#include <billiards/simulation/pool_table.hpp>

#include <billiards/cloth.hpp>
#include <billiards/events.hpp>
#include <billiards/shot.hpp>
#include <billiards/spin.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace billiards::simulation {

/// What happened at an event of a shot.
struct ShotEvent {
  /// The kinds of events, in the order in which events at the same time are resolved.
  enum class Kind {
    strike,      ///< the cue struck `ball`
    ball,        ///< `ball` met ball `other`
    cushion,     ///< `ball` met straight cushion `other` (PoolTable::cushions())
    jaw,         ///< `ball` met jaw `other` (PoolTable::jaws())
    pocket,      ///< `ball` entered pocket `other` (PoolTable::pockets()) and left play
    transition,  ///< `ball`'s phase ended: `from` → `to`
  };
  Kind kind = Kind::strike;          ///< what happened
  double time = 0;                   ///< seconds since the shot began
  std::size_t ball = 0;              ///< the ball (its index)
  std::size_t other = 0;             ///< the other ball, the cushion, the jaw or the pocket (else `ball`)
  Motion from = Motion::stationary;  ///< `ball`'s phase before the event
  Motion to = Motion::stationary;    ///< `ball`'s phase after it
  PoolBall ball_after;               ///< `ball`'s state after the event
  PoolBall other_after;              ///< the other ball's state after a ball–ball event (else `ball_after`)
};

/// The name of an event's kind: "strike", "ball", "cushion", "jaw", "pocket", "transition".
inline const char* kind_name(ShotEvent::Kind kind) noexcept {
  switch (kind) {
    case ShotEvent::Kind::strike: return "strike";
    case ShotEvent::Kind::ball: return "ball";
    case ShotEvent::Kind::cushion: return "cushion";
    case ShotEvent::Kind::jaw: return "jaw";
    case ShotEvent::Kind::pocket: return "pocket";
    case ShotEvent::Kind::transition: return "transition";
  }
  return "unknown";
}

/// The name of a phase: "sliding", "rolling", "spinning", "stationary".
inline const char* motion_name(Motion motion) noexcept {
  switch (motion) {
    case Motion::sliding: return "sliding";
    case Motion::rolling: return "rolling";
    case Motion::spinning: return "spinning";
    case Motion::stationary: return "stationary";
  }
  return "unknown";
}

/// How a Shot plays.
struct ShotOptions {
  /// The most events a shot may take; play() stops with billiards::simulation::RunawayShot beyond it.
  std::uint64_t event_limit = 100000;
  /// Check the invariants at every event (Shot::play): on in debug builds, off where NDEBUG is defined.
#ifdef NDEBUG
  bool check_invariants = false;
#else
  bool check_invariants = true;
#endif
};

namespace detail {

/// A body a shot's prediction leaves out at t = 0: the one of a contact that changed nothing (its bodies no
/// longer approached), which the same rounding would otherwise report again at once.
struct ExcludedContact {
  ShotEvent::Kind kind = ShotEvent::Kind::strike;  ///< the body's kind (strike: none)
  std::size_t index = 0;  ///< the body's index
  /// Whether a contact with body `other` of kind `k` at `t` from now is the one left out.
  [[nodiscard]] bool operator()(ShotEvent::Kind k, std::size_t other, double t) const {
    return t == 0 && k == kind && other == index;
  }
};

}  // namespace detail

/// A shot that did not come to rest within ShotOptions::event_limit events.
class RunawayShot : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An invariant of a shot broken at an event (two balls overlapping, a ball off the cloth, kinetic
/// energy gained): a defect of the engine, reported with the time, the event and the balls.
class BrokenInvariant : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// A shot: the table, the physics and the balls; strike() with the cue, then play() until every ball is at
/// rest or pocketed.
///
/// Events at the same time are resolved in a fixed order: by time, then kind (ShotEvent::Kind's order),
/// then the ball's index, then the other's, so that the same shot gives the same events bit for bit. A
/// ball touching two balls or two cushions at once meets them one after the other in that order, each
/// contact resolved with the state the previous one left; a contact whose bodies no longer approach
/// changes nothing and is not recorded.
///
/// Contacts follow the runtime's laws: billiards::collide_with_friction between balls,
/// billiards::collide_with_cushion at a cushion's nose and at a jaw (its normal towards the jaw's axis);
/// the vertical velocity a contact gives is dropped (the cloth's reaction keeps a ball on it). Bodies
/// that the cloth's friction presses together — a sliding ball curving into a cushion or into a ball it
/// grazes, a ball with draw pushing one in front — would meet again and again, ever faster (inelastic
/// collapse): a contact that leaves such bodies separating slower than pressing_speed leaves them
/// separating at pressing_speed instead, the energy taken from their relative motion along the contact
/// plane and then from their spins, so that no energy is added. The bodies then part by a few
/// micrometres at most before the cloth brings them back: sustained contact as a short train of
/// contacts.
class Shot {
 public:
  /// The largest overlap of two balls, of a ball and a cushion or of a ball and a jaw at an event, as a
  /// fraction of the radius.
  static constexpr double overlap_tolerance = 1e-9;
  /// The kinetic energy may grow at an event by at most this fraction of the largest total the shot has
  /// had (rounding of the contact laws, which conserve or dissipate it exactly).
  static constexpr double energy_tolerance = 1e-12;
  /// The speed (m/s) at which bodies the cloth presses together leave a contact at the least: the
  /// energy is taken from their relative velocity along the contact plane, then from their spins (see
  /// the class's description).
  static constexpr double pressing_speed = 1e-3;

  /// Validates the physics (billiards::invalid_argument naming the field: radius and mass positive and
  /// finite, friction coefficients finite and ≥ 0, gravity positive, restitutions in [0, 1], the table's
  /// nose height in [R, 2R)) and the balls (std::invalid_argument naming the ball: a state not finite,
  /// a velocity not horizontal, a centre not on the cloth at least a radius inside every cushion's nose,
  /// two balls overlapping). A ball's position.z is set to the radius.
  Shot(PoolTable table, PoolPhysics physics, std::vector<PoolBall> balls, ShotOptions options = {})
      : table_(std::move(table)),
        physics_(std::move(physics)),
        options_(options),
        cushions_(table_.cushions()),
        jaws_(table_.jaws()),
        pockets_(table_.pockets()) {
    validate_physics();
    close_mouths();
    const double R = physics_.radius;
    for (std::size_t i = 0; i < balls.size(); ++i) {
      const PoolBall& b = balls[i];
      const auto fail = [&](const std::string& what) {
        throw std::invalid_argument("ball " + std::to_string(i) + " " + what);
      };
      if (!b.position.allFinite() || !b.velocity.allFinite() || !b.angular_velocity.allFinite())
        fail("has a position, velocity or spin that is not finite");
      if (!b.pocketed) {
        const double x = b.position.x(), y = b.position.y(), slack = R * overlap_tolerance;
        if (!(x >= R - slack && x <= table_.length - R + slack && y >= R - slack && y <= table_.width - R + slack))
          fail("is at (" + number(x) + ", " + number(y) + "), expected a centre on the cloth at least a radius (" +
               number(R) + ") inside every cushion's nose");
        if (b.velocity.z() != 0)
          fail("has v_z = " + number(b.velocity.z()) + ", expected 0 (a ball on the cloth moves horizontally)");
      }
      Entry e;
      e.state = {{b.position.x(), b.position.y(), R}, b.velocity, b.angular_velocity, R};
      e.pocketed = b.pocketed;
      if (e.pocketed) {
        e.state.velocity.setZero();
        e.state.angular_velocity.setZero();
      }
      balls_.push_back(e);
    }
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      for (std::size_t j = i + 1; j < balls_.size(); ++j) {
        if (balls_[i].pocketed || balls_[j].pocketed) continue;
        const double d = distance(balls_[i].state.position, balls_[j].state.position);
        if (d < 2 * R * (1 - overlap_tolerance))
          throw std::invalid_argument("balls " + std::to_string(i) + " and " + std::to_string(j) +
                                      " overlap: their centres are " + number(d) + " m apart, expected at least " +
                                      number(2 * R) + " (two radii)");
      }
    }
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      begin_phase(i);
      keyframe(i);
    }
    // Every ball's own events first (its path's box), then each pair once.
    for (std::size_t i = 0; i < balls_.size(); ++i) predict(i, balls_.size());
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      if (!balls_[i].pocketed) predict_pairs(i, i + 1, balls_.size(), {});
    }
    energy_scale_ = last_energy_ = energy();
  }

  /// Strikes ball `index` with `cue` now (billiards::checked::strike: the tip's offsets and restitution;
  /// an elevated cue's vertical velocity is dropped, the ball stays on the cloth). Throws
  /// std::invalid_argument for an index that is not a ball in play, billiards::invalid_argument for a bad
  /// cue.
  void strike(std::size_t index, const Cue<double>& cue) {
    if (index >= balls_.size() || balls_[index].pocketed)
      throw std::invalid_argument("strike: ball " + std::to_string(index) + " is not a ball in play (there are " +
                                  std::to_string(balls_.size()) + " balls)");
    const SpinningBall<double> before{at(index, now_).velocity, at(index, now_).angular_velocity, physics_.mass,
                                      physics_.radius};
    const SpinningBall<double> struck = checked::strike(before, cue);
    settle(index);
    Entry& e = balls_[index];
    const Motion from = motion(e.state, physics_.cloth);
    e.state.velocity = struck.velocity;
    e.state.velocity.z() = 0;
    e.state.angular_velocity = struck.angular_velocity;
    changed(index, balls_.size());
    record(ShotEvent::Kind::strike, index, index, from);
    last_energy_ = energy();
    energy_scale_ = std::max(energy_scale_, last_energy_);
  }

  /// Plays every event until every ball is at rest or pocketed. Throws RunawayShot when the shot would
  /// take more than ShotOptions::event_limit events, and BrokenInvariant where an invariant checked
  /// (ShotOptions::check_invariants) fails: two balls, or a ball and a cushion or jaw, overlapping by
  /// more than overlap_tolerance of a radius; a ball that is neither on the cloth (inside the noses, or in
  /// a pocket's mouth) nor pocketed; the kinetic energy growing at an event.
  void play() {
    while (!queue_.empty()) {
      const Predicted next = queue_.top();
      queue_.pop();
      if (!current(next)) continue;
      if (events_.size() >= options_.event_limit)
        throw RunawayShot("billiards::simulation::Shot: the shot took more than " +
                          std::to_string(options_.event_limit) + " events (ShotOptions::event_limit) at t = " +
                          number(now_) + " s without coming to rest");
      resolve(next);
    }
  }

  /// Every event so far, in order.
  [[nodiscard]] const std::vector<ShotEvent>& events() const noexcept { return events_; }
  /// The time of the last event (s).
  [[nodiscard]] double time() const noexcept { return now_; }
  /// The balls at the last event.
  [[nodiscard]] std::vector<PoolBall> balls() const { return balls_at(now_); }
  /// The balls at any time `t` ≥ 0 of the shot so far, and on beyond its last event (each ball moved by
  /// its phases from its last event at or before `t`): the trajectories, sampled at any rate. At the time
  /// of an event, the states after it.
  [[nodiscard]] std::vector<PoolBall> balls_at(double t) const {
    std::vector<PoolBall> out;
    out.reserve(balls_.size());
    for (const std::vector<Keyframe>& frames : history_) {
      // The last keyframe at or before t (the first if t precedes them all).
      auto it = std::upper_bound(frames.begin(), frames.end(), t,
                                 [](double time, const Keyframe& k) { return time < k.time; });
      const Keyframe& k = it == frames.begin() ? frames.front() : *std::prev(it);
      out.push_back(k.pocketed || !(t > k.time) ? as_pool_ball(k.state, k.pocketed)
                                                 : as_pool_ball(evolve(k.state, physics_.cloth, t - k.time), false));
    }
    return out;
  }
  /// The table.
  [[nodiscard]] const PoolTable& table() const noexcept { return table_; }
  /// The physics.
  [[nodiscard]] const PoolPhysics& physics() const noexcept { return physics_; }
  /// The pockets' capture circles as the shot uses them: the table's, each widened where needed to reach
  /// into its two jaws' reach (a ball's centre comes no nearer a jaw's axis than R + the jaw's radius), so
  /// that no ball passes between a jaw and the pocket.
  [[nodiscard]] const std::vector<Pocket>& pockets() const noexcept { return pockets_; }
  /// The total kinetic energy (translation and rotation) of the balls in play at the last event (J).
  [[nodiscard]] double energy() const {
    double sum = 0;
    for (std::size_t i = 0; i < balls_.size(); ++i) sum += energy_of(i, now_);
    return sum;
  }

 private:
  struct Entry {
    BallOnCloth<double> state;  // at time `since`
    double since = 0;
    double duration = 0;  // the phase's duration from `since` (+∞ at rest)
    double horizontal_acceleration[2] = {0, 0};
    Motion phase = Motion::stationary;  // of `state`
    bool moving = false;  // sliding or rolling: its centre moves
    double reach_end = std::numeric_limits<double>::infinity();  // its predictions' end (absolute time)
    std::array<double, 4> box{};  // x and y ranges of its centre from its last prediction to reach_end
    bool pocketed = false;
    std::uint64_t version = 0;
  };
  struct Keyframe {
    double time;
    BallOnCloth<double> state;
    bool pocketed;
  };
  struct Predicted {
    double time;
    ShotEvent::Kind kind;
    std::size_t ball, other;
    std::uint64_t version, other_version;
    // The earliest first; at the same time by kind, then by balls: a deterministic order.
    bool operator>(const Predicted& o) const {
      return std::tie(time, kind, ball, other) > std::tie(o.time, o.kind, o.ball, o.other);
    }
  };

  // The shortest text that reads back as x.
  static std::string number(double x) {
    char text[32];
    const auto written = std::to_chars(text, text + sizeof text, x);
    return std::string(text, written.ptr);
  }
  static double distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::hypot(a.x() - b.x(), a.y() - b.y());
  }
  static PoolBall as_pool_ball(const BallOnCloth<double>& s, bool pocketed) {
    return {s.position, s.velocity, s.angular_velocity, pocketed};
  }

  void validate_physics() const {
    const PoolPhysics& p = physics_;
    const auto require = [](bool ok, const char* name, double value, const char* expected) {
      if (!ok)
        throw billiards::invalid_argument("Shot", std::string("physics.") + name, number(value), expected);
    };
    const auto positive = [](double x) { return std::isfinite(x) && x > 0; };
    const auto friction = [](double x) { return std::isfinite(x) && x >= 0; };
    const auto restitution = [](double x) { return x >= 0 && x <= 1; };
    require(positive(p.radius), "radius", p.radius, "a positive, finite length (m)");
    require(positive(p.mass), "mass", p.mass, "a positive, finite mass (kg)");
    require(friction(p.cloth.sliding_friction), "cloth.sliding_friction", p.cloth.sliding_friction, "finite and >= 0");
    require(friction(p.cloth.rolling_friction), "cloth.rolling_friction", p.cloth.rolling_friction, "finite and >= 0");
    require(friction(p.cloth.spinning_friction), "cloth.spinning_friction", p.cloth.spinning_friction,
            "finite and >= 0");
    require(positive(p.cloth.gravity), "cloth.gravity", p.cloth.gravity, "positive and finite (m/s^2)");
    require(restitution(p.ball_restitution), "ball_restitution", p.ball_restitution, "in [0, 1]");
    require(friction(p.ball_friction), "ball_friction", p.ball_friction, "finite and >= 0");
    require(restitution(p.cushion_restitution), "cushion_restitution", p.cushion_restitution, "in [0, 1]");
    require(friction(p.cushion_friction), "cushion_friction", p.cushion_friction, "finite and >= 0");
    if (!(table_.nose_height >= p.radius && table_.nose_height < 2 * p.radius))
      throw billiards::invalid_argument("Shot", "table.nose_height", number(table_.nose_height),
                                        "a height in [R, 2R) = [" + number(p.radius) + ", " + number(2 * p.radius) +
                                            ")");
  }

  // Each pocket's capture circle widened, where needed, to reach into both its jaws' reach (a centre
  // comes no nearer a jaw's axis than R + ρ_jaw), so that no ball can pass between a jaw and the pocket
  // (pooltool's geometry leaves a gap of 0.2 mm there at the corners, which its pockets' straight walls
  // behind the jaws close).
  void close_mouths() {
    const double R = physics_.radius;
    for (Pocket& pocket : pockets_) {
      std::vector<double> gaps;
      for (const Jaw& jaw : jaws_) gaps.push_back((jaw.centre - pocket.centre).norm() - (R + jaw.radius));
      std::sort(gaps.begin(), gaps.end());
      // The two nearest jaws are the pocket's own; 1 µm of overlap.
      pocket.radius = std::max(pocket.radius, gaps[1] + 1e-6);
    }
  }

  // Ball i at time t ≥ its reference time (within its phase, or beyond it by evolve's own phases).
  [[nodiscard]] BallOnCloth<double> at(std::size_t i, double t) const {
    const Entry& e = balls_[i];
    if (e.pocketed || !(t > e.since)) return e.state;
    return evolve(e.state, physics_.cloth, t - e.since);
  }

  // Ball i's centre and velocity at time t within its phase, x0 + v0 τ + ½ a τ² and v0 + a τ (τ = t less
  // its reference time) with the phase's constant acceleration: the motion at() follows, without its
  // spin and phase changes, for the many pairs each event predicts.
  [[nodiscard]] std::pair<Eigen::Vector2d, Eigen::Vector2d> centre_and_velocity(std::size_t i, double t) const {
    const Entry& e = balls_[i];
    const Eigen::Vector2d r(e.state.position.x(), e.state.position.y()), v(e.state.velocity.x(), e.state.velocity.y());
    if (e.pocketed || !e.moving || !(t > e.since)) return {r, v};
    const double tau = t - e.since;
    const Eigen::Vector2d a(e.horizontal_acceleration[0], e.horizontal_acceleration[1]);
    return {r + tau * v + (0.5 * tau * tau) * a, v + tau * a};
  }

  [[nodiscard]] double energy_of(std::size_t i, double t) const {
    if (balls_[i].pocketed) return 0;
    const BallOnCloth<double> s = at(i, t);
    const double m = physics_.mass, R = physics_.radius;
    return 0.5 * m * s.velocity.squaredNorm() + 0.2 * m * R * R * s.angular_velocity.squaredNorm();
  }

  // The horizontal acceleration of a ball in its phase: −μ_s g û sliding (û the contact's slip
  // direction), −μ_r g v̂ rolling, 0 otherwise.
  [[nodiscard]] Eigen::Vector2d acceleration(const BallOnCloth<double>& s, Motion phase) const {
    const Cloth<double>& cloth = physics_.cloth;
    Eigen::Vector2d direction;
    double size = 0;
    if (phase == Motion::sliding) {
      const Eigen::Vector3d u = contact_slip(s);
      direction = {u.x(), u.y()};
      size = cloth.sliding_friction * cloth.gravity;
    } else if (phase == Motion::rolling) {
      direction = {s.velocity.x(), s.velocity.y()};
      size = cloth.rolling_friction * cloth.gravity;
    } else {
      return Eigen::Vector2d::Zero();
    }
    return -size * (direction / billiards::detail::horizontal_length(direction.x(), direction.y()));
  }

  // The phase of ball i's reference state: its duration, whether it moves, its acceleration.
  void begin_phase(std::size_t i) {
    Entry& e = balls_[i];
    e.horizontal_acceleration[0] = e.horizontal_acceleration[1] = 0;
    if (e.pocketed) {
      e.phase = Motion::stationary;
      e.duration = std::numeric_limits<double>::infinity();
      e.moving = false;
      return;
    }
    // The contact's slip once for the phase, its duration and its direction (motion, transition_time).
    const billiards::detail::Slip<double> slip = billiards::detail::slip_of(e.state);
    e.phase = billiards::detail::motion_with(e.state, slip);
    e.duration = billiards::detail::phase_duration(e.state, physics_.cloth, e.phase, slip);
    e.moving = e.phase == Motion::sliding || e.phase == Motion::rolling;
    const Cloth<double>& cloth = physics_.cloth;
    if (e.phase == Motion::sliding) {
      const double k = cloth.sliding_friction * cloth.gravity / slip.speed;
      e.horizontal_acceleration[0] = -k * slip.vector.x();
      e.horizontal_acceleration[1] = -k * slip.vector.y();
    } else if (e.phase == Motion::rolling) {
      const Eigen::Vector2d a = acceleration(e.state, e.phase);
      e.horizontal_acceleration[0] = a.x();
      e.horizontal_acceleration[1] = a.y();
    }
  }

  // Ball i's state now becomes its reference state.
  void settle(std::size_t i) {
    Entry& e = balls_[i];
    if (e.pocketed) return;
    e.state = at(i, now_);
    e.since = now_;
  }

  void keyframe(std::size_t i) {
    if (history_.size() <= i) history_.resize(i + 1);
    history_[i].push_back({now_, balls_[i].state, balls_[i].pocketed});
  }

  [[nodiscard]] bool current(const Predicted& p) const {
    if (balls_[p.ball].version != p.version || balls_[p.ball].pocketed) return false;
    if (p.kind == ShotEvent::Kind::ball) return balls_[p.other].version == p.other_version && !balls_[p.other].pocketed;
    return true;
  }

  void push(double t, ShotEvent::Kind kind, std::size_t i, std::size_t other) {
    const std::uint64_t other_version = kind == ShotEvent::Kind::ball ? balls_[other].version : 0;
    queue_.push({t, kind, i, other, balls_[i].version, other_version});
  }

  // The time left in ball j's phase from now, finite (the largest double for a phase without end).
  [[nodiscard]] double remaining(std::size_t j) const {
    const Entry& e = balls_[j];
    const double left = e.duration - (now_ - e.since);
    return std::isfinite(left) ? std::max(left, 0.0) : std::numeric_limits<double>::max();
  }

  // The box holding ball i's centre from now over the next `horizon` seconds of its phase (each
  // coordinate a parabola: its extremes at the ends and at its vertex).
  // The range of x0 + v t + ½ a t² over t in [0, horizon], widened by rounding's share (a millionth of
  // the range and of the radius).
  [[nodiscard]] std::pair<double, double> range(double x, double v, double a, double horizon, bool moving) const {
    double low = x, high = x;
    if (moving) {
      const double end = x + v * horizon + 0.5 * a * horizon * horizon;
      low = std::min(low, end);
      high = std::max(high, end);
      const double vertex = a != 0 ? -v / a : 0;
      if (vertex > 0 && vertex < horizon) {
        const double turn = x + v * vertex + 0.5 * a * vertex * vertex;
        low = std::min(low, turn);
        high = std::max(high, turn);
      }
    }
    const double slack = 1e-6 * (high - low + physics_.radius);
    return {low - slack, high + slack};
  }
  void bound(std::size_t i, double horizon) {
    Entry& e = balls_[i];
    const auto [x_low, x_high] = range(e.state.position.x(), e.state.velocity.x(), e.horizontal_acceleration[0],
                                       horizon, e.moving);
    const auto [y_low, y_high] = range(e.state.position.y(), e.state.velocity.y(), e.horizontal_acceleration[1],
                                       horizon, e.moving);
    e.box = {x_low, x_high, y_low, y_high};
  }
  [[nodiscard]] bool box_near(const Entry& e, const Eigen::Vector2d& centre, double reach) const {
    return centre.x() >= e.box[0] - reach && centre.x() <= e.box[1] + reach && centre.y() >= e.box[2] - reach &&
           centre.y() <= e.box[3] + reach;
  }

  // Ball i's next events from now (its reference time): its phase's end, the cushions, jaws and pockets,
  // and the balls from index `first_other` on (all of them but i and `skip` after an event; those above i
  // at the start, so that each pair is predicted once). A ball's events after its first contact with a
  // cushion, jaw or pocket are not looked for: it changes there and is predicted again. Its path until
  // then (`reach_end`) is bounded by a box, and a ball, jaw or pocket out of the box's reach is passed
  // over without solving for its contact.
  void predict(std::size_t i, std::size_t first_other, std::size_t skip = std::numeric_limits<std::size_t>::max(),
               detail::ExcludedContact excluded = {}) {
    Entry& e = balls_[i];
    if (e.pocketed) return;
    if (std::isfinite(e.duration)) push(now_ + e.duration, ShotEvent::Kind::transition, i, i);
    double horizon = remaining(i);
    const double R = physics_.radius;
    const Eigen::Vector2d r(e.state.position.x(), e.state.position.y()), v(e.state.velocity.x(), e.state.velocity.y());
    const Eigen::Vector2d a(e.horizontal_acceleration[0], e.horizontal_acceleration[1]);
    if (e.moving) {
      for (std::size_t k = 0; k < cushions_.size(); ++k) {
        const CushionSegment& c = cushions_[k];
        std::array<double, 3> q = cushion_polynomial((r - c.start).dot(c.normal), v.dot(c.normal), a.dot(c.normal), R);
        touching(q, 1);
        if (stays_apart(q, horizon)) continue;
        const std::optional<double> t = earliest_contact(q, horizon);
        if (!t || excluded(ShotEvent::Kind::cushion, k, *t)) continue;
        // Within the straight part: beyond its ends the jaws take the ball.
        const Eigen::Vector2d there = r + *t * v + (0.5 * *t * *t) * a;
        const Eigen::Vector2d along = c.end - c.start;
        const double f = (there - c.start).dot(along);
        if (f >= 0 && f <= along.squaredNorm()) {
          push(now_ + *t, ShotEvent::Kind::cushion, i, k);
          horizon = std::min(horizon, *t);
        }
      }
      bound(i, horizon);
      for (std::size_t k = 0; k < jaws_.size(); ++k) {
        if (!box_near(e, jaws_[k].centre, R + jaws_[k].radius)) continue;
        std::array<double, 5> p = contact_polynomial<double>(r - jaws_[k].centre, v, a, R + jaws_[k].radius);
        touching(p, 2 * (R + jaws_[k].radius));
        const std::optional<double> t = earliest_contact(p, horizon);
        if (!t || excluded(ShotEvent::Kind::jaw, k, *t)) continue;
        push(now_ + *t, ShotEvent::Kind::jaw, i, k);
        horizon = std::min(horizon, *t);
      }
      for (std::size_t k = 0; k < pockets_.size(); ++k) {
        if (!box_near(e, pockets_[k].centre, pockets_[k].radius)) continue;
        const std::array<double, 5> p = contact_polynomial<double>(r - pockets_[k].centre, v, a, pockets_[k].radius);
        const std::optional<double> t = earliest_contact(p, horizon);
        if (!t) continue;
        push(now_ + *t, ShotEvent::Kind::pocket, i, k);
        horizon = std::min(horizon, *t);
      }
    }
    bound(i, horizon);
    e.reach_end = e.moving ? now_ + horizon : std::numeric_limits<double>::infinity();
    predict_pairs(i, first_other, skip, excluded);
  }

  // Ball i's contacts with the balls from `first_other` on but `skip`, until the earlier of the two's
  // reach_end (see predict).
  void predict_pairs(std::size_t i, std::size_t first_other, std::size_t skip, detail::ExcludedContact excluded) {
    const Entry& e = balls_[i];
    const double R = physics_.radius;
    const Eigen::Vector2d r(e.state.position.x(), e.state.position.y()), v(e.state.velocity.x(), e.state.velocity.y());
    const Eigen::Vector2d a(e.horizontal_acceleration[0], e.horizontal_acceleration[1]);
    for (std::size_t j = first_other; j < balls_.size(); ++j) {
      const Entry& o = balls_[j];
      if (j == i || j == skip || o.pocketed || (!e.moving && !o.moving)) continue;
      const double end = std::min(e.reach_end, o.reach_end);
      if (!(end >= now_)) continue;  // the other's box ends before now: it changes at once
      if (!(o.box[0] - 2 * R <= e.box[1] && e.box[0] <= o.box[1] + 2 * R && o.box[2] - 2 * R <= e.box[3] &&
            e.box[2] <= o.box[3] + 2 * R))
        continue;
      const auto [position, velocity] = centre_and_velocity(j, now_);
      const Eigen::Vector2d dr = position - r, dv = velocity - v;
      const Eigen::Vector2d da(o.horizontal_acceleration[0] - a.x(), o.horizontal_acceleration[1] - a.y());
      std::array<double, 5> p = contact_polynomial<double>(dr, dv, da, 2 * R);
      touching(p, 4 * R);
      const double pair_horizon = std::isfinite(end) ? end - now_ : std::numeric_limits<double>::max();
      const std::optional<double> t = earliest_contact(p, pair_horizon);
      if (t && !excluded(ShotEvent::Kind::ball, j, *t)) push(now_ + *t, ShotEvent::Kind::ball, i, j);
    }
  }

  // Whether a cushion's polynomial, apart now and not convex (c2 ≤ 0: a ball moving off the cushion
  // as the cloth slows it), stays above its rounding up to the horizon: its least value on [0, horizon]
  // is at an end. earliest_contact finds the same, after a search for the turning point.
  [[nodiscard]] static bool stays_apart(const std::array<double, 3>& q, double horizon) {
    if (!(q[0] > 0 && q[2] <= 0)) return false;
    const billiards::detail::EventPolynomial<double> p{{q[0], q[1], q[2], 0, 0}, 2};
    return billiards::detail::evaluate(p, horizon) > billiards::detail::evaluation_error(p, horizon);
  }

  // Bodies overlapping by at most overlap_tolerance of a radius (rounding, after a contact) count as
  // touching: the polynomial starts at 0, so that bodies that separate and then approach again meet —
  // from a value just below 0 the polynomial might never reach 0 from above. `scale` is the polynomial's
  // derivative by the gap at contact (1 for a cushion's, 2D for a circle's).
  void touching(std::span<double> p, double scale) const {
    if (p[0] < 0 && p[0] >= -scale * physics_.radius * overlap_tolerance) p[0] = 0;
  }

  // Ball i changed now: its old predictions are stale; its phase begins again and it is predicted against
  // everything but `skip` (the other ball of a ball–ball event, predicted with it already).
  void changed(std::size_t i, std::size_t skip, detail::ExcludedContact excluded = {}) {
    ++balls_[i].version;
    begin_phase(i);
    keyframe(i);
    predict(i, 0, skip, excluded);
  }

  void record(ShotEvent::Kind kind, std::size_t i, std::size_t other, Motion from) {
    ShotEvent event;
    event.kind = kind;
    event.time = now_;
    event.ball = i;
    event.other = other;
    event.from = from;
    event.to = balls_[i].phase;
    event.ball_after = as_pool_ball(balls_[i].state, balls_[i].pocketed);
    event.other_after = kind == ShotEvent::Kind::ball ? as_pool_ball(balls_[other].state, false) : event.ball_after;
    events_.push_back(event);
  }

  [[nodiscard]] SpinningBall<double> spinning(const BallOnCloth<double>& s) const {
    return {s.velocity, s.angular_velocity, physics_.mass, physics_.radius};
  }
  static bool same(const SpinningBall<double>& after, const BallOnCloth<double>& before) {
    return after.velocity == before.velocity && after.angular_velocity == before.angular_velocity;
  }
  void take(std::size_t i, const SpinningBall<double>& after) {
    balls_[i].state.velocity = after.velocity;
    balls_[i].state.velocity.z() = 0;  // the cloth's reaction: a ball on the cloth stays on it
    balls_[i].state.angular_velocity = after.angular_velocity;
  }

  void resolve(const Predicted& p) {
    const double energy_before_event = options_.check_invariants ? energy_at(p.time) : 0;
    now_ = p.time;
    const std::size_t i = p.ball;
    Entry& e = balls_[i];
    const Motion from = e.phase;
    std::size_t skip = balls_.size();
    switch (p.kind) {
      case ShotEvent::Kind::transition: {
        // The phase's end: evolved by its predicted duration from its start (now − since may round a
        // sliver short of it), then set to the next phase exactly should rounding have left it short.
        BallOnCloth<double> end = evolve(e.state, physics_.cloth, e.duration);
        if (motion(end, physics_.cloth) == from) end = finish(end, from);
        e.state = end;
        e.since = now_;
        break;
      }
      case ShotEvent::Kind::ball: {
        const BallOnCloth<double> a = at(i, now_), b = at(p.other, now_);
        Eigen::Vector3d n = b.position - a.position;
        n.z() = 0;
        n /= n.norm();
        const auto after = collide_with_friction(spinning(a), spinning(b), n, physics_.ball_restitution,
                                                 physics_.ball_friction);
        // Bodies that no longer approach (rounding at a graze) are left as they move.
        if (same(after.first, a) && same(after.second, b)) {
          // No longer approaching: nothing changes, but the two are predicted again from here, with each
          // other only after now.
          settle(i);
          settle(p.other);
          changed(i, balls_.size(), {ShotEvent::Kind::ball, p.other});
          changed(p.other, i);
          return;
        }
        settle(i);
        settle(p.other);
        take(i, after.first);
        take(p.other, after.second);
        separate_pressed_pair(i, p.other, n);
        skip = p.other;
        break;
      }
      case ShotEvent::Kind::cushion:
      case ShotEvent::Kind::jaw: {
        const BallOnCloth<double> a = at(i, now_);
        Eigen::Vector3d n;
        if (p.kind == ShotEvent::Kind::cushion) {
          n = {-cushions_[p.other].normal.x(), -cushions_[p.other].normal.y(), 0};
        } else {
          const Eigen::Vector2d towards = jaws_[p.other].centre - Eigen::Vector2d(a.position.x(), a.position.y());
          n = {towards.x() / towards.norm(), towards.y() / towards.norm(), 0};
        }
        const SpinningBall<double> after = collide_with_cushion(
            spinning(a), Cushion<double>{n, table_.nose_height, physics_.cushion_restitution, physics_.cushion_friction});
        if (same(after, a)) {
          settle(i);
          changed(i, balls_.size(), {p.kind, p.other});
          return;
        }
        settle(i);
        take(i, after);
        separate_pressed_ball(i, n);
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
    changed(i, skip);
    if (p.kind == ShotEvent::Kind::ball) changed(p.other, balls_.size());
    record(p.kind, i, p.other, from);
    if (options_.check_invariants) check(energy_before_event);
  }

  // A contact the cloth's friction presses together (the relative acceleration along the normal closes
  // the gap) that leaves the bodies separating slower than pressing_speed would meet again at once, over
  // and over: inelastic collapse, without end before a phase ends. Such a contact leaves them separating
  // at pressing_speed, paid for from their relative velocity along the contact plane and then from their
  // spins, so that the kinetic energy stays what the contact left and momentum is kept. In units of the
  // reduced mass's half (m/4 for two balls, m/2 for a ball at a cushion): `normal` the separation speed,
  // `tangential` the relative velocity along the plane, `spin_energy` the spins' kinetic energy. Returns
  // the new separation speed, the factor for the tangential velocity and the factor for the spins.
  struct Separation {
    double normal, tangential_factor, spin_factor;
  };
  static Separation separation(double normal, double tangential_squared, double spin_energy) {
    const double need = pressing_speed * pressing_speed - normal * normal;
    const double from_tangential = std::min(need, tangential_squared);
    const double from_spin = std::min(need - from_tangential, spin_energy);
    return {std::sqrt(normal * normal + from_tangential + from_spin),
            tangential_squared > 0 ? std::sqrt((tangential_squared - from_tangential) / tangential_squared) : 1.0,
            spin_energy > 0 ? std::sqrt(std::max(spin_energy - from_spin, 0.0) / spin_energy) : 1.0};
  }

  // Two balls after their contact along `normal` (from i to j).
  void separate_pressed_pair(std::size_t i, std::size_t j, const Eigen::Vector3d& normal) {
    BallOnCloth<double>& a = balls_[i].state;
    BallOnCloth<double>& b = balls_[j].state;
    const Eigen::Vector2d n(normal.x(), normal.y());
    const Eigen::Vector2d pressing = acceleration(b, motion(b, physics_.cloth)) - acceleration(a, motion(a, physics_.cloth));
    const Eigen::Vector2d va(a.velocity.x(), a.velocity.y()), vb(b.velocity.x(), b.velocity.y());
    const Eigen::Vector2d centre = 0.5 * (va + vb), w = vb - va;
    const double along = w.dot(n);
    if (!(pressing.dot(n) < 0) || !(along < pressing_speed)) return;
    const Eigen::Vector2d tangential = w - along * n;
    const double R = physics_.radius;
    // Rotational energy 0.2 m R² ω² per ball, in units of m/4.
    const double spin = 0.8 * R * R * (a.angular_velocity.squaredNorm() + b.angular_velocity.squaredNorm());
    const Separation s = separation(along, tangential.squaredNorm(), spin);
    const Eigen::Vector2d turned = s.normal * n + s.tangential_factor * tangential;
    a.velocity.head<2>() = centre - 0.5 * turned;
    b.velocity.head<2>() = centre + 0.5 * turned;
    a.angular_velocity *= s.spin_factor;
    b.angular_velocity *= s.spin_factor;
  }

  // A ball after its contact with a cushion or jaw, `normal` from the ball towards it.
  void separate_pressed_ball(std::size_t i, const Eigen::Vector3d& normal) {
    BallOnCloth<double>& a = balls_[i].state;
    const Eigen::Vector2d n(-normal.x(), -normal.y());  // from the cushion or jaw into the table
    const Eigen::Vector2d v(a.velocity.x(), a.velocity.y());
    const double along = v.dot(n);
    if (!(acceleration(a, motion(a, physics_.cloth)).dot(n) < 0) || !(along < pressing_speed)) return;
    const Eigen::Vector2d tangential = v - along * n;
    const double R = physics_.radius;
    // Rotational energy 0.2 m R² ω², in units of m/2.
    const Separation s = separation(along, tangential.squaredNorm(), 0.4 * R * R * a.angular_velocity.squaredNorm());
    a.velocity.head<2>() = s.normal * n + s.tangential_factor * tangential;
    a.angular_velocity *= s.spin_factor;
  }

  // A state rounding left a sliver short of its phase's end, set to the end exactly (the next phase:
  // rolling without slip, at rest, or without spin about ẑ).
  [[nodiscard]] BallOnCloth<double> finish(const BallOnCloth<double>& s, Motion phase) const {
    BallOnCloth<double> out = s;
    const Eigen::Vector3d up(0, 0, 1);
    switch (phase) {
      case Motion::sliding: {
        out.velocity = s.velocity - (2.0 / 7.0) * contact_slip(s);
        out.velocity.z() = 0;
        const Eigen::Vector3d spin = up.cross(out.velocity) / s.radius;
        out.angular_velocity.x() = spin.x();
        out.angular_velocity.y() = spin.y();
        break;
      }
      case Motion::rolling:
        out.velocity.setZero();
        out.angular_velocity.x() = out.angular_velocity.y() = 0;
        break;
      case Motion::spinning: out.angular_velocity.z() = 0; break;
      case Motion::stationary: break;
    }
    return out;
  }

  [[nodiscard]] double energy_at(double t) const {
    double sum = 0;
    for (std::size_t i = 0; i < balls_.size(); ++i) sum += energy_of(i, std::max(t, balls_[i].since));
    return sum;
  }

  // The invariants after an event (every ball, every pair): see play().
  void check(double energy_before_event) {
    const double R = physics_.radius, slack = R * overlap_tolerance;
    std::vector<Eigen::Vector3d> at_now(balls_.size());
    for (std::size_t i = 0; i < balls_.size(); ++i) at_now[i] = at(i, now_).position;
    const auto fail = [&](std::size_t i, const std::string& what) {
      throw BrokenInvariant("billiards::simulation::Shot: at t = " + number(now_) + " s (event " +
                            std::to_string(events_.size()) + ", " + kind_name(events_.back().kind) + "), ball " +
                            std::to_string(i) + " " + what);
    };
    // How far behind a nose line a ball's centre may be: inside a pocket's capture circle, at the most.
    double reach = 0;
    for (const Pocket& pocket : pockets_) {
      reach = std::max({reach, -pocket.centre.x() + pocket.radius, pocket.centre.x() + pocket.radius - table_.length,
                        -pocket.centre.y() + pocket.radius, pocket.centre.y() + pocket.radius - table_.width});
    }
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      if (balls_[i].pocketed) continue;
      const Eigen::Vector2d r(at_now[i].x(), at_now[i].y());
      if (!(r.x() > -reach && r.x() < table_.length + reach && r.y() > -reach && r.y() < table_.width + reach))
        fail(i, "left the table at (" + number(r.x()) + ", " + number(r.y()) + ")");
      for (std::size_t k = 0; k < cushions_.size(); ++k) {
        const CushionSegment& c = cushions_[k];
        const Eigen::Vector2d along = c.end - c.start;
        const double f = (r - c.start).dot(along);
        if (f >= 0 && f <= along.squaredNorm() && (r - c.start).dot(c.normal) < R - slack)
          fail(i, "is inside cushion " + std::to_string(k) + ": its centre " + number((r - c.start).dot(c.normal)) +
                      " m from the nose line");
      }
      for (std::size_t k = 0; k < jaws_.size(); ++k) {
        if ((r - jaws_[k].centre).norm() < R + jaws_[k].radius - slack) fail(i, "is inside jaw " + std::to_string(k));
      }
      for (std::size_t j = i + 1; j < balls_.size(); ++j) {
        if (balls_[j].pocketed) continue;
        const double d = distance(at_now[i], at_now[j]);
        if (d < 2 * R - slack) fail(i, "overlaps ball " + std::to_string(j) + " by " + number(2 * R - d) + " m");
      }
    }
    const double after = energy();
    const double allowed = energy_tolerance * energy_scale_;
    if (!(energy_before_event <= last_energy_ + allowed))
      fail(events_.back().ball, "gained kinetic energy between events: " + number(last_energy_) + " J to " +
                                    number(energy_before_event) + " J");
    if (!(after <= energy_before_event + allowed))
      fail(events_.back().ball,
           "gained kinetic energy at the event: " + number(energy_before_event) + " J to " + number(after) + " J");
    last_energy_ = after;
  }

  PoolTable table_;
  PoolPhysics physics_;
  ShotOptions options_;
  std::vector<CushionSegment> cushions_;
  std::vector<Jaw> jaws_;
  std::vector<Pocket> pockets_;
  std::vector<Entry> balls_;
  std::vector<std::vector<Keyframe>> history_;
  std::vector<ShotEvent> events_;
  std::priority_queue<Predicted, std::vector<Predicted>, std::greater<>> queue_;
  double now_ = 0;
  double energy_scale_ = 0;
  double last_energy_ = 0;
};

}  // namespace billiards::simulation
