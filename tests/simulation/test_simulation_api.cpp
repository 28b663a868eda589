// billiards::simulation as a user's program drives it: a table and a gas built from a configuration of
// the caller's, run for a number of events or until a time, each event reported to a callback, the
// state read back in the caller's order. Every expected value is worked out by hand from the motion
// (free flight, a head-on exchange of equal balls, a reflection), never captured from the code.
#include <billiards/simulation/gas.hpp>
#include <billiards/simulation/table.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

using namespace billiards::simulation;

namespace {

TableSetup table_with(std::vector<Ball<2>> balls) {
  TableSetup setup;
  setup.width = 4;
  setup.height = 2;
  setup.radius = 0.125;
  setup.balls = std::move(balls);
  return setup;
}

}  // namespace

TEST_CASE("A table runs for a number of events, each reported to the callback", "[simulation][table]") {
  // Head on along y = 1: centres 1 apart, closing at 2, touching at a gap of 2 r = 0.25: t = 0.375.
  Table table(table_with({{{1, 1}, {1, 0}}, {{2, 1}, {-1, 0}}}));
  std::vector<TableEvent> seen;
  const std::uint64_t ran = table.run_events(1, [&](const TableEvent& event) {
    seen.push_back(event);
    // The callback sees the table at the event's time.
    CHECK(table.balls()[0].position.x() == Approx(1.375).epsilon(1e-14));
  });
  CHECK(ran == 1);
  REQUIRE(seen.size() == 1);
  CHECK(seen[0].kind == TableEvent::Kind::ball);
  CHECK(seen[0].resolved);
  CHECK(seen[0].time == Approx(0.375).epsilon(1e-14));
  CHECK(((seen[0].first == 0 && seen[0].second == 1) || (seen[0].first == 1 && seen[0].second == 0)));
  // Equal masses head on exchange their velocities.
  CHECK(table.balls()[0].velocity == TableVector(-1, 0));
  CHECK(table.balls()[1].velocity == TableVector(1, 0));
  // Then each ball meets its cushion: ball 0 at x = r after 1.375 − 0.125 = 1.25 s, ball 1 at
  // x = 4 − r after 4 − 0.125 − 1.625 = 2.25 s.
  seen.clear();
  CHECK(table.run_events(2, [&](const TableEvent& event) { seen.push_back(event); }) == 2);
  REQUIRE(seen.size() == 2);
  CHECK(seen[0].kind == TableEvent::Kind::cushion);
  CHECK(seen[0].first == 0);
  CHECK(seen[0].second == 0);  // the left cushion
  CHECK(seen[0].time == Approx(0.375 + 1.25).epsilon(1e-14));
  CHECK(seen[1].first == 1);
  CHECK(seen[1].second == 1);  // the right cushion
  CHECK(seen[1].time == Approx(0.375 + 2.25).epsilon(1e-14));
  CHECK(table.event_count() == 3);
  CHECK(table.ball_collisions() == 1);
  CHECK(table.cushion_collisions() == 2);
}

TEST_CASE("A table runs until a time and moves every ball on to it", "[simulation][table]") {
  SECTION("free flight: no event before the time") {
    Table table(table_with({{{1, 1}, {0.5, 0.25}}}));
    CHECK(table.run_until(1.0L) == 0);
    CHECK(table.time() == 1.0L);
    CHECK(table.balls()[0].position.x() == Approx(1.5).epsilon(1e-15));
    CHECK(table.balls()[0].position.y() == Approx(1.25).epsilon(1e-15));
  }
  SECTION("a reflection on the way") {
    // From x = 3.5 at +1: the right cushion at x = 4 − r = 3.875 after 0.375 s, then back at −1.
    Table table(table_with({{{3.5, 1}, {1, 0}}}));
    std::vector<double> times;
    CHECK(table.run_until(1.0L, [&](const TableEvent& event) { times.push_back(event.time); }) == 1);
    REQUIRE(times.size() == 1);
    CHECK(times[0] == Approx(0.375).epsilon(1e-14));
    CHECK(table.balls()[0].position.x() == Approx(3.875 - 0.625).epsilon(1e-14));
    CHECK(table.balls()[0].velocity == TableVector(-1, 0));
    CHECK(table.time() == 1.0L);
  }
  SECTION("balls at rest: the time passes, nothing happens") {
    Table table(table_with({{{1, 1}, {0, 0}}, {{2, 1}, {0, 0}}}));
    CHECK(table.run_until(5.0L) == 0);
    CHECK(table.time() == 5.0L);
    CHECK(table.run_events(10) == 0);  // no event can happen: fewer than asked
    CHECK_FALSE(table.step());
  }
  SECTION("a time before now or NaN is an error naming the argument") {
    Table table(table_with({{{1, 1}, {1, 0}}}));
    table.run_until(0.5L);
    CHECK_THROWS_WITH(table.run_until(0.25L), Catch::Contains("until is 0.25, expected a time from 0.5 s"));
    CHECK_THROWS_AS(table.run_until(std::numeric_limits<long double>::quiet_NaN()), std::invalid_argument);
    // A ball bouncing between the cushions forever: a run to +∞ would never end, one to a time far
    // beyond the largest double would take as many steps; both are refused.
    CHECK_THROWS_AS(table.run_until(std::numeric_limits<long double>::infinity()), std::invalid_argument);
    CHECK_THROWS_AS(table.run_until(1e400L), std::invalid_argument);
    CHECK(table.time() == 0.5L);
  }
}

TEST_CASE("A gas from the caller's configuration: two disks head on", "[simulation][gas]") {
  // A box of 10, disks of radius 0.25 (σ = 0.5) and mass 2 at (2, 5) and (6, 5), closing at 2: they touch
  // when the gap 4 − σ = 3.5 has closed, at t = 1.75, and exchange their velocities.
  GasSetup<2> setup;
  setup.side = 10;
  setup.radius = 0.25;
  setup.mass = 2;
  setup.balls = {{{2, 5}, {1, 0}}, {{6, 5}, {-1, 0}}};
  Gas<2> gas(setup);
  CHECK(gas.temperature() == 1.0);  // m Σ v²/(d N) = 2 · (1 + 1)/(2 · 2)
  CHECK(gas.size() == 2);
  CHECK(gas.radius() == 0.25);
  CHECK(gas.mass() == 2);

  SECTION("until a time before the collision: free flight") {
    CHECK(gas.run_until(1.0) == 0);
    CHECK(gas.time() == 1.0);
    const auto p = gas.positions();
    CHECK(p[0].x() == Approx(3).epsilon(1e-15));
    CHECK(p[1].x() == Approx(5).epsilon(1e-15));
  }
  SECTION("one collision, reported to the callback at contact") {
    std::vector<GasEvent> seen;
    CHECK(gas.run_events(1, [&](const GasEvent& c) { seen.push_back(c); }) == 1);
    REQUIRE(seen.size() == 1);
    CHECK(seen[0].time == Approx(1.75).epsilon(1e-14));
    CHECK(((seen[0].first == 0 && seen[0].second == 1) || (seen[0].first == 1 && seen[0].second == 0)));
    const auto v = gas.velocities();
    CHECK(v[0] == Eigen::Vector2d(-1, 0));
    CHECK(v[1] == Eigen::Vector2d(1, 0));
    CHECK(gas.collisions() == 1);
    // The virial of the span: r_12·Δp_1 = (−σ, 0)·(m (−2, 0)) = 2 m σ = 2.
    CHECK(gas.measured().virial == Approx(2).epsilon(1e-14));
    CHECK(gas.measured().collisions == 1);
  }
  SECTION("until a time past the collision: they part, and meet again across the box") {
    // At 1.75 the centres are at 3.75 and 4.25 and part at 2; across the box they are 10 − 0.5 = 9.5
    // apart and touch when 9.5 − σ = 9 has closed: at 1.75 + 4.5 = 6.25, ball 0 at 3.75 − 4.5 + 10 =
    // 9.25 and ball 1 at 4.25 + 4.5 = 8.75. They exchange again; 0.25 later 9.5 and 8.5.
    std::vector<double> times;
    CHECK(gas.run_until(6.5, [&](const GasEvent& c) { times.push_back(c.time); }) == 2);
    REQUIRE(times.size() == 2);
    CHECK(times[0] == Approx(1.75).epsilon(1e-14));
    CHECK(times[1] == Approx(6.25).epsilon(1e-14));
    const auto p = gas.positions();
    CHECK(p[0].x() == Approx(9.5).margin(1e-12));
    CHECK(p[1].x() == Approx(8.5).margin(1e-12));
    CHECK(gas.velocities()[0] == Eigen::Vector2d(1, 0));
    CHECK(gas.time() == 6.5);
  }
  SECTION("a time before now is an error naming the argument") {
    gas.run_until(1.0);
    CHECK_THROWS_WITH(gas.run_until(0.5),
                      Catch::Contains("until is 0.5, expected a finite time at or after 1"));
  }
}

TEST_CASE("A gas's setup is validated with errors that name the value", "[simulation][gas]") {
  GasSetup<3> setup;
  setup.side = 5;
  setup.balls = {{{1, 1, 1}, {1, 0, 0}}, {{3, 1, 1}, {0, 0, 0}}};
  CHECK_NOTHROW(Gas<3>(setup));
  const auto rejects = [](const GasSetup<3>& s, const std::string& words) {
    CHECK_THROWS_WITH(Gas<3>(s), Catch::Contains(words));
  };
  GasSetup<3> bad = setup;
  bad.balls[1].position = {1.5, 1, 1};
  rejects(bad, "balls 0 and 1 overlap: their centres are 0.5 apart");
  bad = setup;
  bad.balls[0].position = {0.5, 1, 1};
  bad.balls[1].position = {4.8, 1, 1};  // 0.7 apart on their nearest images, across the boundary
  rejects(bad, "balls 0 and 1 overlap: their centres are 0.7 apart on their nearest images");
  bad = setup;
  bad.side = 2.5;
  rejects(bad, "side is 2.5, 2.5 diameters, expected from 3 diameters");
  bad = setup;
  bad.radius = -1;
  rejects(bad, "radius is -1, expected a positive finite number");
  bad = setup;
  bad.balls.resize(1);
  rejects(bad, "balls holds 1 balls, expected from 2");
  bad = setup;
  bad.balls[0].velocity.x() = std::numeric_limits<double>::infinity();
  rejects(bad, "balls[0].velocity has a component of inf");
  bad = setup;
  bad.balls[1].position.y() = std::nan("");
  rejects(bad, "balls[1].position is not finite");
  // Positions anywhere are taken into the box.
  GasSetup<3> outside = setup;
  outside.balls[1].position = {3 + 5 * 7, 1 - 5 * 3, 1};
  Gas<3> gas(outside);
  CHECK(gas.positions()[1].isApprox(Eigen::Vector3d(3, 1, 1), 1e-14));
  // However far outside, a position lands inside the box.
  outside.balls[1].position = {7.9e27, -1.0206185567010309e17, 3};
  const Gas<3> far(outside);
  for (int k = 0; k < 3; ++k) {
    CHECK(far.positions()[1][k] >= 0);
    CHECK(far.positions()[1][k] < 5);
  }
}

TEST_CASE("A large gas reports its collisions by the caller's numbers after renumbering",
          "[simulation][gas]") {
  // Beyond 4096 balls the engine renumbers its balls by cell every N collisions; the callback and the
  // state keep the setup's numbers: the two balls a collision names touch at its time.
  gas::Options options;
  options.dimension = 2;
  options.balls = 5000;
  options.packing_fraction = 0.3;
  Gas<2> g(gas::lattice<2>(options));
  std::uint64_t checked = 0;
  double worst = 0;
  g.run_events(5200, [&](const GasEvent& c) {
    if (g.collisions() <= 5100 || checked >= 50) return;
    const auto p = g.positions();
    const double distance = g.nearest_image(p[c.first], p[c.second]).norm();
    worst = std::max(worst, std::fabs(distance - 1));
    ++checked;
  });
  CHECK(checked == 50);
  CHECK(worst < 1e-9);
  // Run until a time gives the same collisions as running for their number, bit for bit.
  Gas<2> a(gas::lattice<2>(options)), b(gas::lattice<2>(options));
  double last = 0;
  a.run_events(6000, [&](const GasEvent& c) { last = c.time; });
  CHECK(b.run_until(last) == 6000);
  CHECK(a.velocities() == b.velocities());
}

TEST_CASE("A gas beyond the caches calls the callback once a collision, with the pair that touches",
          "[simulation][gas]") {
  // From 2^13 balls on neighbour lists and 2^15 on cells the engines run another loop (the one that
  // asks memory ahead), where the callback is called through a pointer.
  const GasMethod method = GENERATE(GasMethod::neighbour_lists, GasMethod::cells);
  gas::Options options;
  options.dimension = 2;
  options.balls = method == GasMethod::cells ? 33000 : 8400;
  options.packing_fraction = 0.3;
  Gas<2> g(gas::lattice<2>(options), 0, method);
  std::uint64_t calls = 0;
  double worst = 0, previous = 0;
  bool ordered = true;
  const std::uint64_t done = g.run_events(3000, [&](const GasEvent& c) {
    ++calls;
    ordered = ordered && c.time >= previous && c.time == g.time();
    previous = c.time;
    if (calls % 60 != 0) return;  // the positions are a copy of every ball's
    const auto p = g.positions();
    worst = std::max(worst, std::fabs(g.nearest_image(p[c.first], p[c.second]).norm() - 1));
  });
  CHECK(done == 3000);
  CHECK(calls == 3000);
  CHECK(ordered);
  CHECK(worst < 1e-9);
  // A callback that is a plain function takes the same path.
  static std::uint64_t counted = 0;
  counted = 0;
  CHECK(g.run(500, std::numeric_limits<double>::infinity(), +[](const GasEvent&) { ++counted; }) == 500);
  CHECK(counted == 500);
}

TEST_CASE("A gas built from another's state runs on as it would have", "[simulation][gas]") {
  gas::Options options;
  options.dimension = 3;
  options.balls = 256;
  Gas<3> first(gas::lattice<3>(options));
  first.run_events(2000);
  const GasSetup<3> state = first.setup();
  Gas<3> second(state);
  CHECK(second.temperature() == Approx(first.temperature()).epsilon(1e-15));
  CHECK(second.momentum().norm() < 1e-12);
  const auto p = second.positions();
  for (std::size_t i = 0; i < p.size(); ++i) {
    CHECK(p[i] == state.balls[i].position);
  }
}
