// The event calendar of billiards/simulation/event_calendar.hpp against a reference it does not share code
// with: a std::set of (time, item) pairs. Random moves of random items, times drawn near now, far beyond the
// year, equal, and +∞; each step the earliest must be an item with the reference's earliest time, and what
// the look ahead reports must be the pending items of a span of times after it, nearer first. The shot's
// queue (core/event_queue.hpp, OwnedEvents) against a std::multiset of its events likewise.
#include <billiards/simulation/core/event_calendar.hpp>
#include <billiards/simulation/core/event_queue.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <utility>
#include <vector>

using billiards::simulation::EventCalendar;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// The look ahead's report, where it makes one: items with finite times after the earliest's, none
// twice, those one bucket ahead no later than those two ahead, and every item whose time lies
// within the span reported among them (a whole bucket, not its first items).
void check_look_ahead(EventCalendar& calendar, const std::set<std::pair<double, std::uint32_t>>& reference,
                      const std::vector<double>& times, std::uint32_t earliest) {
  std::vector<std::pair<std::uint32_t, int>> soon;
  calendar.look_ahead(2, [&](std::uint32_t i, int ahead) { soon.push_back({i, ahead}); });
  if (soon.empty()) return;
  double lo = inf, hi = -inf, latest_first = -inf, earliest_second = inf;
  std::set<std::uint32_t> seen;
  for (const auto& [i, ahead] : soon) {
    REQUIRE(i < times.size());
    REQUIRE((ahead == 1 || ahead == 2));
    REQUIRE(seen.insert(i).second);
    REQUIRE(std::isfinite(times[i]));
    REQUIRE(times[i] >= times[earliest]);
    lo = std::min(lo, times[i]);
    hi = std::max(hi, times[i]);
    if (ahead == 1) latest_first = std::max(latest_first, times[i]);
    if (ahead == 2) earliest_second = std::min(earliest_second, times[i]);
  }
  REQUIRE(latest_first <= earliest_second);
  for (auto it = reference.lower_bound({lo, 0}); it != reference.end() && it->first <= hi; ++it) {
    INFO("item " << it->second << " at " << it->first << " lies in the span reported, [" << lo << ", " << hi
                 << "]");
    REQUIRE(seen.count(it->second) == 1);
  }
}

// Runs `steps` events: each takes the earliest item, moves now to its time and files it (and
// `others` random items) at a later time drawn by `draw`. With `defer`, filings into later buckets
// wait in the calendar's queue (defer_filings), which is switched off and on again now and then.
template <class Draw>
void run_with(bool defer, std::size_t items, int steps, int others, Draw draw) {
  INFO("filings deferred: " << defer);
  std::mt19937_64 random(items * 7919 + static_cast<std::size_t>(steps));
  std::vector<double> times(items);
  double now = 0;
  for (double& t : times) t = draw(random, now);
  EventCalendar calendar;
  calendar.defer_filings(defer);
  calendar.reset(times, now);
  std::set<std::pair<double, std::uint32_t>> reference;
  for (std::uint32_t i = 0; i < items; ++i) reference.insert({times[i], i});
  std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(items - 1));
  const auto move = [&](std::uint32_t i, double t) {
    reference.erase({times[i], i});
    times[i] = t;
    reference.insert({t, i});
    calendar.prefetch_record(i);  // hints: they change nothing, and take no address out of range
    calendar.prefetch_removal(i);
    calendar.prefetch_update(i, t);
    calendar.update(i, t);
  };
  for (int step = 0; step < steps; ++step) {
    const std::uint32_t earliest = calendar.earliest();
    if (reference.begin()->first == inf) {
      REQUIRE(earliest == EventCalendar::none);
      return;
    }
    REQUIRE(earliest != EventCalendar::none);
    REQUIRE(times[earliest] == reference.begin()->first);
    REQUIRE(calendar.time(earliest) == times[earliest]);
    // The look ahead before the moves, or on every third step after them, when filings may wait.
    if (step % 3 != 1) check_look_ahead(calendar, reference, times, earliest);
    now = times[earliest];
    move(earliest, draw(random, now));
    for (int k = 0; k < others; ++k) move(pick(random), draw(random, now));
    if (step % 3 == 1) {
      const std::uint32_t next = calendar.earliest();
      if (next != EventCalendar::none) check_look_ahead(calendar, reference, times, next);
    }
    if (step % 5000 == 4999) calendar.reset(times, now);  // refiled mid-run, as the gas does
    if (defer && step % 3001 == 3000) {                   // the waiting filings filed at once
      calendar.defer_filings(false);
      calendar.defer_filings(true);
    }
  }
}

template <class Draw>
void run_against_reference(std::size_t items, int steps, int others, Draw draw) {
  run_with(false, items, steps, others, draw);
  run_with(true, items, steps, others, draw);
}

}  // namespace

TEST_CASE("the event calendar returns the earliest time, as a sorted set does") {
  SECTION("exponential times, as a gas's events") {
    run_against_reference(1000, 50000, 1, [](std::mt19937_64& r, double now) {
      return now + std::exponential_distribution<double>(1.0)(r);
    });
  }
  SECTION("a few items, times far beyond the year among near ones") {
    run_against_reference(5, 20000, 2, [](std::mt19937_64& r, double now) {
      const double u = std::uniform_real_distribution<double>(0, 1)(r);
      return u < 0.2 ? now + 1e6 * u : now + 1e-3 * u;
    });
  }
  SECTION("equal times and items without an event") {
    run_against_reference(300, 30000, 3, [](std::mt19937_64& r, double now) {
      const int k = std::uniform_int_distribution<int>(0, 9)(r);
      if (k == 0) return inf;
      if (k < 4) return now;       // at once
      return std::floor(now) + k;  // many equal times
    });
  }
  SECTION("every time +∞ but one, then none") {
    run_against_reference(64, 100, 0, [](std::mt19937_64& r, double now) {
      return now == 0 && std::uniform_int_distribution<int>(0, 63)(r) == 0 ? 1.0 : inf;
    });
  }
  SECTION("times spread over 300 orders of magnitude") {
    run_against_reference(200, 20000, 1, [](std::mt19937_64& r, double now) {
      return now + std::pow(10.0, std::uniform_real_distribution<double>(-150, 150)(r));
    });
  }
}

TEST_CASE("the event calendar rejects a NaN time or one before now") {
  EventCalendar calendar;
  CHECK_THROWS_AS(calendar.reset({1.0, std::nan("")}, 0), std::invalid_argument);
  CHECK_THROWS_AS(calendar.reset({1.0, 0.5}, 0.75), std::invalid_argument);
  calendar.reset({}, 0);
  CHECK(calendar.earliest() == EventCalendar::none);
}

// The shot's queue, billiards::simulation::detail::OwnedEvents, against a std::multiset of every event
// queued: random pushes by random owners (times drawn from few values, so that ties are common and the
// order between them is the events' own, or from many, so that one owner holds the least time), pops of
// the earliest and clears of an owner's events, for one owner up to more than 64 (the owners' times are
// scanned two at a time up to 64). Each step the owner named earliest must hold the reference's first
// event.
TEST_CASE("OwnedEvents pops the earliest of all owners' events, and clear drops one owner's", "[queue]") {
  struct Event {
    double time;
    int key;  // breaks ties, as a prediction's kind and balls do
    std::size_t owner;
    bool operator>(const Event& o) const { return time > o.time || (time == o.time && key > o.key); }
    bool operator<(const Event& o) const { return o > *this; }
  };
  const std::size_t owners = GENERATE(std::size_t{1}, std::size_t{7}, std::size_t{10}, std::size_t{16},
                                      std::size_t{64}, std::size_t{65}, std::size_t{70});
  // Room for one event an owner: the shared array widens again and again; for sixteen: rarely.
  const std::size_t room = GENERATE(std::size_t{1}, std::size_t{16});
  const int values = GENERATE(20, 1 << 30);
  billiards::simulation::detail::OwnedEvents<Event> queue(owners, room);
  std::multiset<Event> reference;
  std::mt19937_64 random(11);
  std::uniform_int_distribution<int> action(0, 9), value(0, values), key(0, 20);
  std::uniform_int_distribution<std::size_t> who(0, owners - 1);
  int pops = 0, clears = 0;
  for (int step = 0; step < 20000; ++step) {
    const int a = action(random);
    if (a < 5 || reference.empty()) {
      const Event e{static_cast<double>(value(random)) / 4, key(random), who(random)};
      queue.push(e.owner, e);
      reference.insert(e);
    } else if (a < 9) {
      const std::size_t owner = queue.earliest();
      REQUIRE(owner < owners);
      const Event& top = queue.top(owner);
      const Event first = *reference.begin();
      REQUIRE(top.time == first.time);
      REQUIRE(top.key == first.key);
      const Event popped = queue.pop(owner);
      // the reference's equal events are interchangeable only where they are equal in every field
      const auto it = std::find_if(reference.begin(), reference.end(), [&](const Event& e) {
        return e.time == popped.time && e.key == popped.key && e.owner == popped.owner;
      });
      REQUIRE(it != reference.end());
      reference.erase(it);
      ++pops;
    } else {
      const std::size_t owner = who(random);
      queue.clear(owner);
      std::erase_if(reference, [&](const Event& e) { return e.owner == owner; });
      ++clears;
    }
    REQUIRE(queue.size() == reference.size());
    REQUIRE(queue.empty() == reference.empty());
  }
  CHECK(pops > 5000);
  CHECK(clears > 1000);
}
