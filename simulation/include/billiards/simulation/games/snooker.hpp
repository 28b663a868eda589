/// \file
/// Snooker after the WPBSA's rules, decided from a shot's events: a red, then a colour, while reds
/// remain (the colours respotted), then the colours in order; fouls worth 4 to 7 to the opponent; the
/// cue ball in hand in the D after it is pocketed; the frame's end on the last black (re-spotted on a
/// tie). Ball indices as snooker_setup() places them (snooker_ball::). Which rules are in and which are left
/// out: docs/snooker.md.
#pragma once

#include <billiards/simulation/games/nine_ball.hpp>
#include <billiards/simulation/games/rules.hpp>
#include <billiards/simulation/shot/layouts.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

namespace billiards::simulation::games {

/// What the player to shoot is on in snooker.
enum class SnookerOn {
  red,       ///< a red (reds remain, and the turn's last stroke did not pot one)
  colour,    ///< any colour, after a red potted (the first colour the cue ball meets is the nominated one)
  sequence,  ///< the lowest valued colour on the table: no red remains and the colour after the last is played
};

/// A frame of snooker between two players (snooker_ball:: indices: 0 the white, 1–15 the reds, 16–21 yellow
/// to black).
struct SnookerState {
  std::array<bool, snooker_ball::ball_count> on_table = [] {
    std::array<bool, snooker_ball::ball_count> all{};
    all.fill(true);
    return all;
  }();                                           ///< by index
  std::size_t player = 0;                        ///< whose turn it is (0 or 1)
  std::array<int, 2> scores{0, 0};               ///< each player's points in the frame
  SnookerOn on = SnookerOn::red;                 ///< what the player to shoot is on
  BallInHand ball_in_hand = BallInHand::in_d;    ///< in the D for the opening stroke
  bool over = false;                             ///< the frame has ended
  std::optional<std::size_t> winner;             ///< who won it, where it has ended

  /// The number of reds on the table.
  [[nodiscard]] int reds() const noexcept {
    int n = 0;
    for (std::size_t b = snooker_ball::first_red; b <= snooker_ball::last_red; ++b) n += on_table[b] ? 1 : 0;
    return n;
  }
  /// The lowest valued colour on the table (snooker_ball::yellow … snooker_ball::black; 0 where none is).
  [[nodiscard]] std::size_t lowest_colour() const noexcept {
    for (std::size_t b = snooker_ball::yellow; b <= snooker_ball::black; ++b)
      if (on_table[b]) return b;
    return 0;
  }
  /// Whether `ball` is on for the player to shoot.
  [[nodiscard]] bool is_on(std::size_t ball) const noexcept {
    switch (on) {
      case SnookerOn::red: return snooker_ball::is_red(ball);
      case SnookerOn::colour: return snooker_ball::is_colour(ball);
      case SnookerOn::sequence: return ball == lowest_colour();
    }
    return false;
  }
};

namespace detail {

// A snooker stroke's fouls and its penalty (WPBSA: the value of the ball on, of the ball first met, of
// any ball pocketed wrongly, at least 4). With a colour on, the ball on is the first colour met.
inline std::pair<std::vector<Foul>, int> snooker_fouls(const SnookerState& state, const ShotSummary& s) {
  std::vector<Foul> fouls;
  int penalty = 4;
  std::optional<std::size_t> on_ball;
  if (state.on == SnookerOn::red) on_ball = snooker_ball::first_red;
  if (state.on == SnookerOn::sequence) on_ball = state.lowest_colour();
  if (state.on == SnookerOn::colour && s.first_contact && snooker_ball::is_colour(*s.first_contact))
    on_ball = s.first_contact;
  if (on_ball) penalty = std::max(penalty, snooker_ball::value(*on_ball));
  if (!s.first_contact) {
    fouls.push_back(Foul::no_contact);
  } else {
    penalty = std::max(penalty, snooker_ball::value(*s.first_contact));
    if (!state.is_on(*s.first_contact)) fouls.push_back(Foul::wrong_ball_first);
  }
  bool wrong_potted = false;
  for (const std::size_t b : s.pocketed) {
    const bool allowed = state.on == SnookerOn::red ? snooker_ball::is_red(b) : on_ball && b == *on_ball;
    if (!allowed) {
      wrong_potted = true;
      penalty = std::max(penalty, snooker_ball::value(b));
    }
  }
  if (wrong_potted) fouls.push_back(Foul::wrong_ball_potted);
  if (s.cue_ball_pocketed) fouls.push_back(Foul::scratch);
  return {fouls, fouls.empty() ? 0 : penalty};
}

// The frame's end where the last black has gone (potted or by a foul): the higher score wins; on a tie
// the black is re-spotted and the opponent of the shooter plays from the D.
inline void snooker_last_black(const SnookerState& state, Decision<SnookerState>& d) {
  Verdict& v = d.verdict;
  SnookerState& next = d.next;
  if (next.scores[0] == next.scores[1]) {
    next.on_table[snooker_ball::black] = true;
    if (std::find(v.respotted.begin(), v.respotted.end(), snooker_ball::black) == v.respotted.end())
      v.respotted.push_back(snooker_ball::black);
    next.on = SnookerOn::sequence;
    v.next_player = 1 - state.player;
    v.ball_in_hand = BallInHand::in_d;
    v.reason += "; the scores tied: the black re-spotted, the opponent plays from the D";
    return;
  }
  v.game_over = next.over = true;
  v.winner = next.winner = next.scores[0] > next.scores[1] ? 0 : 1;
  v.reason += "; the last black: the frame is over";
}

// Snooker's rules on a stroke summed up as `s`.
inline void snooker_rules(const SnookerState& state, const ShotSummary& s, Decision<SnookerState>& d) {
  Verdict& v = d.verdict;
  SnookerState& next = d.next;
  const std::size_t other = 1 - state.player;
  auto [fouls, penalty] = snooker_fouls(state, s);
  v.fouls = std::move(fouls);
  const bool last_black = state.on == SnookerOn::sequence && state.lowest_colour() == snooker_ball::black;
  // The colours respotted: every colour potted on a foul, and while reds remain (or after the last red)
  // a colour potted on a legal stroke; in the sequence a legal pot stays down.
  for (const std::size_t b : s.pocketed) {
    if (!snooker_ball::is_colour(b)) continue;
    const bool stays_down = v.legal() && state.on == SnookerOn::sequence;
    if (!stays_down && !(last_black && b == snooker_ball::black)) {
      next.on_table[b] = true;
      v.respotted.push_back(b);
    }
  }
  const bool reds_left = next.reds() > 0;
  if (!v.legal()) {
    v.penalty = penalty;
    next.scores[other] += penalty;
    v.next_player = other;
    v.ball_in_hand = s.cue_ball_pocketed ? BallInHand::in_d : BallInHand::none;
    next.on = reds_left ? SnookerOn::red : SnookerOn::sequence;
    v.reason = std::string("a foul (") + foul_name(v.fouls.front()) + "): " + std::to_string(penalty) +
               " points to the opponent, who plays" + (s.cue_ball_pocketed ? " from the D" : "");
    if (last_black) snooker_last_black(state, d);
    return;
  }
  for (const std::size_t b : s.pocketed) v.points += snooker_ball::value(b);
  next.scores[state.player] += v.points;
  if (s.pocketed.empty()) {
    v.next_player = other;
    next.on = reds_left ? SnookerOn::red : SnookerOn::sequence;
    v.reason = "nothing potted: the turn passes";
    return;
  }
  v.next_player = state.player;
  next.on = state.on == SnookerOn::red ? SnookerOn::colour : reds_left ? SnookerOn::red : SnookerOn::sequence;
  v.reason = state.on == SnookerOn::red      ? "a red potted: the shooter is on a colour"
             : state.on == SnookerOn::colour ? "a colour potted after a red: it is respotted, the shooter continues"
                                             : "the colour on potted: the shooter continues on the next";
  if (last_black) snooker_last_black(state, d);
}

}  // namespace detail

/// The rules' decision on one stroke of snooker: `events` are the shot's (Shot::events(), beginning
/// with the strike of the white, ball 0), `state` the frame before it. Throws std::invalid_argument for
/// a frame already over, a player other than 0 or 1, events that are not one shot's, or a pocketed ball
/// that was not on the table.
inline Decision<SnookerState> snooker(const SnookerState& state, std::span<const ShotEvent> events) {
  check_player("snooker", state.player);
  if (state.over) throw std::invalid_argument("snooker: the frame is over, expected a frame in play");
  const ShotSummary s = summarize(events);
  detail::check_pocketed("snooker", state.on_table, s);
  Decision<SnookerState> d{{}, state};
  d.verdict.potted = s.pocketed;
  for (const std::size_t b : s.pocketed) d.next.on_table[b] = false;
  detail::snooker_rules(state, s, d);
  if (!d.verdict.game_over) d.next.player = d.verdict.next_player;
  d.next.ball_in_hand = d.verdict.game_over ? BallInHand::none : d.verdict.ball_in_hand;
  return d;
}

}  // namespace billiards::simulation::games
