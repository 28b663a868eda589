/// \file
/// 8-ball after the WPA's World Standardized Rules, decided from a shot's events: the break, the open
/// table and the groups (solids 1–7, stripes 9–15), the player's own group first, the fouls and ball in
/// hand, the 8 ending the game. Which rules are in and which are left out: docs/eight_ball.md.
#pragma once

#include <billiards/simulation/games/nine_ball.hpp>
#include <billiards/simulation/games/rules.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <string>

namespace billiards::simulation::games {

/// A player's group of balls in 8-ball.
enum class Group {
  open,     ///< not yet chosen: the table is open
  solids,   ///< balls 1 to 7
  stripes,  ///< balls 9 to 15
};

/// The group of object ball `ball` (the 8 and the cue ball: open, in neither group).
[[nodiscard]] inline Group group_of(std::size_t ball) noexcept {
  return ball >= 1 && ball <= 7 ? Group::solids : ball >= 9 && ball <= 15 ? Group::stripes : Group::open;
}

/// A game of 8-ball between two players: ball 0 is the cue ball, balls 1 to 15 the object balls.
struct EightBallState {
  std::array<bool, 16> on_table{true, true, true, true, true, true, true, true,
                                true, true, true, true, true, true, true, true};  ///< by number
  std::size_t player = 0;                                 ///< whose turn it is (0 or 1)
  bool breaking = true;                                   ///< the next shot is the break
  std::array<Group, 2> groups{Group::open, Group::open};  ///< each player's group
  BallInHand ball_in_hand = BallInHand::none;  ///< where the player to shoot may place the cue ball
  bool over = false;                           ///< the game has ended
  std::optional<std::size_t> winner;           ///< who won, where it has ended

  /// Whether `player` has pocketed every ball of their group (and so shoots at the 8).
  [[nodiscard]] bool on_the_eight(std::size_t who) const noexcept {
    if (groups[who] == Group::open) return false;
    for (std::size_t b = 1; b <= 15; ++b)
      if (on_table[b] && group_of(b) == groups[who]) return false;
    return true;
  }
  /// Whether the player to shoot may meet `ball` first.
  [[nodiscard]] bool may_hit_first(std::size_t ball) const noexcept {
    if (on_the_eight(player)) return ball == 8;
    if (groups[player] == Group::open) return ball != 8;
    return group_of(ball) == groups[player];
  }
};

namespace detail {

// The fouls of an 8-ball shot after the break.
inline std::vector<Foul> eight_ball_fouls(const EightBallState& state, const ShotSummary& s) {
  std::vector<Foul> fouls;
  if (!s.first_contact)
    fouls.push_back(Foul::no_contact);
  else if (!state.may_hit_first(*s.first_contact))
    fouls.push_back(Foul::wrong_ball_first);
  if (s.first_contact && s.pocketed.empty() && !s.cushion_after_contact) fouls.push_back(Foul::no_rail);
  if (s.cue_ball_pocketed) fouls.push_back(Foul::scratch);
  return fouls;
}

// The break: a scratch is a foul (ball in hand behind the head string); a break that pockets nothing and
// drives fewer than four object balls to a cushion passes the turn; an 8 pocketed is respotted.
inline void eight_ball_break(const ShotSummary& s, Decision<EightBallState>& d) {
  Verdict& v = d.verdict;
  const std::size_t shooter = d.next.player, other = 1 - shooter;
  if (s.cue_ball_pocketed) v.fouls.push_back(Foul::scratch);
  const bool eight_down = std::find(s.pocketed.begin(), s.pocketed.end(), 8) != s.pocketed.end();
  if (eight_down) {
    d.next.on_table[8] = true;
    v.respotted.push_back(8);
  }
  if (!v.legal()) {
    v.next_player = other;
    v.ball_in_hand = BallInHand::behind_head_string;
    v.reason = "a scratch on the break: the incoming player has the cue ball in hand behind the head string";
  } else if (s.pocketed.empty() && s.object_balls_to_cushion.size() < 4) {
    v.next_player = other;
    v.reason =
        "an illegal break (nothing pocketed, fewer than four object balls to a cushion): the incoming "
        "player accepts the table as it lies";
  } else if (!s.pocketed.empty() && !(eight_down && s.pocketed.size() == 1)) {
    v.next_player = shooter;
    v.reason = "a ball pocketed on the break: the breaker continues, the table open";
  } else {
    v.next_player = eight_down ? shooter : other;
    v.reason = eight_down ? "the 8 pocketed on the break: respotted, the breaker continues"
                          : "a legal break that pocketed nothing: the turn passes";
  }
  if (eight_down && v.legal()) v.reason += " (the 8 respotted)";
}

// After the break: the 8, the groups, the turn.
inline void eight_ball_shot(const EightBallState& state, const ShotSummary& s, Decision<EightBallState>& d) {
  Verdict& v = d.verdict;
  const std::size_t shooter = state.player, other = 1 - shooter;
  v.fouls = eight_ball_fouls(state, s);
  const bool eight_down = std::find(s.pocketed.begin(), s.pocketed.end(), 8) != s.pocketed.end();
  if (eight_down) {
    const bool wins = v.legal() && state.on_the_eight(shooter);
    v.game_over = d.next.over = true;
    v.winner = d.next.winner = wins ? shooter : other;
    v.reason = wins        ? "the 8 pocketed on a legal shot after the shooter's group: the shooter wins"
               : v.legal() ? "the 8 pocketed before the shooter's group was cleared: the shooter loses"
                           : "the 8 pocketed on a foul: the shooter loses";
    return;
  }
  if (!v.legal()) {
    v.next_player = other;
    v.ball_in_hand = BallInHand::anywhere;
    v.reason = std::string("a foul (") + foul_name(v.fouls.front()) +
               "): the incoming player has the cue ball in hand anywhere";
    return;
  }
  if (state.groups[shooter] == Group::open && !s.pocketed.empty()) {
    // The table open: the group of the first ball pocketed on this legal shot becomes the shooter's.
    d.next.groups[shooter] = group_of(s.pocketed.front());
    d.next.groups[other] = d.next.groups[shooter] == Group::solids ? Group::stripes : Group::solids;
  }
  const Group own = d.next.groups[shooter];
  const bool own_down =
      std::any_of(s.pocketed.begin(), s.pocketed.end(), [&](std::size_t b) { return group_of(b) == own; });
  v.next_player = own_down ? shooter : other;
  v.reason = own_down ? "a ball of the shooter's group pocketed on a legal shot: the shooter continues"
                      : "a legal shot that pocketed none of the shooter's group: the turn passes";
}

}  // namespace detail

/// The rules' decision on one shot of 8-ball: `events` are the shot's (Shot::events(), beginning with
/// the strike of the cue ball, ball 0), `state` the game before it. Throws std::invalid_argument for a
/// game already over, a player other than 0 or 1, events that are not one shot's, or a pocketed ball
/// that was not on the table.
inline Decision<EightBallState> eight_ball(const EightBallState& state, std::span<const ShotEvent> events) {
  return detail::decide("eight_ball", state, events, [&](const ShotSummary& s, Decision<EightBallState>& d) {
    if (state.breaking)
      detail::eight_ball_break(s, d);
    else
      detail::eight_ball_shot(state, s, d);
  });
}

}  // namespace billiards::simulation::games
