/// \file
/// Three-cushion billiards after the UMB's rules, decided from a shot's events: a point when the
/// shooter's cue ball meets both object balls and at least three cushions before it meets the second;
/// the shooter continues after a point; the first to the target wins. Which rules are in:
/// docs/three_cushion.md.
#pragma once

#include <billiards/simulation/games/nine_ball.hpp>
#include <billiards/simulation/games/rules.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

namespace billiards::simulation::games {

/// A game of three-cushion: ball 0 is player 0's cue ball (white), ball 1 player 1's (yellow), ball 2
/// the red. Every ball stays on the table (a carom table has no pockets).
struct ThreeCushionState {
  std::array<int, 2> scores{0, 0};    ///< each player's points
  std::size_t player = 0;             ///< whose turn it is (0 or 1): they strike ball `player`
  int target = 40;                    ///< the points that win the game (UMB events play to 40 or 50)
  bool over = false;                  ///< the game has ended
  std::optional<std::size_t> winner;  ///< who won, where it has ended
};

/// Whether the cue ball `cue_ball` scored: it met both other balls of 0, 1, 2, and met at least three
/// cushions before it met the second of them.
[[nodiscard]] inline bool three_cushion_point(std::span<const ShotEvent> events, std::size_t cue_ball) {
  int cushions = 0;
  std::optional<std::size_t> first;
  for (const ShotEvent& e : events) {
    if (e.first != cue_ball && !(e.kind == ShotEvent::Kind::ball && e.second == cue_ball)) continue;
    if (e.kind == ShotEvent::Kind::cushion || e.kind == ShotEvent::Kind::jaw) ++cushions;
    if (e.kind != ShotEvent::Kind::ball) continue;
    const std::size_t other = e.first == cue_ball ? e.second : e.first;
    if (!first)
      first = other;
    else if (other != *first)
      return cushions >= 3;
  }
  return false;
}

/// The rules' decision on one shot of three-cushion: `events` are the shot's, beginning with the strike
/// of the shooter's cue ball (ball `state.player`). Throws std::invalid_argument for a game already
/// over, a player other than 0 or 1, a target below 1, or events that are not one shot of that ball.
inline Decision<ThreeCushionState> three_cushion(const ThreeCushionState& state,
                                                 std::span<const ShotEvent> events) {
  check_player("three_cushion", state.player);
  if (state.over) throw std::invalid_argument("three_cushion: the game is over, expected a game in play");
  if (state.target < 1)
    throw std::invalid_argument("three_cushion: target is " + std::to_string(state.target) +
                                ", expected at least 1");
  const ShotSummary s = summarize(events, state.player);
  if (s.cue_ball_pocketed || !s.pocketed.empty())
    throw std::invalid_argument(
        "three_cushion: events: a ball pocketed, expected a carom table (no pockets)");
  Decision<ThreeCushionState> d{{}, state};
  Verdict& v = d.verdict;
  const std::size_t shooter = state.player, other = 1 - shooter;
  if (three_cushion_point(events, shooter)) {
    v.points = 1;
    if (++d.next.scores[shooter] >= state.target) {
      v.game_over = d.next.over = true;
      v.winner = d.next.winner = shooter;
      v.reason = "a point, the target reached: the shooter wins";
    } else {
      v.next_player = shooter;
      v.reason = "a point (both object balls, three cushions before the second): the shooter continues";
    }
  } else {
    v.next_player = other;
    v.reason = "no point: the turn passes";
  }
  if (!v.game_over) d.next.player = v.next_player;
  return d;
}

}  // namespace billiards::simulation::games
