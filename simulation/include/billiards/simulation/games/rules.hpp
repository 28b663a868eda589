/// \file
/// What the rules of every game read from a shot: its events summed up (the cue ball's first contact,
/// the cushions met after it, the balls pocketed, the object balls driven to a cushion) and what a
/// rule's decision says (legal or which foul, what was potted and must be respotted, who plays next and
/// from where, whether the game is over). The games: nine_ball.hpp, eight_ball.hpp, snooker.hpp,
/// three_cushion.hpp.
#pragma once

#include <billiards/simulation/shot/event.hpp>

#include <cstddef>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace billiards::simulation::games {

/// A foul, as the rule books name them.
enum class Foul {
  scratch,           ///< the cue ball was pocketed
  no_contact,        ///< the cue ball met no object ball
  wrong_ball_first,  ///< the cue ball met first a ball it may not meet first
  no_rail,           ///< after the first contact no ball was pocketed and none met a cushion
  illegal_break,     ///< a break that pocketed nothing and drove fewer than four object balls to a cushion
  wrong_ball_potted,  ///< a ball that was not on was pocketed (snooker)
};

/// The name of a foul: "scratch", "no contact", "wrong ball first", "no rail", "illegal break", "wrong
/// ball potted".
inline const char* foul_name(Foul foul) noexcept {
  switch (foul) {
    case Foul::scratch: return "scratch";
    case Foul::no_contact: return "no contact";
    case Foul::wrong_ball_first: return "wrong ball first";
    case Foul::no_rail: return "no rail";
    case Foul::illegal_break: return "illegal break";
    case Foul::wrong_ball_potted: return "wrong ball potted";
  }
  return "unknown";
}

/// Where the next player may place the cue ball.
enum class BallInHand {
  none,                ///< nowhere: the cue ball stays where it stopped
  anywhere,            ///< anywhere on the cloth where it overlaps no ball
  behind_head_string,  ///< behind the head string (the quarter of the table nearest the head cushion)
  in_d,                ///< in the snooker D (snooker_markings)
};

/// A shot's events as the rules read them. A jaw counts as a cushion (it is a cushion's end).
struct ShotSummary {
  std::optional<std::size_t> first_contact;       ///< the first object ball the cue ball met
  bool cushion_after_contact = false;             ///< a ball met a cushion or a jaw after that first contact
  std::vector<std::size_t> pocketed;              ///< the object balls pocketed, in the order they dropped
  bool cue_ball_pocketed = false;                 ///< the cue ball was pocketed
  std::set<std::size_t> object_balls_to_cushion;  ///< the object balls that met a cushion or a jaw
};

/// Sums up the events of one shot, `cue_ball` the ball struck. Throws std::invalid_argument unless they
/// begin with the strike of `cue_ball` (the events of one shot, as Shot::events() gives them).
inline ShotSummary summarize(std::span<const ShotEvent> events, std::size_t cue_ball = 0) {
  if (events.empty() || events.front().kind != ShotEvent::Kind::strike || events.front().first != cue_ball)
    throw std::invalid_argument(
        "events: expected the events of one shot, beginning with the strike of ball " +
        std::to_string(cue_ball));
  ShotSummary s;
  for (const ShotEvent& e : events.subspan(1)) {
    switch (e.kind) {
      case ShotEvent::Kind::ball:
        if (!s.first_contact && (e.first == cue_ball || e.second == cue_ball))
          s.first_contact = e.first == cue_ball ? e.second : e.first;
        break;
      case ShotEvent::Kind::cushion:
      case ShotEvent::Kind::jaw:
        if (s.first_contact) s.cushion_after_contact = true;
        if (e.first != cue_ball) s.object_balls_to_cushion.insert(e.first);
        break;
      case ShotEvent::Kind::pocket:
        if (e.first == cue_ball)
          s.cue_ball_pocketed = true;
        else
          s.pocketed.push_back(e.first);
        break;
      case ShotEvent::Kind::strike:
        throw std::invalid_argument("events: a second strike at t = " + std::to_string(e.time) +
                                    " s, expected the events of one shot");
      case ShotEvent::Kind::transition: break;
    }
  }
  return s;
}

/// What the rules decide about a shot.
struct Verdict {
  std::vector<Foul> fouls;                     ///< every foul committed (none: a legal shot)
  std::vector<std::size_t> potted;             ///< the object balls pocketed, in the order they dropped
  std::vector<std::size_t> respotted;          ///< the balls to put back on their spot
  int points = 0;                              ///< the points the shot scored for its shooter
  int penalty = 0;                             ///< the points a foul gave the shooter's opponent (snooker)
  std::size_t next_player = 0;                 ///< who shoots next (0 or 1)
  BallInHand ball_in_hand = BallInHand::none;  ///< where the next player may place the cue ball
  bool game_over = false;                      ///< the game has ended
  std::optional<std::size_t> winner;           ///< who won it, where it has ended
  std::string reason;                          ///< the decision in words: the rule applied
  /// Whether the shot was legal.
  [[nodiscard]] bool legal() const noexcept { return fouls.empty(); }
};

/// Throws std::invalid_argument unless `player` is 0 or 1.
inline void check_player(const char* game, std::size_t player) {
  if (player > 1)
    throw std::invalid_argument(std::string(game) + ": player is " + std::to_string(player) +
                                ", expected 0 or 1");
}

}  // namespace billiards::simulation::games
