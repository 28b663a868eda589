// The event-driven table of examples/: long-run conservation, the physics of simple cases against
// hand-worked answers, the break, rejected setups, the setup file and the SVG.
#include "table.hpp"
#include "table_io.hpp"

#include <billiards/checked.hpp>
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

using namespace billiards_example;

namespace {

Setup empty_table() {
  Setup setup;
  setup.balls.clear();
  return setup;
}

long double relative_drift(long double before, long double after) {
  return std::fabs(after - before) / before;
}

}  // namespace

TEST_CASE("A shortened long run conserves the kinetic energy", "[examples][table]") {
  // 16 balls until 10^4 ball-ball collisions, no velocity correction of any kind.
  Simulation simulation(random_setup(Setup{}, 16, 1));
  const long double before = simulation.kinetic_energy();
  while (simulation.ball_collisions() < 10000) simulation.step();
  CHECK(relative_drift(before, simulation.kinetic_energy()) <= 1e-12L);
  CHECK(simulation.largest_overlap() <= Simulation::overlap_tolerance);
  CHECK(simulation.cushion_collisions() > 0);
  CHECK(simulation.events() >= simulation.ball_collisions() + simulation.cushion_collisions());
}

TEST_CASE("Simple tables against hand-worked answers", "[examples][table]") {
  Setup setup = empty_table();
  setup.width = 4;
  setup.height = 2;
  setup.radius = 0.5;
  setup.mass = 2;
  SECTION("equal balls head on: the moving one stops and the other leaves at its speed") {
    setup.balls = {{Vector(1, 1), Vector(1, 0)}, {Vector(3, 1), Vector(0, 0)}};
    Simulation simulation(setup);
    const Event event = simulation.step();
    CHECK(event.kind == Event::Kind::ball);
    CHECK(event.resolved);
    CHECK(event.time == 1);  // the gap of 2 − 1 closes at 1
    CHECK(simulation.balls()[0].velocity == Vector(0, 0));
    CHECK(simulation.balls()[1].velocity == Vector(1, 0));
  }
  SECTION("a ball meets the cushion a radius away and is reflected exactly") {
    setup.balls = {{Vector(2, 1), Vector(0.25, 0.5)}};
    Simulation simulation(setup);
    const Event event = simulation.step();
    CHECK(event.kind == Event::Kind::cushion);
    CHECK(event.second == 3);  // the top cushion: y = 2 − 0.5 is reached after 1
    CHECK(event.time == 1);
    CHECK(simulation.balls()[0].position == Vector(2.25, 1.5));
    CHECK(simulation.balls()[0].velocity == Vector(0.25, -0.5));
  }
  SECTION("a single ball bouncing between the cushions keeps its speed exactly") {
    setup.balls = {{Vector(1.3, 0.7), Vector(0.37, -0.91)}};
    Simulation simulation(setup);
    for (int i = 0; i < 1000; ++i) simulation.step();
    CHECK(simulation.balls()[0].velocity.cwiseAbs() == Vector(0.37, 0.91));
  }
  SECTION("balls at rest have no event") {
    setup.balls = {{Vector(1, 1), Vector(0, 0)}};
    Simulation simulation(setup);
    CHECK_THROWS_WITH(simulation.step(), Catch::Contains("at rest"));
  }
}

TEST_CASE("The break", "[examples][table]") {
  Simulation simulation(break_setup(Setup{}));
  REQUIRE(simulation.balls().size() == 16);
  const Event first = simulation.step();
  // The cue ball covers half the table less two radii at 8 m/s before it meets the apex ball.
  const Setup& table = simulation.setup();
  CHECK(first.kind == Event::Kind::ball);
  CHECK(first.first + first.second == 1);  // balls 0 and 1
  CHECK(first.time == Approx((0.5 * table.width - 2 * table.radius) / 8).epsilon(1e-12));
  const long double before = 0.5L * table.mass * 64;
  while (simulation.ball_collisions() < 500) simulation.step();
  CHECK(relative_drift(before, simulation.kinetic_energy()) <= 1e-12L);
  int moving = 0;
  for (const Ball& ball : simulation.balls()) moving += ball.velocity.norm() > 0;
  CHECK(moving == 16);
}

TEST_CASE("Bad setups are rejected with a clear error", "[examples][table]") {
  Setup setup = empty_table();
  SECTION("overlapping balls") {
    setup.balls = {{Vector(1, 0.5), Vector(0, 0)}, {Vector(1.05, 0.5), Vector(0, 0)}};
    CHECK_THROWS_WITH(validate(setup), Catch::Contains("balls 0 and 1 overlap") && Catch::Contains("0.05"));
  }
  SECTION("a ball outside the table") {
    setup.balls = {{Vector(3, 0.5), Vector(0, 0)}};
    CHECK_THROWS_WITH(validate(setup), Catch::Contains("ball 0 at (3, 0.5) is outside the table"));
  }
  SECTION("a ball closer to a cushion than its radius") {
    setup.balls = {{Vector(0.01, 0.5), Vector(0, 0)}};
    CHECK_THROWS_WITH(validate(setup), Catch::Contains("outside the table"));
  }
  SECTION("a radius that is not positive") {
    setup.radius = 0;
    setup.balls = {{Vector(1, 0.5), Vector(0, 0)}};
    CHECK_THROWS_WITH(validate(setup), Catch::Contains("radius is 0, expected a positive finite number"));
  }
  SECTION("no balls") { CHECK_THROWS_WITH(validate(setup), Catch::Contains("no balls")); }
  SECTION("a validation message without a file has no prefix") {
    setup.balls = {{Vector(3, 0.5), Vector(0, 0)}};
    CHECK_THROWS_WITH(validate(setup), Catch::StartsWith("ball 0 at (3, 0.5)"));
  }
  SECTION("more balls than fit") {
    CHECK_THROWS_WITH(random_setup(Setup{}, 100000, 1), Catch::Contains("balls is 100000: cannot place"));
  }
  SECTION("a velocity beyond the checked calls' limit; at it two balls head on exchange speeds") {
    const double limit = billiards::component_limit<double>();
    setup.balls = {{Vector(1, 0.5), Vector(limit, 0)}, {Vector(2, 0.5), Vector(-limit, 0)}};
    validate(setup);
    Simulation simulation(setup);
    while (simulation.ball_collisions() < 1) simulation.step();
    // Along d = p2 − p1 (not a power of two long) the exchange is exact to a few roundings.
    CHECK(simulation.balls()[0].velocity.x() == Approx(-limit).epsilon(1e-15));
    CHECK(simulation.balls()[1].velocity.x() == Approx(limit).epsilon(1e-15));
    CHECK(std::fabs(simulation.balls()[0].velocity.y()) <= 1e-15 * limit);
    setup.balls[1].velocity.x() = -std::nextafter(limit, 2 * limit);
    CHECK_THROWS_WITH(validate(setup), Catch::Contains("ball 1 has velocity (") &&
                                           Catch::Contains("expected components of magnitude at most"));
    setup.balls[1].velocity = Vector(0, -5e307);  // head on at 5e307, v2 − v1 once overflowed to NaN
    CHECK_THROWS_WITH(validate(setup), Catch::Contains("ball 1 has velocity (0, -5e+307)"));
  }
  SECTION("more balls than the table can start in reasonable time") {
    Setup large = empty_table();
    large.width = large.height = 1e6;
    large.radius = 4;
    CHECK_THROWS_WITH(random_setup(large, largest_ball_count + 1, 1),
                      Catch::Contains("balls is 100001, expected at most 100000"));
    for (std::size_t i = 0; i <= largest_ball_count; ++i) {
      large.balls.push_back(
          {Vector(10 + 10.0 * static_cast<double>(i % 1000), 10 + 10.0 * static_cast<double>(i / 1000)),
           Vector(0, 0)});
    }
    CHECK_THROWS_WITH(validate(large), Catch::Contains("balls is 100001, expected at most 100000"));
    large.balls.pop_back();
    CHECK_NOTHROW(validate(large));
  }
  SECTION("the simulation validates too") {
    setup.balls = {{Vector(3, 0.5), Vector(0, 0)}};
    CHECK_THROWS_AS(Simulation(setup), std::invalid_argument);
  }
}

TEST_CASE("Setup files", "[examples][table]") {
  SECTION("every directive, comments and blank lines") {
    std::istringstream in(
        "# two balls\ntable 3 1.5\nradius 0.1\n\nmass 0.2  # kg\nball 1 0.75 1 0\nball 2 0.75 0 0\n");
    const Setup setup = read_setup(in, "two.setup");
    CHECK(setup.width == 3);
    CHECK(setup.height == 1.5);
    CHECK(setup.radius == 0.1);
    CHECK(setup.mass == 0.2);
    REQUIRE(setup.balls.size() == 2);
    CHECK(setup.balls[1].position == Vector(2, 0.75));
  }
  SECTION("an unknown directive names the file and line") {
    std::istringstream in("table 3 1.5\nballs 1 1 0 0\n");
    CHECK_THROWS_WITH(
        read_setup(in, "bad.setup"),
        Catch::Contains("bad.setup:2: unknown directive 'balls'") && Catch::Contains("expected"));
  }
  SECTION("a wrong number of numbers") {
    std::istringstream in("ball 1 1 0\n");
    CHECK_THROWS_WITH(read_setup(in, "bad.setup"),
                      Catch::Contains("bad.setup:1: ball: 3 numbers, expected 4"));
  }
  SECTION("something that is not a number") {
    std::istringstream in("radius big\n");
    CHECK_THROWS_WITH(read_setup(in, "bad.setup"), Catch::Contains("'big' is not a finite number"));
  }
  SECTION("an invalid table names the file and the line") {
    std::istringstream in("ball 1 0.5 0 0\nball 1.01 0.5 0 0\n");
    CHECK_THROWS_WITH(read_setup(in, "bad.setup"), Catch::Contains("bad.setup:2: balls 0 and 1 overlap"));
  }
  SECTION("every validation error names the line it comes from") {
    std::istringstream off("# a comment\nball 1 0.5 0 0\n\nball 3 0.5 0 0\n");
    CHECK_THROWS_WITH(read_setup(off, "bad.setup"),
                      Catch::StartsWith("bad.setup:4: ball 1 at (3, 0.5) is outside"));
    std::istringstream radius("ball 1 0.5 0 0\nradius -1\n");
    CHECK_THROWS_WITH(read_setup(radius, "bad.setup"), Catch::StartsWith("bad.setup:2: radius is -1"));
    std::istringstream mass("mass 0\nball 1 0.5 0 0\n");
    CHECK_THROWS_WITH(read_setup(mass, "bad.setup"), Catch::StartsWith("bad.setup:1: mass is 0"));
    std::istringstream table("table 0.01 1\nball 1 0.5 0 0\n");
    CHECK_THROWS_WITH(read_setup(table, "bad.setup"), Catch::StartsWith("bad.setup:1: radius is"));
    std::istringstream none("# nothing\n");
    CHECK_THROWS_WITH(read_setup(none, "bad.setup"), Catch::StartsWith("bad.setup: no balls"));
  }
  SECTION("numbers: subnormal values are numbers, underflow and overflow are named") {
    std::istringstream tiny("ball 1 0.5 1e-310 0\n");
    CHECK(read_setup(tiny, "tiny.setup").balls[0].velocity.x() == 1e-310);
    std::istringstream zero("ball 1 0.5 1e-400 0\n");
    CHECK_THROWS_WITH(read_setup(zero, "bad.setup"),
                      Catch::Contains("'1e-400' is below the smallest subnormal"));
    std::istringstream huge("ball 1 0.5 1e400 0\n");
    CHECK_THROWS_WITH(read_setup(huge, "bad.setup"), Catch::Contains("'1e400' is not a finite number"));
  }
  SECTION("a hostile file: an endless line is cut short, and so is its quote") {
    std::istringstream endless("ball " + std::string(1 << 20, '7') + "\n");
    try {
      (void)read_setup(endless, "zero.setup");
      FAIL("accepted");
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      CHECK_THAT(message, Catch::StartsWith("zero.setup:1: the line is longer than 4096 characters"));
      CHECK(message.size() < 300);
    }
    std::istringstream word("radius " + std::string(3000, 'x') + "\n");
    try {
      (void)read_setup(word, "word.setup");
      FAIL("accepted");
    } catch (const std::invalid_argument& error) {
      CHECK(std::string(error.what()).size() < 300);
    }
  }
  SECTION("a file that cannot be opened says why") {
    CHECK_THROWS_WITH(
        read_setup_file("/nonexistent/table.setup"),
        Catch::Contains("/nonexistent/table.setup: cannot open the setup file: No such file or directory"));
    CHECK_THROWS_WITH(read_setup_file("/tmp"), Catch::Contains("is a folder"));
  }
}

TEST_CASE("Validation compares each ball with a handful of neighbours, not with every ball",
          "[examples][table]") {
  // 40 000 balls in a square lattice of spacing 2.2 r, every one of them near others: the all-pairs
  // check compared 8·10^8 pairs; the cell grid compares each ball with those in its 3 x 3 cells.
  Setup setup = empty_table();
  setup.radius = 0.001;
  const int side = 200;
  setup.width = setup.height = (side + 1) * 2.2 * setup.radius;
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      setup.balls.push_back(
          {Vector((i + 1) * 2.2 * setup.radius, (j + 1) * 2.2 * setup.radius), Vector(0, 0)});
    }
  }
  const std::size_t compared = validate(setup);
  CHECK(compared <= 8 * setup.balls.size());
  // And it still finds an overlap anywhere in it.
  setup.balls.back().position = setup.balls.front().position + Vector(setup.radius, 0);
  CHECK_THROWS_WITH(validate(setup), Catch::Contains("balls 0 and 39999 overlap"));
}

TEST_CASE("Radii too small for the table's rounding are rejected up front", "[examples][table]") {
  Setup setup = empty_table();
  setup.radius = 1e-6;
  setup.balls = {{Vector(1, 0.5), Vector(1, 0)}};
  CHECK_THROWS_WITH(validate(setup), Catch::Contains("radius is 1e-06, expected at least 9.0") ||
                                         Catch::Contains("radius is 1e-06, expected at least 9.02"));
  setup.radius = 1e-4;
  CHECK_NOTHROW(validate(setup));
}

TEST_CASE("A ball crawling at 1e-300 hits the ball in its way", "[examples][table]") {
  Setup setup = empty_table();
  setup.balls = {{Vector(1, 0.6), Vector(1e-300, 0)}, {Vector(1.5, 0.6), Vector(0, 0)}};
  Simulation simulation(setup);
  const Event event = simulation.step();
  CHECK(event.kind == Event::Kind::ball);
  CHECK(event.resolved);
  CHECK(event.time == Approx((0.5 - 2 * setup.radius) / 1e-300));
  CHECK(simulation.ball_collisions() == 1);
  CHECK(simulation.largest_overlap() <= Simulation::overlap_tolerance);
}

TEST_CASE("Tables far from metres play as the same table in metres", "[examples][table]") {
  // Three balls on a 1 m table, and the same table scaled by 2^-1000 (about 1e-301 m) and by 2^1000
  // at the same speeds: the events must be the same ones, in the same order, at times scaled by the
  // same power of two. On the small table the squared distance of two centres underflowed to
  // 0, and two balls far apart were taken as lying on each other after the first event.
  Setup metres = empty_table();
  metres.width = metres.height = 1;
  metres.radius = 0.01;
  metres.balls = {{Vector(0.02, 0.02), Vector(1, 1)},
                  {Vector(0.8, 0.02), Vector(-1, 0.3)},
                  {Vector(0.5, 0.5), Vector(-1, 0)}};
  for (const int exponent : {-1000, 1000}) {
    CAPTURE(exponent);
    Setup scaled = metres;
    scaled.width = scaled.height = std::ldexp(1.0, exponent);
    scaled.radius = std::ldexp(metres.radius, exponent);
    for (Ball& ball : scaled.balls) ball.position = std::ldexp(1.0, exponent) * ball.position;
    Simulation reference(metres), simulation(scaled);
    for (int k = 0; k < 300; ++k) {
      const Event expected = reference.step(), event = simulation.step();
      REQUIRE(event.kind == expected.kind);
      REQUIRE(event.first == expected.first);
      REQUIRE(event.second == expected.second);
      CHECK(event.time == Approx(std::ldexp(expected.time, exponent)).epsilon(1e-9));  // the same speeds
    }
    CHECK(simulation.ball_collisions() == reference.ball_collisions());
    CHECK(simulation.ball_collisions() > 10);
    CHECK(simulation.largest_overlap() <= Simulation::overlap_tolerance);
  }
  SECTION("two balls far apart on a table of 1e-300 m do not overlap") {
    Setup tiny = empty_table();
    tiny.width = tiny.height = 1e-300;
    tiny.radius = 1e-302;
    tiny.balls = {{Vector(2e-302, 2e-302), Vector(0, 0)}, {Vector(5e-301, 5e-301), Vector(0, 0)}};
    CHECK(overlap(tiny, 0, 1) == Approx(2e-302 - std::hypot(4.8e-301, 4.8e-301)).epsilon(1e-12));
    CHECK(overlap(tiny, 0, 1) < 0);
  }
}

TEST_CASE("Balls too slow for their table end the run with a reason, and time passes the largest double",
          "[examples][table]") {
  Setup setup = empty_table();
  setup.width = setup.height = 1e300;
  setup.radius = 1e298;
  SECTION("at 1e-300 m/s no event falls within the largest finite time: not 'every ball is at rest'") {
    setup.balls = {{Vector(2e298, 2e298), Vector(1e-300, 1e-300)},
                   {Vector(5e299, 5e299), Vector(-1e-300, 0)}};
    Simulation simulation(setup);
    CHECK_THROWS_WITH(simulation.step(),
                      Catch::Contains("too slow for the table") && !Catch::Contains("every ball is at rest"));
  }
  SECTION("at 1e-7 m/s the table time sums past 1.8e308 s in long double, not to infinity") {
    setup.balls = {{Vector(2e298, 2e298), Vector(1e-7, 1.3e-7)},
                   {Vector(8e299, 2e298), Vector(-1e-7, 3e-8)},
                   {Vector(5e299, 5e299), Vector(-1e-7, 0)}};
    Simulation simulation(setup);
    const long double before = simulation.kinetic_energy();
    while (simulation.time() <= std::numeric_limits<double>::max()) simulation.step();
    CHECK(std::isfinite(simulation.time()));
    CHECK(relative_drift(before, simulation.kinetic_energy()) <= 1e-12L);
  }
}

TEST_CASE("Trajectories as SVG", "[examples][table]") {
  Simulation simulation(break_setup(Setup{}));
  Trajectories trajectories(simulation.setup());
  for (int i = 0; i < 40; ++i) trajectories.record(simulation.step(), simulation.balls());
  trajectories.finish(simulation.balls());
  const std::string svg = trajectories.svg("the break");
  CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
  CHECK(svg.find("</svg>\n") == svg.size() - 7);
  std::size_t polylines = 0;
  for (std::size_t at = svg.find("<polyline"); at != std::string::npos; at = svg.find("<polyline", at + 1))
    ++polylines;
  CHECK(polylines == 16);
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "billiards_test_break.svg";
  write_file_atomically(path, svg);
  std::ifstream in(path);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(written == svg);
  CHECK_FALSE(std::filesystem::exists(path.string() + ".tmp"));
  std::filesystem::remove(path);
  CHECK_THROWS_WITH(write_file_atomically("/nonexistent-folder/x.svg", svg),
                    Catch::Contains("/nonexistent-folder/x.svg"));
}
