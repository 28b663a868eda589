// The shot's first test of a pair (detail::ShotReaches::near: which balls' boxes come within a moving
// ball's reach, eight at a time) against the same conditions written out one ball at a time: boxes that
// share only an edge or a corner, boxes of NaN, predictions that end exactly now or never, any first
// ball and count. Built twice: as the other simulation tests are (on x86-64, pairs of balls compared at
// once) and, as billiards_simulation_scalar_tests, with __SSE2__ undefined (one ball at a time, as on
// processors without those comparisons).
#include <billiards/simulation/shot.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

using billiards::simulation::detail::ShotReaches;
using billiards::simulation::shot::Box;

namespace {

struct Entry {
  Box box;
  double end;
  bool candidate, moving;
};

// Ball j's bit, from the conditions as near() states them, written out without Box::overlaps.
bool expected(const Entry& e, const Box& reach, bool moving, double now) {
  const bool overlaps = e.box.x_low <= reach.x_high && reach.x_low <= e.box.x_high &&
                        e.box.y_low <= reach.y_high && reach.y_low <= e.box.y_high;
  return overlaps && e.end >= now && e.candidate && (moving || e.moving);
}

// A coordinate from a small set, so that edges coincide often, or any value in [0, 3), or NaN.
double coordinate(std::mt19937_64& random) {
  static const double grid[] = {0.0, 0.5, 1.0, 1.5, 2.0, 2.5};
  std::uniform_int_distribution<int> kind(0, 9);
  const int k = kind(random);
  if (k == 0) return std::numeric_limits<double>::quiet_NaN();
  if (k < 6) return grid[std::uniform_int_distribution<int>(0, 5)(random)];
  return std::uniform_real_distribution<double>(0, 3)(random);
}

Box box(std::mt19937_64& random) {
  double x0 = coordinate(random), x1 = coordinate(random), y0 = coordinate(random), y1 = coordinate(random);
  if (x1 < x0) std::swap(x0, x1);
  if (y1 < y0) std::swap(y0, y1);
  return {x0, x1, y0, y1};
}

double end_time(std::mt19937_64& random, double now) {
  switch (std::uniform_int_distribution<int>(0, 4)(random)) {
    case 0: return now;
    case 1: return std::nextafter(now, 0.0);
    case 2: return std::numeric_limits<double>::infinity();
    case 3: return std::numeric_limits<double>::quiet_NaN();
    default: return std::uniform_real_distribution<double>(0, 2)(random);
  }
}

}  // namespace

TEST_CASE("ShotReaches::near sets a ball's bit exactly where its box, end and flags say", "[reach]") {
  std::mt19937_64 random(20261207);
  const double now = 1.0;
  std::uint64_t bits_set = 0, checked = 0;
  for (int round = 0; round < 3000; ++round) {
    const std::size_t balls = std::uniform_int_distribution<std::size_t>(1, 140)(random);
    ShotReaches reaches(balls);
    std::vector<Entry> entries(balls);
    for (std::size_t j = 0; j < balls; ++j) {
      std::uniform_int_distribution<int> coin(0, 3);
      entries[j] = {box(random), end_time(random, now), coin(random) != 0, coin(random) < 2};
      reaches.assign(j, entries[j].box, entries[j].end, entries[j].candidate, entries[j].moving);
    }
    const Box reach = box(random);
    const bool moving = std::uniform_int_distribution<int>(0, 1)(random) == 1;
    const std::size_t base = std::uniform_int_distribution<std::size_t>(0, balls - 1)(random);
    const std::size_t count = std::min<std::size_t>(64, balls - base);
    const std::uint64_t bits = reaches.near(reach, moving, now, base, count);
    for (std::size_t k = 0; k < 64; ++k) {
      const bool bit = (bits >> k) & 1;
      if (k >= count) {
        REQUIRE_FALSE(bit);
        continue;
      }
      const bool want = expected(entries[base + k], reach, moving, now);
      if (bit != want) FAIL("round " << round << ", ball " << base + k << " of " << balls << ": bit " << bit);
      bits_set += bit;
      ++checked;
    }
  }
  // Both answers are common: the draw tests the bits, not an all-zero mask.
  CHECK(bits_set > checked / 20);
  CHECK(bits_set < checked / 2);
}

TEST_CASE("ShotReaches::near: boxes sharing an edge or a corner with the reach are near", "[reach]") {
  ShotReaches reaches(9);
  const Box reach{1, 2, 1, 2};
  const Box touching[] = {{0, 1, 1, 2}, {2, 3, 1, 2}, {1, 2, 0, 1}, {1, 2, 2, 3}, {0, 1, 0, 1}, {2, 3, 2, 3}};
  const Box apart[] = {{0, std::nextafter(1.0, 0.0), 1, 2}, {std::nextafter(2.0, 3.0), 3, 1, 2},
                       {1, 2, std::nextafter(2.0, 3.0), 3}};
  std::size_t j = 0;
  for (const Box& b : touching) reaches.assign(j++, b, 5, true, true);
  for (const Box& b : apart) reaches.assign(j++, b, 5, true, true);
  CHECK(reaches.near(reach, true, 5, 0, 9) == 0b000111111);
  // Ending just before now: none; a ball at rest meets only moving ones.
  CHECK(reaches.near(reach, true, std::nextafter(5.0, 6.0), 0, 9) == 0);
  reaches.assign(0, touching[0], 5, true, false);
  CHECK(reaches.near(reach, false, 5, 0, 9) == 0b000111110);
  CHECK(reaches.near(reach, false, 5, 3, 6) == 0b000111);
}
