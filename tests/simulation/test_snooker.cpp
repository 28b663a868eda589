// Snooker's rules (billiards/simulation/games/snooker.hpp) on the WPBSA rule book's cases as hand-built
// event lists: a red then a colour, the colours in order, each foul and its value, the cue ball in hand
// in the D, the frame's end on the last black and a tie re-spotting it; a maximum break of 147.
#include <billiards/simulation/games.hpp>

#include "game_events.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cstddef>
#include <initializer_list>
#include <vector>

namespace {

using namespace billiards::simulation;
using namespace billiards::simulation::games;
using game_events::drop;
using game_events::events_of;
using game_events::hit;
using game_events::rail;
namespace ball = billiards::simulation::snooker_ball;

// The frame with only the colours from `from` on (every red and the colours below it potted).
SnookerState colours_from(std::size_t from) {
  SnookerState s;
  for (std::size_t b = 1; b < from; ++b) s.on_table[b] = false;
  s.on = SnookerOn::sequence;
  s.ball_in_hand = BallInHand::none;
  return s;
}

// The rules' decision on a shot at the last black, the scores `scores` before it.
Decision<SnookerState> on_last_black(std::array<int, 2> scores, std::initializer_list<game_events::Step> steps) {
  SnookerState s = colours_from(ball::black);
  s.scores = scores;
  return snooker(s, events_of(steps));
}

}  // namespace

TEST_CASE("snooker: a red, then a colour, while reds remain", "[simulation][games][snooker]") {
  const SnookerState start;
  SECTION("a red potted scores 1 and puts the shooter on a colour") {
    const auto d = snooker(start, events_of({hit(0, 7), drop(7, 0)}));
    CHECK(d.verdict.legal());
    CHECK(d.verdict.points == 1);
    CHECK(d.next.scores == std::array<int, 2>{1, 0});
    CHECK(d.next.on == SnookerOn::colour);
    CHECK(d.next.player == 0);
    CHECK_FALSE(d.next.on_table[7]);
    CHECK(d.next.ball_in_hand == BallInHand::none);
  }
  SECTION("two reds in one stroke score 2") {
    CHECK(snooker(start, events_of({hit(0, 7), hit(7, 8), drop(7, 0), drop(8, 3)})).verdict.points == 2);
  }
  SECTION("nothing potted: the turn passes, the opponent on a red") {
    const auto d = snooker(start, events_of({hit(0, 7), rail(7)}));
    CHECK(d.verdict.legal());
    CHECK(d.next.player == 1);
    CHECK(d.next.on == SnookerOn::red);
  }
  SECTION("the colour after a red scores its value and is respotted; a red is on again") {
    SnookerState s = start;
    s.on = SnookerOn::colour;
    s.on_table[7] = false;
    const auto d = snooker(s, events_of({hit(0, ball::black), drop(ball::black, 3)}));
    CHECK(d.verdict.legal());
    CHECK(d.verdict.points == 7);
    CHECK(d.verdict.respotted == std::vector<std::size_t>{ball::black});
    CHECK(d.next.on_table[ball::black]);
    CHECK(d.next.on == SnookerOn::red);
    CHECK(d.next.player == 0);
  }
  SECTION("the colour after the last red is respotted, then the colours in order") {
    SnookerState s = colours_from(ball::yellow);
    s.on = SnookerOn::colour;
    const auto d = snooker(s, events_of({hit(0, ball::blue), drop(ball::blue, 4)}));
    CHECK(d.verdict.points == 5);
    CHECK(d.next.on_table[ball::blue]);
    CHECK(d.next.on == SnookerOn::sequence);
    CHECK(d.next.is_on(ball::yellow));
    CHECK_FALSE(d.next.is_on(ball::blue));
  }
}

TEST_CASE("snooker: fouls are worth the highest value involved, at least 4, to the opponent",
          "[simulation][games][snooker]") {
  const SnookerState start;
  const auto foul = [](const SnookerState& s, std::vector<billiards::simulation::ShotEvent> events) {
    return snooker(s, events).verdict;
  };
  SECTION("a red on and a colour met first: the colour's value, at least 4") {
    CHECK(foul(start, events_of({hit(0, ball::yellow)})).penalty == 4);
    CHECK(foul(start, events_of({hit(0, ball::blue)})).penalty == 5);
    const auto v = foul(start, events_of({hit(0, ball::pink)}));
    CHECK(v.fouls == std::vector<Foul>{Foul::wrong_ball_first});
    CHECK(v.penalty == 6);
    CHECK(v.next_player == 1);
    CHECK(v.ball_in_hand == BallInHand::none);
  }
  SECTION("a red on, a red met first and the black potted: 7, the black respotted, the red's pot void") {
    const auto d = snooker(start, events_of({hit(0, 3), hit(3, ball::black), drop(3, 0), drop(ball::black, 1)}));
    CHECK(d.verdict.fouls == std::vector<Foul>{Foul::wrong_ball_potted});
    CHECK(d.verdict.penalty == 7);
    CHECK(d.verdict.points == 0);
    CHECK(d.next.scores == std::array<int, 2>{0, 7});
    CHECK(d.verdict.respotted == std::vector<std::size_t>{ball::black});
    CHECK(d.next.on_table[ball::black]);
    CHECK_FALSE(d.next.on_table[3]);  // a red potted on a foul stays down
  }
  SECTION("no ball met: 4") {
    const auto v = foul(start, events_of({rail(0), rail(0)}));
    CHECK(v.fouls == std::vector<Foul>{Foul::no_contact});
    CHECK(v.penalty == 4);
  }
  SECTION("the white pocketed: 4, the opponent plays from the D") {
    const auto d = snooker(start, events_of({hit(0, 9), drop(0, 2)}));
    CHECK(d.verdict.fouls == std::vector<Foul>{Foul::scratch});
    CHECK(d.verdict.penalty == 4);
    CHECK(d.next.ball_in_hand == BallInHand::in_d);
    CHECK(d.next.player == 1);
  }
  SECTION("a colour on and a red met first: 4") {
    SnookerState s = start;
    s.on = SnookerOn::colour;
    const auto d = snooker(s, events_of({hit(0, 2)}));
    CHECK(d.verdict.fouls == std::vector<Foul>{Foul::wrong_ball_first});
    CHECK(d.verdict.penalty == 4);
    CHECK(d.next.on == SnookerOn::red);
  }
  SECTION("a colour on, the blue met first and the pink potted: 6, the pink respotted") {
    SnookerState s = start;
    s.on = SnookerOn::colour;
    const auto d = snooker(s, events_of({hit(0, ball::blue), hit(ball::blue, ball::pink), drop(ball::pink, 5)}));
    CHECK(d.verdict.fouls == std::vector<Foul>{Foul::wrong_ball_potted});
    CHECK(d.verdict.penalty == 6);
    CHECK(d.next.on_table[ball::pink]);
  }
  SECTION("the yellow on and the blue met first: 5; the green met first: 4") {
    CHECK(foul(colours_from(ball::yellow), events_of({hit(0, ball::blue)})).penalty == 5);
    CHECK(foul(colours_from(ball::yellow), events_of({hit(0, ball::green)})).penalty == 4);
  }
  SECTION("the colour on potted on a foul is respotted") {
    const auto d = snooker(colours_from(ball::green), events_of({hit(0, ball::green), drop(ball::green), drop(0)}));
    CHECK(d.verdict.penalty == 4);
    CHECK(d.next.on_table[ball::green]);
    CHECK(d.next.is_on(ball::green));
  }
}

TEST_CASE("snooker: the colours in order and the frame's end", "[simulation][games][snooker]") {
  SECTION("the colour on potted stays down, the shooter goes on to the next") {
    const auto d = snooker(colours_from(ball::yellow), events_of({hit(0, ball::yellow), drop(ball::yellow, 2)}));
    CHECK(d.verdict.points == 2);
    CHECK(d.verdict.respotted.empty());
    CHECK_FALSE(d.next.on_table[ball::yellow]);
    CHECK(d.next.is_on(ball::green));
    CHECK(d.next.player == 0);
  }
  SECTION("the last black potted ends the frame: the higher score wins") {
    const auto d = on_last_black({60, 62}, {hit(0, ball::black), drop(ball::black, 0)});
    CHECK(d.verdict.game_over);
    CHECK(d.verdict.winner == 0u);
    CHECK(d.next.scores == std::array<int, 2>{67, 62});
  }
  SECTION("a foul on the last black ends the frame, its 7 to the opponent") {
    const auto d = on_last_black({60, 55}, {hit(0, ball::black), drop(0, 4)});
    CHECK(d.verdict.game_over);
    CHECK(d.verdict.penalty == 7);
    CHECK(d.verdict.winner == 1u);
  }
  SECTION("a miss on the last black without a foul does not end it") {
    const auto d = on_last_black({0, 0}, {hit(0, ball::black), rail(ball::black)});
    CHECK_FALSE(d.verdict.game_over);
    CHECK(d.next.player == 1);
  }
  SECTION("a tie on the last black: the black re-spotted, the opponent plays from the D") {
    const auto d = on_last_black({50, 57}, {hit(0, ball::black), drop(ball::black, 0)});
    CHECK_FALSE(d.verdict.game_over);
    CHECK(d.next.on_table[ball::black]);
    CHECK(d.verdict.respotted == std::vector<std::size_t>{ball::black});
    CHECK(d.next.player == 1);
    CHECK(d.next.ball_in_hand == BallInHand::in_d);
  }
}

TEST_CASE("snooker: a maximum break is 147 and ends the frame", "[simulation][games][snooker]") {
  SnookerState s;
  for (std::size_t red = ball::first_red; red <= ball::last_red; ++red) {
    s = snooker(s, events_of({hit(0, red), drop(red, 0)})).next;
    REQUIRE(s.on == SnookerOn::colour);
    s = snooker(s, events_of({hit(0, ball::black), drop(ball::black, 1)})).next;
    REQUIRE(s.on_table[ball::black]);
  }
  REQUIRE(s.on == SnookerOn::sequence);
  for (std::size_t colour = ball::yellow; colour <= ball::black; ++colour) {
    REQUIRE(s.is_on(colour));
    s = snooker(s, events_of({hit(0, colour), drop(colour, 2)})).next;
  }
  CHECK(s.scores == std::array<int, 2>{147, 0});
  CHECK(s.over);
  CHECK(s.winner == 0u);
  CHECK(s.player == 0);
}

TEST_CASE("snooker: a frame over, a player other than 0 or 1 and a ball potted twice are refused",
          "[simulation][games][snooker]") {
  SnookerState s;
  s.player = 2;
  CHECK_THROWS_WITH(snooker(s, events_of({hit(0, 1)})), "snooker: player is 2, expected 0 or 1");
  s.player = 0;
  s.over = true;
  CHECK_THROWS_WITH(snooker(s, events_of({hit(0, 1)})), Catch::Contains("the frame is over"));
  s.over = false;
  s.on_table[4] = false;
  CHECK_THROWS_WITH(snooker(s, events_of({hit(0, 1), drop(4)})), Catch::Contains("ball 4 is pocketed"));
}
