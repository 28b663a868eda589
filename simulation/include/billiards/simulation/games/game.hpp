/// \file
/// A game played shot by shot: the table, its balls, the game's state, and a step that places the cue
/// ball where it is in hand, plays the shot to rest, decides it by the rules and respots what they
/// respot. What an agent plays against (Python's billiards.games.GameEnv is this class), and what a
/// program that plays whole games needs beside the rules.
#pragma once

#include <billiards/simulation/games/eight_ball.hpp>
#include <billiards/simulation/games/nine_ball.hpp>
#include <billiards/simulation/games/rules.hpp>
#include <billiards/simulation/games/snooker.hpp>
#include <billiards/simulation/games/three_cushion.hpp>
#include <billiards/simulation/shot/layouts.hpp>
#include <billiards/simulation/shot/shot.hpp>

#include <billiards/shot.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace billiards::simulation::games {

/// The games a Game plays.
enum class GameKind {
  nine_ball,      ///< "9ball": 9-ball (WPA)
  eight_ball,     ///< "8ball": 8-ball (WPA)
  snooker,        ///< "snooker": snooker (WPBSA)
  three_cushion,  ///< "3cushion": three-cushion (UMB)
};

/// The game named "9ball", "8ball", "snooker" or "3cushion". Throws std::invalid_argument naming the
/// name and the ones there are.
inline GameKind game_kind(std::string_view name) {
  if (name == "9ball") return GameKind::nine_ball;
  if (name == "8ball") return GameKind::eight_ball;
  if (name == "snooker") return GameKind::snooker;
  if (name == "3cushion") return GameKind::three_cushion;
  throw std::invalid_argument("game is '" + std::string(name) + "', expected 9ball, 8ball, snooker or 3cushion");
}

/// What one step of a game did.
struct GameStep {
  Verdict verdict;           ///< the rules' decision on the shot
  std::size_t shooter = 0;   ///< who took it (0 or 1)
  double reward = 0;         ///< for the shooter: pool ±1 for the game won or lost, snooker points − penalty,
                             ///< three-cushion the point
  std::size_t events = 0;    ///< the shot's events
};

/// A game between two players on one table, shot by shot. The balls are the game's (snooker_ball::
/// indices for snooker; 0, 1, 2 the white, the yellow and the red for three-cushion; ball 0 the cue ball
/// and the object balls by number for pool).
class Game {
 public:
  /// The states of the games.
  using State = std::variant<NineBallState, EightBallState, SnookerState, ThreeCushionState>;

  /// A game of `kind` on `table` with `physics`, its shots played with `options`; `target` the points
  /// that win three-cushion. Starts at reset(0, 0). Throws std::invalid_argument for a target below 1, a
  /// table with pockets for three-cushion, and as the starting position does (a table too short for the
  /// snooker set-up).
  Game(GameKind kind, PoolTable table, PoolPhysics physics, ShotOptions options = {}, int target = 40)
      : kind_(kind), table_(std::move(table)), physics_(std::move(physics)), options_(options), target_(target) {
    if (target < 1)
      throw std::invalid_argument("target is " + std::to_string(target) + ", expected at least 1");
    if (kind == GameKind::three_cushion && table_.has_pockets)
      throw std::invalid_argument("table has pockets, expected a carom table (has_pockets false) for three-cushion");
    reset(0, 0);
  }

  /// A new game: the kind's starting position (the rack or the snooker set-up spread by `jitter` drawn
  /// from `seed`; three-cushion's breaker's white to the side of the seed's parity), the break to play, the
  /// cue ball in hand behind the head string (pool) or in the D (snooker).
  void reset(double jitter, std::uint64_t seed) {
    switch (kind_) {
      case GameKind::nine_ball:
      case GameKind::eight_ball: {
        const bool nine = kind_ == GameKind::nine_ball;
        balls_ = rack(table_, physics_, nine ? Rack::nine_ball : Rack::eight_ball, jitter, seed);
        if (nine) {
          NineBallState s;
          s.ball_in_hand = BallInHand::behind_head_string;
          state_ = s;
        } else {
          EightBallState s;
          s.ball_in_hand = BallInHand::behind_head_string;
          state_ = s;
        }
        break;
      }
      case GameKind::snooker:
        balls_ = snooker_setup(table_, physics_, jitter, seed);
        state_ = SnookerState{};
        break;
      case GameKind::three_cushion: {
        balls_ = three_cushion_setup(table_, physics_, seed % 2 == 0 ? 1 : -1);
        ThreeCushionState s;
        s.target = target_;
        state_ = s;
        break;
      }
    }
    shot_.reset();
  }

  /// Plays one shot: where the cue ball is in hand, places it at `place` if that is legal, else at the
  /// nearest free point (place_cue_ball); strikes the shooter's cue ball (ball 0; three-cushion: the
  /// shooter's own ball) with `cue`, plays to rest, decides by the rules and respots what they respot.
  /// Throws std::logic_error for a game over, and what Shot and the rules throw (a cue refused,
  /// EventLimitReached, BrokenInvariant, a pocket on a three-cushion shot), the game's balls, state and
  /// last shot then left as they were before the step.
  GameStep step(const Cue<double>& cue, std::optional<TableVector> place = std::nullopt) {
    if (over()) throw std::logic_error("Game::step: the game is over, expected reset()");
    std::vector<PoolBall> balls = balls_;
    const BallInHand hand = ball_in_hand();
    if (hand != BallInHand::none) {
      const Placement where = hand == BallInHand::anywhere             ? Placement::anywhere
                              : hand == BallInHand::behind_head_string ? Placement::behind_head_string
                                                                       : Placement::in_d;
      place_cue_ball(table_, physics_, balls, place, where);
    }
    GameStep out;
    out.shooter = player();
    Shot shot(table_, physics_, balls, options_);
    shot.strike(striker(), cue);
    shot.play();
    out.events = shot.events().size();
    State next = state_;
    out.verdict = decide(shot, next);
    std::vector<PoolBall> after = shot.balls();
    for (const std::size_t b : out.verdict.respotted) {
      if (kind_ == GameKind::snooker)
        respot_colour(table_, physics_, after, b);
      else
        respot_on_long_string(table_, physics_, after, b);
    }
    state_ = std::move(next);
    balls_ = std::move(after);
    shot_ = std::move(shot);
    out.reward = reward(out);
    return out;
  }

  /// The kind of game.
  [[nodiscard]] GameKind kind() const noexcept { return kind_; }
  /// The table.
  [[nodiscard]] const PoolTable& table() const noexcept { return table_; }
  /// The balls' and the cloth's physics.
  [[nodiscard]] const PoolPhysics& physics() const noexcept { return physics_; }
  /// The balls where they lie (the cue ball in hand stays where it was pocketed, `pocketed`, until the
  /// next step places it).
  [[nodiscard]] const std::vector<PoolBall>& balls() const noexcept { return balls_; }
  /// The game's state.
  [[nodiscard]] const State& state() const noexcept { return state_; }
  /// The last shot played (empty after reset()).
  [[nodiscard]] const std::optional<Shot>& last_shot() const noexcept { return shot_; }
  /// Who shoots next (0 or 1).
  [[nodiscard]] std::size_t player() const {
    return std::visit([](const auto& s) { return s.player; }, state_);
  }
  /// Where the player to shoot may place the cue ball (none in three-cushion).
  [[nodiscard]] BallInHand ball_in_hand() const {
    return std::visit(
        [](const auto& s) {
          if constexpr (requires { s.ball_in_hand; })
            return s.ball_in_hand;
          else
            return BallInHand::none;
        },
        state_);
  }
  /// The ball the player to shoot strikes: 0, the cue ball (three-cushion: the shooter's own ball).
  [[nodiscard]] std::size_t striker() const { return kind_ == GameKind::three_cushion ? player() : 0; }
  /// Whether the player to shoot may meet `ball` first with the ball they strike, by the rules: the
  /// lowest-numbered ball (9-ball), a ball of their group or the 8 (8-ball), a ball on (snooker),
  /// either other ball (three-cushion); never the struck ball itself or a ball that is not there.
  [[nodiscard]] bool may_meet_first(std::size_t ball) const {
    if (ball >= balls_.size() || ball == striker()) return false;
    return std::visit(
        [ball](const auto& s) {
          using S = std::decay_t<decltype(s)>;
          if constexpr (std::is_same_v<S, NineBallState>) return ball == s.lowest();
          if constexpr (std::is_same_v<S, EightBallState>) return s.may_hit_first(ball);
          if constexpr (std::is_same_v<S, SnookerState>) return s.is_on(ball);
          if constexpr (std::is_same_v<S, ThreeCushionState>) return true;
        },
        state_);
  }
  /// Whether the game has ended.
  [[nodiscard]] bool over() const {
    return std::visit([](const auto& s) { return s.over; }, state_);
  }

 private:
  // The rules on `shot` from the state `next`, moved on to the state after it.
  static Verdict decide(const Shot& shot, State& next) {
    const std::span<const ShotEvent> events = shot.events();
    return std::visit(
        [&](auto& s) {
          auto d = decide_by_rules(s, events);
          s = d.next;
          return d.verdict;
        },
        next);
  }
  static Decision<NineBallState> decide_by_rules(const NineBallState& s, std::span<const ShotEvent> e) {
    return nine_ball(s, e);
  }
  static Decision<EightBallState> decide_by_rules(const EightBallState& s, std::span<const ShotEvent> e) {
    return eight_ball(s, e);
  }
  static Decision<SnookerState> decide_by_rules(const SnookerState& s, std::span<const ShotEvent> e) {
    return snooker(s, e);
  }
  static Decision<ThreeCushionState> decide_by_rules(const ThreeCushionState& s, std::span<const ShotEvent> e) {
    return three_cushion(s, e);
  }

  // The step's reward for its shooter.
  [[nodiscard]] double reward(const GameStep& step) const {
    const Verdict& v = step.verdict;
    if (kind_ == GameKind::snooker) return v.points - v.penalty;
    if (kind_ == GameKind::three_cushion) return v.points;
    if (!v.game_over) return 0;
    return v.winner == step.shooter ? 1 : -1;
  }

  GameKind kind_;
  PoolTable table_;
  PoolPhysics physics_;
  ShotOptions options_;
  int target_;
  std::vector<PoolBall> balls_;
  State state_;
  std::optional<Shot> shot_;
};

}  // namespace billiards::simulation::games
