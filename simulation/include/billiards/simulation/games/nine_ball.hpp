/// \file
/// 9-ball after the WPA's World Standardized Rules, decided from a shot's events: the break, the lowest
/// numbered ball first, the fouls and ball in hand, the 9 ending the game, three fouls in a row losing
/// it. Which rules are in and which are left out: docs/nine_ball.md.
#pragma once

#include <billiards/simulation/games/rules.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

namespace billiards::simulation::games {

/// A game of 9-ball between two players: ball 0 is the cue ball, balls 1 to 9 the object balls.
struct NineBallState {
  std::array<bool, 10> on_table{true, true, true, true, true, true, true, true, true, true};  ///< by number
  std::size_t player = 0;                      ///< whose turn it is (0 or 1)
  bool breaking = true;                        ///< the next shot is the break
  std::array<int, 2> fouls_in_a_row{0, 0};     ///< each player's fouls since their last legal shot
  BallInHand ball_in_hand = BallInHand::none;  ///< where the player to shoot may place the cue ball
  bool over = false;                           ///< the game has ended
  std::optional<std::size_t> winner;           ///< who won, where it has ended

  /// The lowest numbered object ball on the table (0 where none is).
  [[nodiscard]] std::size_t lowest() const noexcept {
    for (std::size_t b = 1; b <= 9; ++b)
      if (on_table[b]) return b;
    return 0;
  }
};

/// A decision and the game after it.
template <typename State>
struct Decision {
  Verdict verdict;  ///< what the rules decided
  State next;       ///< the game after the shot (the potted balls off the table, the respotted ones back)
};

namespace detail {

// The fouls of a 9-ball shot in the order the rule book lists them: the contact, the cushion, the
// cue ball, and (on the break) the break's own requirement.
inline std::vector<Foul> nine_ball_fouls(const NineBallState& state, const ShotSummary& s) {
  std::vector<Foul> fouls;
  if (!s.first_contact)
    fouls.push_back(Foul::no_contact);
  else if (*s.first_contact != state.lowest())
    fouls.push_back(Foul::wrong_ball_first);
  if (s.first_contact && s.pocketed.empty() && !s.cushion_after_contact) fouls.push_back(Foul::no_rail);
  if (s.cue_ball_pocketed) fouls.push_back(Foul::scratch);
  if (state.breaking && fouls.empty() && s.pocketed.empty() && s.object_balls_to_cushion.size() < 4)
    fouls.push_back(Foul::illegal_break);
  return fouls;
}

// Checks that every pocketed ball was on the table.
template <std::size_t N>
void check_pocketed(const char* game, const std::array<bool, N>& on_table, const ShotSummary& s) {
  for (const std::size_t b : s.pocketed) {
    if (b >= N || !on_table[b])
      throw std::invalid_argument(std::string(game) + ": events: ball " + std::to_string(b) +
                                  " is pocketed, expected a ball on the table");
  }
}

}  // namespace detail

namespace detail {

// What every game's decision does around its own rules: checks the state and the events, takes the
// pocketed balls off the table, ends the break, then calls `rules(summary, decision)`, and sets who
// shoots next and from where.
template <typename State, typename Rules>
Decision<State> decide(const char* game, const State& state, std::span<const ShotEvent> events,
                       Rules&& rules) {
  check_player(game, state.player);
  if (state.over)
    throw std::invalid_argument(std::string(game) + ": the game is over, expected a game in play");
  const ShotSummary s = summarize(events);
  check_pocketed(game, state.on_table, s);
  Decision<State> d{{}, state};
  d.verdict.potted = s.pocketed;
  for (const std::size_t b : s.pocketed) d.next.on_table[b] = false;
  d.next.breaking = false;
  rules(s, d);
  if (!d.verdict.game_over) d.next.player = d.verdict.next_player;
  d.next.ball_in_hand = d.verdict.game_over ? BallInHand::none : d.verdict.ball_in_hand;
  return d;
}

// 9-ball's rules on a shot summed up as `s`, the game before it `state`.
inline void nine_ball_rules(const NineBallState& state, const ShotSummary& s, Decision<NineBallState>& d) {
  Verdict& v = d.verdict;
  NineBallState& next = d.next;
  v.fouls = nine_ball_fouls(state, s);
  const std::size_t other = 1 - state.player;
  const bool nine_down = std::find(s.pocketed.begin(), s.pocketed.end(), 9) != s.pocketed.end();
  if (v.legal()) {
    next.fouls_in_a_row[state.player] = 0;
    if (nine_down) {
      v.game_over = next.over = true;
      v.winner = next.winner = state.player;
      v.reason = "the 9 pocketed on a legal shot: the shooter wins";
    } else {
      v.next_player = s.pocketed.empty() ? other : state.player;
      v.reason = s.pocketed.empty() ? "a legal shot that pocketed nothing: the turn passes"
                                    : "a ball pocketed on a legal shot: the shooter continues";
    }
    return;
  }
  if (nine_down) {
    next.on_table[9] = true;
    v.respotted.push_back(9);
  }
  v.next_player = other;
  v.ball_in_hand = BallInHand::anywhere;
  v.reason = std::string("a foul (") + foul_name(v.fouls.front()) +
             "): the incoming player has the cue ball in hand anywhere" +
             (nine_down ? ", the 9 respotted" : "");
  if (++next.fouls_in_a_row[state.player] >= 3) {
    v.game_over = next.over = true;
    v.winner = next.winner = other;
    v.reason = "a third foul in a row: the shooter loses the game";
  }
}

}  // namespace detail

/// The rules' decision on one shot of 9-ball: `events` are the shot's (Shot::events(), beginning with
/// the strike of the cue ball, ball 0), `state` the game before it. Throws std::invalid_argument for a
/// game already over, a player other than 0 or 1, events that are not one shot's, or a pocketed ball
/// that was not on the table.
inline Decision<NineBallState> nine_ball(const NineBallState& state, std::span<const ShotEvent> events) {
  return detail::decide("nine_ball", state, events, [&](const ShotSummary& s, Decision<NineBallState>& d) {
    detail::nine_ball_rules(state, s, d);
  });
}

}  // namespace billiards::simulation::games
