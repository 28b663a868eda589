// Hand-built shot events for the rules' tests: the strike of a ball, then contacts, cushions and pockets
// 0.1 s apart, as Shot::events() lists them.
#pragma once

#include <billiards/simulation/shot/event.hpp>

#include <cstddef>
#include <initializer_list>
#include <vector>

namespace game_events {

using Kind = billiards::simulation::ShotEvent::Kind;

struct Step {
  Kind kind;
  std::size_t first, second;
};

// A shot's events: the strike of ball `striker` (0 unless given), then `steps` 0.1 s apart.
inline std::vector<billiards::simulation::ShotEvent> events_of(std::initializer_list<Step> steps,
                                                              std::size_t striker = 0) {
  std::vector<billiards::simulation::ShotEvent> events(1);
  events[0].kind = Kind::strike;
  events[0].first = events[0].second = striker;
  double t = 0;
  for (const Step& s : steps) {
    billiards::simulation::ShotEvent e;
    e.time = t += 0.1;
    e.kind = s.kind;
    e.first = s.first;
    e.second = s.second;
    events.push_back(e);
  }
  return events;
}

inline Step hit(std::size_t a, std::size_t b) { return {Kind::ball, a, b}; }
inline Step rail(std::size_t a, std::size_t cushion = 2) { return {Kind::cushion, a, cushion}; }
inline Step drop(std::size_t a, std::size_t pocket = 1) { return {Kind::pocket, a, pocket}; }

}  // namespace game_events
