/// \file
/// The exceptions every engine throws, the same type for the same situation:
/// - bad input (a setup, an argument): std::invalid_argument (billiards::invalid_argument, which
///   derives from it, where a runtime call names the argument);
/// - an event limit reached: EventLimitReached, a std::runtime_error;
/// - an invariant broken at an event (a defect of the engine): BrokenInvariant, a std::logic_error.
/// Nothing left to happen is not an error: step() returns an empty optional.
#pragma once

#include <charconv>
#include <stdexcept>
#include <string>

namespace billiards::simulation {

/// A run stopped at an engine's limit on events: a shot that would take more than
/// ShotOptions::event_limit events without coming to rest, or a gas whose balls went on for more than
/// its limit of events in a row without a collision (their paths never meet).
class EventLimitReached : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An invariant broken at an event (two balls overlapping, a ball off the table, kinetic energy
/// gained): a defect of the engine, reported with the time, the event and the balls.
class BrokenInvariant : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

namespace detail {

/// The shortest text that reads back as x, for messages.
inline std::string shortest(double x) {
  char text[32];
  const auto written = std::to_chars(text, text + sizeof text, x);
  return std::string(text, written.ptr);
}

}  // namespace detail

}  // namespace billiards::simulation
