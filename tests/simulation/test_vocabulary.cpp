// The engines' common vocabulary: one templated test drives Shot, Table, Gas<2> and Gas<3> through the
// same calls — step(), run_events(), run_until(), time(), energy(), balls(), event_count() and the event's
// time, kind, first and second — and checks what each promises the same way: the energy against a sum
// worked from balls() by hand (conserved by the elastic engines, never gained by the shot), the events in
// time order, run_until stopping at its time, step() on an engine at rest, and the same exception types
// for the same situations.
#include <billiards/simulation/gas.hpp>
#include <billiards/simulation/shot.hpp>
#include <billiards/simulation/table.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

using namespace billiards::simulation;

static_assert(std::is_base_of_v<std::runtime_error, EventLimitReached>);
static_assert(std::is_base_of_v<std::logic_error, BrokenInvariant>);

namespace {

template <class Engine>
struct Rig;

template <>
struct Rig<Table> {
  using Event = TableEvent;
  static constexpr bool elastic = true;
  static constexpr std::uint64_t events = 300;  // of a break
  static Table moving() { return Table(break_setup(TableSetup{})); }
  static Table at_rest() { return Table(break_setup(TableSetup{}, 0.0)); }
  // Σ ½ m v², from the balls as the engine reports them.
  static double hand_energy(const Table& t) {
    double sum = 0;
    for (const Ball<2>& b : t.balls()) sum += 0.5 * t.setup().mass * b.velocity.squaredNorm();
    return sum;
  }
  static std::size_t ball_count() { return 16; }
  static std::optional<Table> limited() { return std::nullopt; }  // runs are bounded by their count
};

template <>
struct Rig<Shot> {
  using Event = ShotEvent;
  static constexpr bool elastic = false;
  static constexpr std::uint64_t events = 60;  // of a 9-ball break's hundred
  static Shot make(bool strike, ShotOptions options = {}) {
    const PoolTable table = pool_table("9ft");
    const PoolPhysics physics;
    Shot shot(table, physics, rack(table, physics, Rack::nine_ball), options);
    if (strike) shot.strike(0, billiards::Cue<double>{0.567, 8.0, 0.0, 0.0, 0.0, 0.25});
    return shot;
  }
  static Shot moving() { return make(true); }
  static Shot at_rest() { return make(false); }
  // Σ ½ m v² + ⅕ m R² ω² over the balls in play.
  static double hand_energy(const Shot& s) {
    const double m = s.physics().mass, R = s.physics().radius;
    double sum = 0;
    for (const PoolBall& b : s.balls()) {
      if (!b.pocketed)
        sum += 0.5 * m * b.velocity.squaredNorm() + 0.2 * m * R * R * b.angular_velocity.squaredNorm();
    }
    return sum;
  }
  static std::size_t ball_count() { return 10; }
  static std::optional<Shot> limited() {
    ShotOptions options;
    options.event_limit = 5;
    return make(true, options);
  }
};

template <int D>
struct Rig<Gas<D>> {
  using Event = GasEvent;
  static constexpr bool elastic = true;
  static constexpr std::uint64_t events = 300;
  static gas::Options options() {
    gas::Options o;
    o.dimension = D;
    o.balls = 200;
    o.seed = 7;
    return o;
  }
  static Gas<D> moving() { return Gas<D>(gas::lattice<D>(options())); }
  static Gas<D> at_rest() {
    GasSetup<D> setup = gas::lattice<D>(options());
    for (Ball<D>& b : setup.balls) b.velocity.setZero();
    return Gas<D>(setup);
  }
  static double hand_energy(const Gas<D>& g) {
    const std::vector<double> masses = g.masses();
    const std::vector<Ball<D>> balls = g.balls();
    double sum = 0;
    for (std::size_t i = 0; i < balls.size(); ++i) sum += 0.5 * masses[i] * balls[i].velocity.squaredNorm();
    return sum;
  }
  static std::size_t ball_count() { return 200; }
  // One event in a row without a collision is allowed: the lattice's balls cross cells or rebuild
  // their lists before they meet.
  static std::optional<Gas<D>> limited() { return Gas<D>(gas::lattice<D>(options()), 1); }
};

// The relative difference of two energies.
double relative(double a, double b) { return std::fabs(a - b) / std::fabs(b); }

}  // namespace

TEMPLATE_TEST_CASE("Every engine speaks the same vocabulary", "[simulation][vocabulary]", Table, Shot, Gas<2>,
                   Gas<3>) {
  using R = Rig<TestType>;
  using Event = typename R::Event;
  // The same names for the same things, of the same types.
  static_assert(std::is_same_v<decltype(std::declval<const TestType&>().time()), double>);
  static_assert(std::is_same_v<decltype(std::declval<TestType&>().step()), std::optional<Event>>);
  static_assert(std::is_same_v<decltype(std::declval<TestType&>().run_events(1)), std::uint64_t>);
  static_assert(std::is_same_v<decltype(std::declval<TestType&>().run_until(1.0)), std::uint64_t>);
  static_assert(std::is_same_v<decltype(std::declval<const TestType&>().energy()), double>);
  static_assert(std::is_same_v<decltype(std::declval<const TestType&>().event_count()), std::uint64_t>);
  static_assert(std::is_same_v<decltype(Event{}.time), double>);
  static_assert(std::is_same_v<decltype(Event{}.first), std::size_t>);
  static_assert(std::is_same_v<decltype(Event{}.second), std::size_t>);
  static_assert(std::is_enum_v<decltype(Event{}.kind)>);

  SECTION(
      "energy(): the kinetic energy of balls(), kept by the elastic engines and never gained by the shot") {
    TestType engine = R::moving();
    REQUIRE(engine.balls().size() == R::ball_count());
    const double start = engine.energy();
    REQUIRE(start > 0);
    CHECK(relative(start, R::hand_energy(engine)) <= 1e-14);
    double previous = start;
    std::uint64_t checked = 0;
    engine.run_events(R::events, [&](const Event&) {
      const double now = engine.energy();
      CHECK(std::fabs(now - R::hand_energy(engine)) <= 1e-13 * start);
      if (R::elastic) {
        CHECK(relative(now, start) <= 1e-12);
      } else {
        CHECK(now <= previous * (1 + 1e-12));
      }
      previous = now;
      ++checked;
    });
    CHECK(checked == R::events);
  }

  SECTION("events come in time order, each at the engine's time, and are counted") {
    TestType engine = R::moving();
    const std::uint64_t before = engine.event_count();
    double last = engine.time();
    std::vector<Event> seen;
    const std::uint64_t ran = engine.run_events(R::events, [&](const Event& e) {
      CHECK(e.time >= last);
      CHECK(e.time == engine.time());
      CHECK(std::string(kind_name(e.kind)).size() > 0);
      last = e.time;
      seen.push_back(e);
    });
    CHECK(ran == R::events);
    CHECK(seen.size() == R::events);
    CHECK(engine.event_count() == before + R::events);
    // step() runs the next one and returns it.
    const std::optional<Event> next = engine.step();
    REQUIRE(next);
    CHECK(next->time >= last);
    CHECK(engine.time() == next->time);
    CHECK(engine.event_count() == before + R::events + 1);
  }

  SECTION("run_until(t) runs the events up to t, stops at t, and leaves the later ones") {
    TestType engine = R::moving();
    engine.run_events(20);
    const double until = engine.time() + 0.05;
    std::uint64_t reported = 0;
    const std::uint64_t ran = engine.run_until(until, [&](const Event& e) {
      CHECK(e.time <= until);
      ++reported;
    });
    CHECK(ran == reported);
    CHECK(ran > 0);
    CHECK(engine.time() == until);
    const std::optional<Event> next = engine.step();
    REQUIRE(next);
    CHECK(next->time > until);
    // A time before now, or NaN, or +∞ is refused, naming the argument.
    CHECK_THROWS_MATCHES(
        engine.run_until(until / 2), std::invalid_argument,
        Catch::Matchers::Predicate<std::invalid_argument>([](const std::invalid_argument& e) {
          return std::string(e.what()).find("until") != std::string::npos;
        }));
    CHECK_THROWS_AS(engine.run_until(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
  }

  SECTION("step() on an engine at rest returns nothing, and time passes without events") {
    TestType engine = R::at_rest();
    CHECK(engine.energy() == 0);
    CHECK_FALSE(engine.step());
    CHECK(engine.time() == 0);
    CHECK(engine.event_count() == 0);
    CHECK(engine.run_events(10) == 0);
    std::uint64_t reported = 0;
    CHECK(engine.run_until(2.5, [&](const Event&) { ++reported; }) == 0);
    CHECK(reported == 0);
    CHECK(engine.time() == 2.5);
    CHECK(engine.balls().size() == R::ball_count());
  }

  SECTION("an engine's event limit is EventLimitReached, a std::runtime_error") {
    std::optional<TestType> engine = R::limited();
    if (engine) CHECK_THROWS_AS(engine->run_events(1000), EventLimitReached);
  }
}
