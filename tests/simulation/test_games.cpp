// The rules of 9-ball and 8-ball (billiards/simulation/games.hpp) on the rule books' cases: each foul,
// each way to score, each end of a game, as hand-built event lists; and cases played through the engine.
#include <billiards/simulation/games.hpp>
#include <billiards/simulation/shot.hpp>

#include "game_events.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <random>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

namespace {

using namespace billiards::simulation;
using namespace billiards::simulation::games;
using Kind = ShotEvent::Kind;

using game_events::drop;
using game_events::events_of;
using game_events::hit;
using game_events::rail;

NineBallState after_break() {
  NineBallState s;
  s.breaking = false;
  return s;
}

}  // namespace

TEST_CASE("9-ball: the break", "[simulation][games][nine_ball]") {
  const NineBallState start;
  SECTION("the 1 first and four object balls to a cushion: legal, the turn passes") {
    const auto d = nine_ball(start, events_of({hit(0, 1), rail(2), rail(3), rail(4), rail(5)}));
    CHECK(d.verdict.legal());
    CHECK(d.verdict.next_player == 1);
    CHECK(d.verdict.ball_in_hand == BallInHand::none);
    CHECK_FALSE(d.next.breaking);
  }
  SECTION("a ball pocketed: the breaker continues") {
    const auto d = nine_ball(start, events_of({hit(0, 1), drop(5)}));
    CHECK(d.verdict.legal());
    CHECK(d.verdict.next_player == 0);
    CHECK(d.verdict.potted == std::vector<std::size_t>{5});
    CHECK_FALSE(d.next.on_table[5]);
  }
  SECTION("nothing pocketed and three balls to a cushion: a foul, ball in hand anywhere") {
    const auto d = nine_ball(start, events_of({hit(0, 1), rail(2), rail(3), rail(4), rail(2)}));
    REQUIRE(d.verdict.fouls == std::vector<Foul>{Foul::illegal_break});
    CHECK(d.verdict.next_player == 1);
    CHECK(d.verdict.ball_in_hand == BallInHand::anywhere);
    CHECK(d.next.ball_in_hand == BallInHand::anywhere);
  }
  SECTION("the 9 pocketed on a legal break wins") {
    const auto d = nine_ball(start, events_of({hit(0, 1), hit(1, 9), drop(9, 4)}));
    CHECK(d.verdict.game_over);
    CHECK(d.verdict.winner == 0u);
    CHECK(d.next.over);
  }
  SECTION("another ball first is a foul even when balls drop") {
    const auto d = nine_ball(start, events_of({hit(0, 2), drop(2), rail(3)}));
    CHECK(d.verdict.fouls.front() == Foul::wrong_ball_first);
    CHECK_FALSE(d.next.on_table[2]);  // it stays down
  }
}

TEST_CASE("9-ball: the lowest ball first, a pocket or a cushion after", "[simulation][games][nine_ball]") {
  NineBallState s = after_break();
  s.on_table[1] = s.on_table[2] = false;  // the 3 is the lowest
  SECTION("the lowest first and a ball pocketed: the shooter continues") {
    const auto d = nine_ball(s, events_of({hit(0, 3), drop(3)}));
    CHECK(d.verdict.legal());
    CHECK(d.verdict.next_player == 0);
  }
  SECTION("the lowest first and a cushion after: legal, the turn passes") {
    const auto d = nine_ball(s, events_of({hit(0, 3), rail(0)}));
    CHECK(d.verdict.legal());
    CHECK(d.verdict.next_player == 1);
    CHECK(d.next.player == 1);
  }
  SECTION("a cushion only before the contact: no rail") {
    const auto d = nine_ball(s, events_of({rail(0), hit(0, 3)}));
    CHECK(d.verdict.fouls == std::vector<Foul>{Foul::no_rail});
  }
  SECTION("a higher ball first: wrong ball first") {
    const auto d = nine_ball(s, events_of({hit(0, 4), rail(4)}));
    CHECK(d.verdict.fouls == std::vector<Foul>{Foul::wrong_ball_first});
    CHECK(d.verdict.ball_in_hand == BallInHand::anywhere);
  }
  SECTION("the cue ball meets nothing") {
    const auto d = nine_ball(s, events_of({rail(0), rail(0)}));
    CHECK(d.verdict.fouls == std::vector<Foul>{Foul::no_contact});
  }
  SECTION("a scratch: the 9 pocketed on it is respotted, the others stay down") {
    const auto d = nine_ball(s, events_of({hit(0, 3), hit(3, 9), drop(9), drop(4), drop(0, 2)}));
    CHECK(d.verdict.fouls == std::vector<Foul>{Foul::scratch});
    CHECK(d.verdict.respotted == std::vector<std::size_t>{9});
    CHECK(d.next.on_table[9]);
    CHECK_FALSE(d.next.on_table[4]);
    CHECK_FALSE(d.verdict.game_over);
  }
  SECTION("a combination on the 9 wins") {
    const auto d = nine_ball(s, events_of({hit(0, 3), hit(3, 9), drop(9)}));
    CHECK(d.verdict.winner == 0u);
  }
}

TEST_CASE("9-ball: three fouls in a row lose the game", "[simulation][games][nine_ball]") {
  NineBallState s = after_break();
  const auto miss = events_of({rail(0)});
  auto d = nine_ball(s, miss);                             // player 0's first foul
  d = nine_ball(d.next, events_of({hit(0, 1), rail(1)}));  // player 1 legal
  d = nine_ball(d.next, miss);                             // 1 → 0: player 0's second
  // Player 0's own shots: two fouls with no legal shot of theirs between (the opponent's does not count).
  CHECK(d.next.fouls_in_a_row[0] == 2);
  CHECK(d.next.fouls_in_a_row[1] == 0);
  s = after_break();
  for (int foul = 1; foul <= 3; ++foul) {
    d = nine_ball(s, miss);
    s = d.next;
    s.player = 0;  // the opponent declines each time: player 0 shoots again
  }
  CHECK(d.verdict.game_over);
  CHECK(d.verdict.winner == 1u);
  // A legal shot between resets the count.
  s = after_break();
  s.fouls_in_a_row[0] = 2;
  d = nine_ball(s, events_of({hit(0, 1), rail(1)}));
  CHECK(d.next.fouls_in_a_row[0] == 0);
}

TEST_CASE("9-ball: input that is not one shot's, or a game over, is refused",
          "[simulation][games][nine_ball]") {
  NineBallState s = after_break();
  CHECK_THROWS_WITH(nine_ball(s, std::vector<ShotEvent>{}), Catch::Contains("beginning with the strike"));
  auto events = events_of({hit(0, 1), drop(1)});
  s.on_table[1] = false;
  CHECK_THROWS_WITH(nine_ball(s, events),
                    Catch::Contains("ball 1 is pocketed, expected a ball on the table"));
  s = after_break();
  s.over = true;
  CHECK_THROWS_WITH(nine_ball(s, events), Catch::Contains("the game is over"));
  s = after_break();
  s.player = 2;
  CHECK_THROWS_WITH(nine_ball(s, events), Catch::Contains("player is 2"));
  events.push_back(events.front());
  CHECK_THROWS_WITH(nine_ball(after_break(), events), Catch::Contains("a second strike"));
}

TEST_CASE("8-ball: the break", "[simulation][games][eight_ball]") {
  const EightBallState start;
  SECTION("a scratch: ball in hand behind the head string") {
    const auto d = eight_ball(start, events_of({hit(0, 1), rail(2), rail(3), rail(4), rail(5), drop(0)}));
    CHECK(d.verdict.fouls == std::vector<Foul>{Foul::scratch});
    CHECK(d.verdict.ball_in_hand == BallInHand::behind_head_string);
    CHECK(d.verdict.next_player == 1);
  }
  SECTION("the 8 pocketed: respotted, the breaker continues") {
    const auto d = eight_ball(start, events_of({hit(0, 1), hit(1, 8), drop(8)}));
    CHECK(d.verdict.legal());
    CHECK(d.verdict.respotted == std::vector<std::size_t>{8});
    CHECK(d.next.on_table[8]);
    CHECK(d.verdict.next_player == 0);
    CHECK_FALSE(d.verdict.game_over);
  }
  SECTION("a ball pocketed: the breaker continues and the table stays open") {
    const auto d = eight_ball(start, events_of({hit(0, 1), drop(3)}));
    CHECK(d.verdict.next_player == 0);
    CHECK(d.next.groups[0] == Group::open);
  }
  SECTION("nothing pocketed and three balls to a cushion: the incoming player takes the table as it lies") {
    const auto d = eight_ball(start, events_of({hit(0, 1), rail(2), rail(3), rail(4)}));
    CHECK(d.verdict.legal());
    CHECK(d.verdict.next_player == 1);
    CHECK(d.verdict.ball_in_hand == BallInHand::none);
  }
}

TEST_CASE("8-ball: the open table, the groups and the 8", "[simulation][games][eight_ball]") {
  EightBallState s;
  s.breaking = false;
  SECTION("the 8 first on an open table is a foul") {
    const auto d = eight_ball(s, events_of({hit(0, 8), rail(8)}));
    CHECK(d.verdict.fouls == std::vector<Foul>{Foul::wrong_ball_first});
    CHECK(d.verdict.ball_in_hand == BallInHand::anywhere);
  }
  SECTION("a stripe first making a solid: legal, the shooter takes the solids") {
    const auto d = eight_ball(s, events_of({hit(0, 12), hit(12, 2), drop(2)}));
    CHECK(d.verdict.legal());
    CHECK(d.next.groups[0] == Group::solids);
    CHECK(d.next.groups[1] == Group::stripes);
    CHECK(d.verdict.next_player == 0);
  }
  s.groups = {Group::solids, Group::stripes};
  SECTION("the other group first is a foul") {
    const auto d = eight_ball(s, events_of({hit(0, 12), drop(12)}));
    CHECK(d.verdict.fouls == std::vector<Foul>{Foul::wrong_ball_first});
    CHECK(d.verdict.next_player == 1);
  }
  SECTION("only the opponent's ball pocketed on a legal shot: the turn passes") {
    const auto d = eight_ball(s, events_of({hit(0, 3), hit(3, 12), drop(12)}));
    CHECK(d.verdict.legal());
    CHECK(d.verdict.next_player == 1);
    CHECK_FALSE(d.next.on_table[12]);
  }
  SECTION("the 8 pocketed before the group is cleared loses") {
    const auto d = eight_ball(s, events_of({hit(0, 3), hit(3, 8), drop(8)}));
    CHECK(d.verdict.game_over);
    CHECK(d.verdict.winner == 1u);
  }
  for (std::size_t b = 1; b <= 7; ++b) s.on_table[b] = false;
  SECTION("the group cleared: the 8 first and pocketed wins") {
    REQUIRE(s.on_the_eight(0));
    const auto d = eight_ball(s, events_of({hit(0, 8), drop(8, 3)}));
    CHECK(d.verdict.legal());
    CHECK(d.verdict.winner == 0u);
  }
  SECTION("the group cleared: a stripe first is a foul") {
    const auto d = eight_ball(s, events_of({hit(0, 12), rail(12)}));
    CHECK(d.verdict.fouls == std::vector<Foul>{Foul::wrong_ball_first});
  }
  SECTION("the 8 pocketed with a scratch loses") {
    const auto d = eight_ball(s, events_of({hit(0, 8), drop(8), drop(0)}));
    CHECK(d.verdict.fouls == std::vector<Foul>{Foul::scratch});
    CHECK(d.verdict.winner == 1u);
  }
}

TEST_CASE("9-ball through the engine: a scratch, a pot and a miss", "[simulation][games][nine_ball]") {
  const PoolTable table = pool_table("9ft");
  const PoolPhysics physics;
  const double R = physics.radius;
  NineBallState state = after_break();
  for (std::size_t b = 2; b <= 9; ++b) state.on_table[b] = false;  // the 1 alone with the cue ball
  const auto play = [&](std::vector<PoolBall> balls, const billiards::Cue<double>& cue) {
    Shot shot(table, physics, std::move(balls));
    shot.strike(0, cue);
    shot.play();
    return nine_ball(state, shot.events());
  };
  std::vector<PoolBall> balls(10);
  for (std::size_t b = 0; b < 10; ++b) {
    balls[b].position = {0.3 + 0.1 * static_cast<double>(b), 1.0, R};
    balls[b].pocketed = b >= 2;
  }
  // The cue ball at (0.5, 0.3) rolled into the head-side corner pocket at (0, 0): a scratch, no contact.
  balls[0].position = {0.5, 0.3, R};
  balls[1].position = {2.0, 1.0, R};
  const double away = std::atan2(-0.3, -0.5);
  auto d = play(balls, {0.567, 3.0, away, 0.0, 0.0, 0.0, 1.0});
  CHECK(d.verdict.fouls == std::vector<Foul>{Foul::no_contact, Foul::scratch});
  // The 1 in front of the foot-side corner pocket at (L, W), the cue ball behind it on the same line,
  // drawn back: the 1 drops, the cue ball stays on the table.
  const Eigen::Vector3d corner(table.length, table.width, R),
      one = corner - 0.2 * Eigen::Vector3d(1, 1, 0).normalized();
  balls[1].position = one;
  balls[0].position = one - 0.5 * Eigen::Vector3d(1, 1, 0).normalized();
  d = play(balls, {0.567, 2.0, M_PI / 4, 0.0, 0.0, -0.4, 1.0});
  CHECK(d.verdict.legal());
  CHECK(d.verdict.potted == std::vector<std::size_t>{1});
  CHECK(d.verdict.next_player == 0);
  // Aimed away from the 1 along the side cushion: no contact.
  d = play(balls, {0.567, 1.0, -3 * M_PI / 4, 0.0, 0.0, 0.0, 1.0});
  CHECK(d.verdict.fouls.front() == Foul::no_contact);
}

TEST_CASE("a shot's end starts the next: a ball at rest in a pocket's mouth is taken, one in a cushion not",
          "[simulation][games][shot]") {
  const PoolTable table = pool_table("7ft");
  const PoolPhysics physics;
  const double R = physics.radius;
  const auto pockets = shot::capture_circles(table, R);
  // Along the corner's diagonal from the cloth towards the pocket: the last point clear of the jaws and
  // outside every capture circle lies beyond the noses' lines, in the mouth.
  Eigen::Vector2d mouth(0, 0);
  for (double d = 0; d < 0.1; d += 1e-4) {
    const Eigen::Vector2d q(table.length - R + d, table.width - R + d);
    const bool clear =
        !shot::broken_invariant(table, table.cushions(), table.jaws(), pockets, {q}, {true}, R);
    const bool captured = (q - pockets[3].centre).norm() < pockets[3].radius;
    if (clear && !captured) mouth = q;
  }
  REQUIRE(mouth.x() > table.length - R);  // beyond the foot cushion's nose line
  std::vector<PoolBall> balls(2);
  balls[0].position = {0.5, 0.5, R};
  balls[1].position = {mouth.x(), mouth.y(), R};
  CHECK_NOTHROW(Shot(table, physics, balls));
  balls[1].position = {table.length - 0.5 * R, 0.5, R};  // inside the foot cushion
  CHECK_THROWS_WITH(Shot(table, physics, balls), Catch::Contains("ball 1 is at"));
}

TEST_CASE("three-cushion: a point is both object balls and three cushions before the second",
          "[simulation][games][three_cushion]") {
  ThreeCushionState s;
  const auto decide = [&](std::vector<ShotEvent> events) { return three_cushion(s, events); };
  SECTION("three cushions, then both balls") {
    const auto d = decide(events_of({rail(0, 1), rail(0, 2), rail(0, 3), hit(0, 2), hit(0, 1)}));
    CHECK(d.verdict.points == 1);
    CHECK(d.next.scores[0] == 1);
    CHECK(d.verdict.next_player == 0);
  }
  SECTION("the first ball, three cushions, the second") {
    CHECK(decide(events_of({hit(0, 2), rail(0, 1), rail(0, 3), rail(0, 0), hit(0, 1)})).verdict.points == 1);
  }
  SECTION("two cushions before the second ball, the third after it: no point") {
    const auto d = decide(events_of({hit(0, 2), rail(0, 1), rail(0, 3), hit(0, 1), rail(0, 0)}));
    CHECK(d.verdict.points == 0);
    CHECK(d.verdict.next_player == 1);
    CHECK(d.next.player == 1);
  }
  SECTION("one object ball only, however many cushions") {
    CHECK(decide(events_of({hit(0, 2), rail(0), rail(0), rail(0), rail(0), hit(0, 2)})).verdict.points == 0);
  }
  SECTION("the object balls meeting each other, or their cushions, count for nothing") {
    CHECK(decide(events_of({hit(0, 2), rail(2), rail(2), rail(2), hit(2, 1)})).verdict.points == 0);
  }
  SECTION("player 1 strikes the yellow, ball 1") {
    s.player = 1;
    const auto events = events_of({rail(1), rail(1), rail(1), hit(1, 0), hit(2, 1)}, 1);
    const auto d = decide(events);
    CHECK(d.verdict.points == 1);
    CHECK(d.next.scores[1] == 1);
    CHECK_THROWS_WITH(decide(events_of({hit(0, 2)})), Catch::Contains("the strike of ball 1"));
  }
  SECTION("the target reached wins") {
    s.scores = {39, 12};
    const auto d = decide(events_of({rail(0), rail(0), rail(0), hit(0, 1), hit(0, 2)}));
    CHECK(d.verdict.game_over);
    CHECK(d.verdict.winner == 0u);
  }
  SECTION("a pocket is not a carom table's") {
    CHECK_THROWS_WITH(decide(events_of({hit(0, 2), drop(2)})), Catch::Contains("carom table"));
  }
}

TEST_CASE("a game played shot by shot: each step the rules' verdict on its shot, the balls as they say",
          "[simulation][games][game]") {
  const std::tuple<games::GameKind, const char*> kinds[] = {{games::GameKind::nine_ball, "7ft"},
                                                           {games::GameKind::eight_ball, "7ft"},
                                                           {games::GameKind::snooker, "snooker"},
                                                           {games::GameKind::three_cushion, "carom"}};
  for (const auto& [kind, table_name] : kinds) {
    ShotOptions options;
    options.check_invariants = true;
    games::Game game(kind, table_preset(table_name), physics_preset(table_name), options, 2);
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(0, 1);
    int finished = 0;
    for (int k = 0; k < 1500; ++k) {
      const games::Game::State before = game.state();
      const std::size_t shooter = game.player();
      const BallInHand hand = game.ball_in_hand();
      const billiards::Cue<double> cue{0.567, 0.3 + 6 * unit(random), 2 * M_PI * unit(random), 0.0,
                                       0.6 * unit(random) - 0.3, 0.6 * unit(random) - 0.3, 1.0};
      const games::GameStep step = game.step(cue, TableVector(0.5, 0.5));
      REQUIRE(game.last_shot());
      const Shot& shot = *game.last_shot();
      CHECK(step.shooter == shooter);
      CHECK(step.events == shot.events().size());
      // The cue ball in hand was placed where the rules allow it.
      const Eigen::Vector3d white = shot.placed()[0].position;
      INFO("step " << k << ": the white placed at (" << white.x() << ", " << white.y() << ")");
      if (hand == BallInHand::in_d)
        CHECK(snooker_markings(game.table()).in_d({white.x(), white.y()}, game.table().width));
      if (hand == BallInHand::behind_head_string) CHECK(white.x() <= 0.25 * game.table().length);
      // The verdict is the rules' on the shot's events from the state before it.
      const Verdict expected = std::visit(
          [&](const auto& s) -> Verdict {
            using State = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<State, NineBallState>) return nine_ball(s, shot.events()).verdict;
            if constexpr (std::is_same_v<State, EightBallState>) return eight_ball(s, shot.events()).verdict;
            if constexpr (std::is_same_v<State, SnookerState>) return snooker(s, shot.events()).verdict;
            if constexpr (std::is_same_v<State, ThreeCushionState>) return three_cushion(s, shot.events()).verdict;
          },
          before);
      CHECK(step.verdict.reason == expected.reason);
      CHECK(step.verdict.potted == expected.potted);
      // Every object ball on the cloth exactly where the rules have it on the table.
      std::visit(
          [&](const auto& s) {
            if constexpr (requires { s.on_table; }) {
              for (std::size_t b = 1; b < game.balls().size(); ++b) CHECK(s.on_table[b] == !game.balls()[b].pocketed);
            }
          },
          game.state());
      if (game.over()) {
        ++finished;
        CHECK_THROWS_AS(game.step(cue), std::logic_error);
        game.reset(1e-3, static_cast<std::uint64_t>(k));
      }
    }
    CHECK(finished > 0);
  }
  CHECK_THROWS_WITH(games::game_kind("pool"), "game is 'pool', expected 9ball, 8ball, snooker or 3cushion");
  CHECK_THROWS_WITH(games::Game(games::GameKind::three_cushion, carom_table(), carom_physics(), {}, 0),
                    "target is 0, expected at least 1");
  CHECK_THROWS_WITH(games::Game(games::GameKind::three_cushion, pool_table("9ft"), carom_physics()),
                    Catch::Contains("expected a carom table"));
  CHECK_THROWS_WITH(games::Game(games::GameKind::snooker, pool_table("7ft"), snooker_physics()),
                    Catch::Contains("too short"));
}

TEST_CASE("which ball a player may meet first: the lowest, the group or the 8, a ball on, either other ball",
          "[simulation][games][game]") {
  EightBallState eight;
  eight.breaking = false;
  eight.groups = {Group::stripes, Group::solids};
  for (std::size_t b = 9; b <= 15; ++b) eight.on_table[b] = false;  // player 0's stripes cleared
  CHECK(eight.may_hit_first(8));
  CHECK_FALSE(eight.may_hit_first(3));
  eight.on_table[15] = true;
  CHECK(eight.may_hit_first(15));
  CHECK_FALSE(eight.may_hit_first(8));
  SnookerState colour;
  colour.on = SnookerOn::colour;
  CHECK(colour.is_on(snooker_ball::black));
  CHECK_FALSE(colour.is_on(3));
  // A game asks its state, and never names the struck ball.
  games::Game nine(games::GameKind::nine_ball, pool_table("7ft"), PoolPhysics{});
  CHECK(nine.may_meet_first(1));
  CHECK_FALSE(nine.may_meet_first(2));
  CHECK_FALSE(nine.may_meet_first(0));
  CHECK_FALSE(nine.may_meet_first(10));
  games::Game open(games::GameKind::eight_ball, pool_table("7ft"), PoolPhysics{});
  CHECK(open.may_meet_first(3));
  CHECK_FALSE(open.may_meet_first(8));
  CHECK_FALSE(open.may_meet_first(0));
  games::Game frame(games::GameKind::snooker, snooker_table(), snooker_physics());
  CHECK(frame.may_meet_first(snooker_ball::first_red));
  CHECK_FALSE(frame.may_meet_first(snooker_ball::pink));
  games::Game carom(games::GameKind::three_cushion, carom_table(), carom_physics());
  CHECK(carom.striker() == 0);
  CHECK(carom.may_meet_first(1));
  CHECK(carom.may_meet_first(2));
  CHECK_FALSE(carom.may_meet_first(0));
}
