/// \file
/// What a shot reports: its events (the cue strike, contacts, pockets, the ends of phases), their
/// kinds' and the phases' names, and how a shot plays (ShotOptions).
#pragma once

#include <billiards/simulation/shot/pool_table.hpp>

#include <billiards/cloth.hpp>

#include <cstddef>
#include <cstdint>

namespace billiards::simulation {

/// What happened at an event of a shot.
struct ShotEvent {
  /// The kinds of events, in the order in which events at the same time are resolved.
  enum class Kind {
    strike,      ///< the cue struck `first`
    ball,        ///< `first` met ball `second`
    cushion,     ///< `first` met straight cushion `second` (PoolTable::cushions())
    jaw,         ///< `first` met jaw `second` (PoolTable::jaws())
    pocket,      ///< `first` entered pocket `second` (PoolTable::pockets()) and left play
    transition,  ///< `first`'s phase ended: `from` → `to`
  };
  double time = 0;                   ///< seconds since the shot began
  Kind kind = Kind::strike;          ///< what happened
  std::size_t first = 0;             ///< the ball (its index)
  std::size_t second = 0;            ///< the other ball, the cushion, the jaw or the pocket (else `first`)
  Motion from = Motion::stationary;  ///< `first`'s phase before the event
  Motion to = Motion::stationary;    ///< `first`'s phase after it
  PoolBall first_after;              ///< `first`'s state after the event
  PoolBall second_after;  ///< the other ball's state after a ball–ball event (else `first_after`)
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
  /// The most events a shot may take; a run beyond it stops with billiards::simulation::EventLimitReached.
  std::uint64_t event_limit = 100000;
  /// The engine's tolerance for sustained contact (m/s; Shot's description): bodies the cloth presses
  /// together that leave a contact slower than this are in sustained contact from there (off the line
  /// of the contact: leave it at this speed). Smaller resolves more of an inelastic collapse contact by
  /// contact before its limit, at a few dozen more events for each tenfold; > 0 and finite.
  double pressing_speed = 1e-3;
  /// Check the invariants at every event: on in debug builds, off where NDEBUG is defined.
#ifdef NDEBUG
  bool check_invariants = false;
#else
  bool check_invariants = true;
#endif
};

}  // namespace billiards::simulation
