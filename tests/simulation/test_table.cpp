// The event-driven table of billiards::simulation: long-run conservation, the physics of simple cases
// against hand-worked answers, the break, rejected setups, running for a number of events or until a
// time with a callback.
#include <billiards/simulation/table.hpp>

#include <billiards/checked.hpp>
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

using namespace billiards::simulation;

namespace {

TableSetup empty_table() {
  TableSetup setup;
  setup.balls.clear();
  return setup;
}

long double relative_drift(long double before, long double after) {
  return std::fabs(after - before) / before;
}

}  // namespace

TEST_CASE("A shortened long run conserves the kinetic energy", "[simulation][table]") {
  // 16 balls until 10^4 ball-ball collisions, no velocity correction of any kind.
  Table simulation(random_setup(TableSetup{}, 16, 1));
  const long double before = simulation.energy();
  while (simulation.ball_collisions() < 10000) simulation.step();
  CHECK(relative_drift(before, simulation.energy()) <= 1e-12L);
  CHECK(simulation.largest_overlap() <= billiards::simulation::overlap_tolerance);
  CHECK(simulation.cushion_collisions() > 0);
  CHECK(simulation.event_count() >= simulation.ball_collisions() + simulation.cushion_collisions());
}

TEST_CASE("Simple tables against hand-worked answers", "[simulation][table]") {
  TableSetup setup = empty_table();
  setup.width = 4;
  setup.height = 2;
  setup.radius = 0.5;
  setup.mass = 2;
  SECTION("equal balls head on: the moving one stops and the other leaves at its speed") {
    setup.balls = {{TableVector(1, 1), TableVector(1, 0)}, {TableVector(3, 1), TableVector(0, 0)}};
    Table simulation(setup);
    const TableEvent event = simulation.step().value();
    CHECK(event.kind == TableEvent::Kind::ball);
    CHECK(event.resolved);
    CHECK(event.time == 1);  // the gap of 2 − 1 closes at 1
    CHECK(simulation.balls()[0].velocity == TableVector(0, 0));
    CHECK(simulation.balls()[1].velocity == TableVector(1, 0));
  }
  SECTION("a ball meets the cushion a radius away and is reflected exactly") {
    setup.balls = {{TableVector(2, 1), TableVector(0.25, 0.5)}};
    Table simulation(setup);
    const TableEvent event = simulation.step().value();
    CHECK(event.kind == TableEvent::Kind::cushion);
    CHECK(event.second == 3);  // the top cushion: y = 2 − 0.5 is reached after 1
    CHECK(event.time == 1);
    CHECK(simulation.balls()[0].position == TableVector(2.25, 1.5));
    CHECK(simulation.balls()[0].velocity == TableVector(0.25, -0.5));
  }
  SECTION("a single ball bouncing between the cushions keeps its speed exactly") {
    setup.balls = {{TableVector(1.3, 0.7), TableVector(0.37, -0.91)}};
    Table simulation(setup);
    for (int i = 0; i < 1000; ++i) simulation.step();
    CHECK(simulation.balls()[0].velocity.cwiseAbs() == TableVector(0.37, 0.91));
  }
  SECTION("balls at rest have no event") {
    setup.balls = {{TableVector(1, 1), TableVector(0, 0)}};
    Table simulation(setup);
    CHECK_FALSE(simulation.step());
    CHECK_THAT(simulation.why_no_event(), Catch::Contains("at rest"));
  }
}

TEST_CASE("The break", "[simulation][table]") {
  Table simulation(break_setup(TableSetup{}));
  REQUIRE(simulation.balls().size() == 16);
  const TableEvent first = simulation.step().value();
  // The cue ball covers half the table less two radii at 8 m/s before it meets the apex ball.
  const TableSetup& table = simulation.setup();
  CHECK(first.kind == TableEvent::Kind::ball);
  CHECK(first.first + first.second == 1);  // balls 0 and 1
  CHECK(first.time == Approx((0.5 * table.width - 2 * table.radius) / 8).epsilon(1e-12));
  const long double before = 0.5L * table.mass * 64;
  while (simulation.ball_collisions() < 500) simulation.step();
  CHECK(relative_drift(before, simulation.energy()) <= 1e-12L);
  int moving = 0;
  for (const Ball<2>& ball : simulation.balls()) moving += ball.velocity.norm() > 0;
  CHECK(moving == 16);
}

TEST_CASE("Bad setups are rejected with a clear error", "[simulation][table]") {
  TableSetup setup = empty_table();
  SECTION("overlapping balls") {
    setup.balls = {{TableVector(1, 0.5), TableVector(0, 0)}, {TableVector(1.05, 0.5), TableVector(0, 0)}};
    CHECK_THROWS_WITH(validate(setup), Catch::Contains("balls 0 and 1 overlap") && Catch::Contains("0.05"));
  }
  SECTION("a ball outside the table") {
    setup.balls = {{TableVector(3, 0.5), TableVector(0, 0)}};
    CHECK_THROWS_WITH(validate(setup), Catch::Contains("ball 0 at (3, 0.5) is outside the table"));
  }
  SECTION("a ball closer to a cushion than its radius") {
    setup.balls = {{TableVector(0.01, 0.5), TableVector(0, 0)}};
    CHECK_THROWS_WITH(validate(setup), Catch::Contains("outside the table"));
  }
  SECTION("a radius that is not positive") {
    setup.radius = 0;
    setup.balls = {{TableVector(1, 0.5), TableVector(0, 0)}};
    CHECK_THROWS_WITH(validate(setup), Catch::Contains("radius is 0, expected a positive finite number"));
  }
  SECTION("no balls") { CHECK_THROWS_WITH(validate(setup), Catch::Contains("no balls")); }
  SECTION("a validation message without a file has no prefix") {
    setup.balls = {{TableVector(3, 0.5), TableVector(0, 0)}};
    CHECK_THROWS_WITH(validate(setup), Catch::StartsWith("ball 0 at (3, 0.5)"));
  }
  SECTION("more balls than fit") {
    CHECK_THROWS_WITH(random_setup(TableSetup{}, 100000, 1),
                      Catch::Contains("balls is 100000: cannot place"));
  }
  SECTION("a velocity beyond the checked calls' limit; at it two balls head on exchange speeds") {
    const double limit = billiards::component_limit<double>();
    setup.balls = {{TableVector(1, 0.5), TableVector(limit, 0)},
                   {TableVector(2, 0.5), TableVector(-limit, 0)}};
    validate(setup);
    Table simulation(setup);
    while (simulation.ball_collisions() < 1) simulation.step();
    // Along d = p2 − p1 (not a power of two long) the exchange is exact to a few roundings.
    CHECK(simulation.balls()[0].velocity.x() == Approx(-limit).epsilon(1e-15));
    CHECK(simulation.balls()[1].velocity.x() == Approx(limit).epsilon(1e-15));
    CHECK(std::fabs(simulation.balls()[0].velocity.y()) <= 1e-15 * limit);
    setup.balls[1].velocity.x() = -std::nextafter(limit, 2 * limit);
    CHECK_THROWS_WITH(validate(setup), Catch::Contains("ball 1 has velocity (") &&
                                           Catch::Contains("expected components of magnitude at most"));
    setup.balls[1].velocity = TableVector(0, -5e307);  // head on at 5e307, v2 − v1 once overflowed to NaN
    CHECK_THROWS_WITH(validate(setup), Catch::Contains("ball 1 has velocity (0, -5e+307)"));
  }
  SECTION("more balls than the table can start in reasonable time") {
    TableSetup large = empty_table();
    large.width = large.height = 1e6;
    large.radius = 4;
    CHECK_THROWS_WITH(random_setup(large, largest_ball_count + 1, 1),
                      Catch::Contains("balls is 100001, expected at most 100000"));
    for (std::size_t i = 0; i <= largest_ball_count; ++i) {
      large.balls.push_back(
          {TableVector(10 + 10.0 * static_cast<double>(i % 1000), 10 + 10.0 * static_cast<double>(i / 1000)),
           TableVector(0, 0)});
    }
    CHECK_THROWS_WITH(validate(large), Catch::Contains("balls is 100001, expected at most 100000"));
    large.balls.pop_back();
    CHECK_NOTHROW(validate(large));
  }
  SECTION("the simulation validates too") {
    setup.balls = {{TableVector(3, 0.5), TableVector(0, 0)}};
    CHECK_THROWS_AS(Table(setup), std::invalid_argument);
  }
}

TEST_CASE("Validation compares each ball with a handful of neighbours, not with every ball",
          "[simulation][table]") {
  // 40 000 balls in a square lattice of spacing 2.2 r, every one of them near others: the all-pairs
  // check compared 8·10^8 pairs; the cell grid compares each ball with those in its 3 x 3 cells.
  TableSetup setup = empty_table();
  setup.radius = 0.001;
  const int side = 200;
  setup.width = setup.height = (side + 1) * 2.2 * setup.radius;
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      setup.balls.push_back(
          {TableVector((i + 1) * 2.2 * setup.radius, (j + 1) * 2.2 * setup.radius), TableVector(0, 0)});
    }
  }
  const std::size_t compared = validate(setup);
  CHECK(compared <= 8 * setup.balls.size());
  // And it still finds an overlap anywhere in it.
  setup.balls.back().position = setup.balls.front().position + TableVector(setup.radius, 0);
  CHECK_THROWS_WITH(validate(setup), Catch::Contains("balls 0 and 39999 overlap"));
}

TEST_CASE("Radii too small for the table's rounding are rejected up front", "[simulation][table]") {
  TableSetup setup = empty_table();
  setup.radius = 1e-6;
  setup.balls = {{TableVector(1, 0.5), TableVector(1, 0)}};
  CHECK_THROWS_WITH(validate(setup), Catch::Contains("radius is 1e-06, expected at least 9.0") ||
                                         Catch::Contains("radius is 1e-06, expected at least 9.02"));
  setup.radius = 1e-4;
  CHECK_NOTHROW(validate(setup));
}

TEST_CASE("A ball crawling at 1e-300 hits the ball in its way", "[simulation][table]") {
  TableSetup setup = empty_table();
  setup.balls = {{TableVector(1, 0.6), TableVector(1e-300, 0)}, {TableVector(1.5, 0.6), TableVector(0, 0)}};
  Table simulation(setup);
  const TableEvent event = simulation.step().value();
  CHECK(event.kind == TableEvent::Kind::ball);
  CHECK(event.resolved);
  CHECK(event.time == Approx((0.5 - 2 * setup.radius) / 1e-300));
  CHECK(simulation.ball_collisions() == 1);
  CHECK(simulation.largest_overlap() <= billiards::simulation::overlap_tolerance);
}

TEST_CASE("Tables far from metres play as the same table in metres", "[simulation][table]") {
  // Three balls on a 1 m table, and the same table scaled by 2^-1000 (about 1e-301 m) and by 2^1000
  // at the same speeds: the events must be the same ones, in the same order, at times scaled by the
  // same power of two. On the small table the squared distance of two centres underflowed to
  // 0, and two balls far apart were taken as lying on each other after the first event.
  TableSetup metres = empty_table();
  metres.width = metres.height = 1;
  metres.radius = 0.01;
  metres.balls = {{TableVector(0.02, 0.02), TableVector(1, 1)},
                  {TableVector(0.8, 0.02), TableVector(-1, 0.3)},
                  {TableVector(0.5, 0.5), TableVector(-1, 0)}};
  for (const int exponent : {-1000, 1000}) {
    CAPTURE(exponent);
    TableSetup scaled = metres;
    scaled.width = scaled.height = std::ldexp(1.0, exponent);
    scaled.radius = std::ldexp(metres.radius, exponent);
    for (Ball<2>& ball : scaled.balls) ball.position = std::ldexp(1.0, exponent) * ball.position;
    Table reference(metres), simulation(scaled);
    for (int k = 0; k < 300; ++k) {
      const TableEvent expected = reference.step().value(), event = simulation.step().value();
      REQUIRE(event.kind == expected.kind);
      REQUIRE(event.first == expected.first);
      REQUIRE(event.second == expected.second);
      CHECK(event.time == Approx(std::ldexp(expected.time, exponent)).epsilon(1e-9));  // the same speeds
    }
    CHECK(simulation.ball_collisions() == reference.ball_collisions());
    CHECK(simulation.ball_collisions() > 10);
    CHECK(simulation.largest_overlap() <= billiards::simulation::overlap_tolerance);
  }
  SECTION("two balls far apart on a table of 1e-300 m do not overlap") {
    TableSetup tiny = empty_table();
    tiny.width = tiny.height = 1e-300;
    tiny.radius = 1e-302;
    tiny.balls = {{TableVector(2e-302, 2e-302), TableVector(0, 0)},
                  {TableVector(5e-301, 5e-301), TableVector(0, 0)}};
    CHECK(overlap(tiny, 0, 1) == Approx(2e-302 - std::hypot(4.8e-301, 4.8e-301)).epsilon(1e-12));
    CHECK(overlap(tiny, 0, 1) < 0);
  }
}

TEST_CASE("Balls too slow for their table end the run with a reason, and time passes the largest double",
          "[simulation][table]") {
  TableSetup setup = empty_table();
  setup.width = setup.height = 1e300;
  setup.radius = 1e298;
  SECTION("at 1e-300 m/s no event falls within the largest finite time: not 'every ball is at rest'") {
    setup.balls = {{TableVector(2e298, 2e298), TableVector(1e-300, 1e-300)},
                   {TableVector(5e299, 5e299), TableVector(-1e-300, 0)}};
    Table simulation(setup);
    CHECK_FALSE(simulation.step());
    CHECK_THAT(simulation.why_no_event(),
               Catch::Contains("too slow for the table") && !Catch::Contains("every ball is at rest"));
  }
  SECTION("at 1e-7 m/s the table time sums past 1.8e308 s in long double, not to infinity") {
    setup.balls = {{TableVector(2e298, 2e298), TableVector(1e-7, 1.3e-7)},
                   {TableVector(8e299, 2e298), TableVector(-1e-7, 3e-8)},
                   {TableVector(5e299, 5e299), TableVector(-1e-7, 0)}};
    Table simulation(setup);
    const long double before = simulation.energy();
    while (simulation.precise_time() <= std::numeric_limits<double>::max()) REQUIRE(simulation.step());
    CHECK(std::isfinite(simulation.precise_time()));
    CHECK(relative_drift(before, simulation.energy()) <= 1e-12L);
  }
}
