// billiards::io's shot files (billiards/io/shot.hpp): setup files read and their mistakes named by file
// and line, the trajectories' CSV sampled at its rate from the shot's own states, the events' JSON one
// object an event.
#include <billiards/io/shot.hpp>

#include <catch2/catch.hpp>

#include <cstddef>
#include <sstream>
#include <string>

using namespace billiards::simulation;
using namespace billiards::io;

namespace {

constexpr double R = 0.028575;

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t count = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
  return count;
}

}  // namespace

TEST_CASE("Shot setup files", "[io][shot]") {
  SECTION("a table and balls of 2, 4 and 7 numbers") {
    std::istringstream in(
        "# a cut\ntable 7ft\nball 0.5 0.5\nball 1 0.5 2 0  # moving\nball 1.5 0.5 0 0 1 2 3\n");
    const ShotSetup setup = read_shot_setup(in, "cut.setup", R);
    REQUIRE(setup.table);
    CHECK(*setup.table == "7ft");
    REQUIRE(setup.balls.size() == 3);
    CHECK(setup.balls[0].position == Eigen::Vector3d(0.5, 0.5, R));
    CHECK(setup.balls[0].velocity.isZero(0));
    CHECK(setup.balls[1].velocity == Eigen::Vector3d(2, 0, 0));
    CHECK(setup.balls[2].angular_velocity == Eigen::Vector3d(1, 2, 3));
    CHECK(setup.origins[2] == "cut.setup:5: ");
  }
  SECTION("each mistake named by the file and the line") {
    const auto fails = [](const std::string& text, const std::string& message) {
      std::istringstream in(text);
      CHECK_THROWS_WITH(read_shot_setup(in, "bad.setup", R), Catch::Contains(message));
    };
    fails("ball 1 1\nball 1\n", "bad.setup:2: ball: 1 numbers, expected 2, 4 or 7");
    fails("table 10ft\n", "bad.setup:1: table: '10ft', expected one of 7ft, 8ft, 9ft, snooker, carom");
    fails("ball 1 1\ncue 1 2\n", "bad.setup:2: unknown directive 'cue'");
    fails("ball 1 nan\n", "bad.setup:1:");
    fails("# nothing\n", "bad.setup: no ball");
  }
}

TEST_CASE("A shot's trajectories and events as files", "[io][shot]") {
  const PoolTable table = pool_table("9ft");
  const PoolPhysics physics;
  Shot shot(table, physics, rack(table, physics, Rack::nine_ball));
  shot.strike(0, billiards::Cue<double>{0.567, 8.0, 0.0, 0.0, 0.0, 0.25});
  shot.play();
  SECTION("the CSV: a header, then every ball at every sample of the rate, and at the last event") {
    const std::string csv = trajectories_csv(shot, 10);
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);
    CHECK(line == "time,ball,x,y,vx,vy,pocketed");
    const std::size_t samples = static_cast<std::size_t>(shot.time() * 10) + 2;  // 0, 0.1, …, and the end
    CHECK(occurrences(csv, "\n") == 1 + samples * shot.balls().size());
    // The first row is the cue ball at the start, as the shot has it.
    std::getline(in, line);
    const PoolBall cue = shot.balls_at(0)[0];
    std::ostringstream expected;
    expected.precision(17);
    expected << "0,0," << cue.position.x() << "," << cue.position.y() << ",";
    CHECK(line.rfind(expected.str(), 0) == 0);
  }
  SECTION("the JSON: one object an event, the pocketed balls listed") {
    const std::string json = shot_json(shot, "9ft");
    CHECK(occurrences(json, "{\"time\": ") == shot.events().size());
    CHECK(occurrences(json, "\"kind\": \"ball\"") ==
          static_cast<std::size_t>(
              std::count_if(shot.events().begin(), shot.events().end(),
                            [](const ShotEvent& e) { return e.kind == ShotEvent::Kind::ball; })));
    CHECK(json.find("\"size\": \"9ft\"") != std::string::npos);
  }
}

TEST_CASE("The events JSON's start: the balls as placed, the strike applied, before any contact",
          "[io][shot]") {
  // The cue ball frozen to an object ball: the strike and the contact both at t = 0. The start holds the
  // object ball at rest (before the contact) and the cue ball as struck.
  const PoolTable table = pool_table("9ft");
  const PoolPhysics physics;
  std::vector<PoolBall> balls(2);
  balls[0].position = {1, 0.6, physics.radius};
  const double touching = 1 + 2 * physics.radius * (1 - 1e-12);  // within rounding: touching now
  balls[1].position = {touching, 0.6, physics.radius};
  Shot shot(table, physics, balls);
  shot.strike(0, billiards::Cue<double>{0.567, 2.0});
  shot.play();
  REQUIRE(shot.events().size() > 1);
  REQUIRE(shot.events()[1].kind == ShotEvent::Kind::ball);
  REQUIRE(shot.events()[1].time == 0);
  const std::string json = shot_json(shot, "9ft");
  const std::size_t start = json.find("\"start\": ["), events = json.find("\"events\": [");
  REQUIRE(start < events);
  const std::string section = json.substr(start, events - start);
  CHECK(section.find("{\"ball\": 1, \"position\": [" + json_number(touching) +
                     ", 0.59999999999999998], \"velocity\": [0, 0]") != std::string::npos);
  CHECK(section.find("{\"ball\": 0, \"position\": [1, 0.59999999999999998], \"velocity\": [" +
                     json_number(shot.events()[0].first_after.velocity.x())) != std::string::npos);
  // The balls at t = 0 after every event there are not the start: ball 1 moves.
  CHECK(shot.balls_at(0)[1].velocity.x() > 0);
}
