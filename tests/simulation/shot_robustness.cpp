// billiards-shot-robustness: seeded random breaks and random shots played to rest with every invariant
// checked at every event (billiards::simulation::Shot, ShotOptions::check_invariants): no overlap of
// balls, cushions or jaws beyond 1e-9 of a radius, every ball on the cloth or pocketed, no energy gained,
// every shot at rest within the event limit. Prints the failures (with their seeds) and the event counts'
// distribution as Markdown.
//
//   billiards-shot-robustness [--table pool|snooker|carom] [--breaks N] [--shots N] [--first-seed S]
//
// On the pool tables (the default), a break of seed s: the 9-ball rack for even s, the 8-ball for odd;
// the 7-, 8- or 9-ft table by s mod 3; a jitter of 0 to 0.01 R; the cue ball struck at 5 to 12 m/s,
// aimed within ±1° of the apex, the tip within 0.3 R of the centre, the cue up to 10° from level. On the
// snooker table a break is the snooker set-up (billiards::simulation::snooker_setup, the same jitter)
// with the white struck from the D at 3 to 12 m/s towards a red drawn from s; on the carom table the
// three-cushion opening position with the cue ball struck at 1 to 12 m/s in any direction. A shot of seed
// s: 1 to 16 balls scattered (billiards::simulation::scatter: about a quarter frozen to a ball, a quarter
// to a cushion), the cue ball struck at 0.1 to 12 m/s in any direction, the tip anywhere within 0.7 R,
// the cue up to 30°. Each table with its physics (billiards::simulation::physics_preset).
//
// Exit status: 0 when every shot came to rest with every invariant kept; 1 otherwise; 2 on a bad command
// line.
#include <billiards/simulation/shot.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace billiards::simulation;

struct Outcome {
  std::vector<std::size_t> events;
  std::size_t pocketed = 0;
  std::vector<std::string> failures;
};

void play(Outcome& outcome, const std::string& name, const PoolTable& table, const PoolPhysics& physics,
          const std::vector<PoolBall>& balls, const billiards::Cue<double>& cue) {
  ShotOptions options;
  options.check_invariants = true;
  try {
    Shot shot(table, physics, balls, options);
    shot.strike(0, cue);
    shot.play();
    for (const PoolBall& b : shot.balls()) {
      if (!b.pocketed && b.velocity.norm() != 0) throw std::logic_error("a ball still moves at the end");
      outcome.pocketed += b.pocketed ? 1 : 0;
    }
    outcome.events.push_back(shot.events().size());
  } catch (const std::exception& error) {
    outcome.failures.push_back(name + ": " + error.what());
  }
}

std::string distribution(std::vector<std::size_t> counts) {
  if (counts.empty()) return "| (none) | | | | | | |";
  std::sort(counts.begin(), counts.end());
  const auto at = [&](double q) { return counts[static_cast<std::size_t>(q * static_cast<double>(counts.size() - 1))]; };
  double mean = 0;
  for (const std::size_t c : counts) mean += static_cast<double>(c);
  mean /= static_cast<double>(counts.size());
  char text[200];
  std::snprintf(text, sizeof text, "| %zu | %zu | %.1f | %zu | %zu | %zu | %zu |", counts.size(), counts.front(), mean,
                at(0.5), at(0.9), at(0.99), counts.back());
  return text;
}

bool count_argument(const char* text, std::uint64_t& value) {
  char* end = nullptr;
  if (text == nullptr || *text == '\0' || *text == '-') return false;
  errno = 0;
  const unsigned long long parsed = std::strtoull(text, &end, 10);
  if (*end != '\0' || errno == ERANGE || parsed > 100000000ULL) return false;
  value = parsed;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t breaks = 10000, shots = 10000, first = 0;
  std::string kind = "pool";
  for (int k = 1; k < argc; k += 2) {
    const std::string option = argv[k];
    if (option == "--table" && k + 1 < argc) {
      kind = argv[k + 1];
      if (kind == "pool" || kind == "snooker" || kind == "carom") continue;
      std::fprintf(stderr, "billiards-shot-robustness: --table '%s', expected pool, snooker or carom\n", kind.c_str());
      return 2;
    }
    std::uint64_t* target = option == "--breaks" ? &breaks : option == "--shots" ? &shots : option == "--first-seed" ? &first : nullptr;
    if (target == nullptr || k + 1 >= argc || !count_argument(argv[k + 1], *target)) {
      std::fprintf(stderr, "billiards-shot-robustness: '%s' %s, expected --breaks N, --shots N or --first-seed S (N at most 10^8)\n",
                   option.c_str(), target == nullptr ? "is not an option" : "needs a whole number");
      return 2;
    }
  }
  static const char* const sizes[] = {"7ft", "8ft", "9ft"};
  const auto table_of = [&](std::uint64_t seed) { return table_preset(kind == "pool" ? sizes[seed % 3] : kind); };
  const PoolPhysics physics = physics_preset(kind == "pool" ? "9ft" : kind);
  Outcome broke, shot;
  for (std::uint64_t seed = first; seed < first + breaks; ++seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    const PoolTable table = table_of(seed);
    const double r = 0.3 * std::sqrt(unit(random)), angle = 2 * M_PI * unit(random);
    billiards::Cue<double> cue{0.567, 5 + 7 * unit(random), (2 * unit(random) - 1) * M_PI / 180,
                               10 * M_PI / 180 * unit(random), r * std::cos(angle), r * std::sin(angle), 1.0};
    std::vector<PoolBall> balls;
    if (kind == "pool") {
      balls = rack(table, physics, seed % 2 == 0 ? Rack::nine_ball : Rack::eight_ball, 0.01 * unit(random), seed);
    } else if (kind == "snooker") {
      balls = snooker_setup(table, physics, 0.01 * unit(random), seed);
      const Eigen::Vector3d to = balls[1 + seed % 15].position - balls[0].position;
      cue.speed = 3 + 9 * unit(random);
      cue.azimuth += std::atan2(to.y(), to.x());
    } else {
      balls = three_cushion_setup(table, physics, seed % 2 == 0 ? 1 : -1);
      cue.speed = 1 + 11 * unit(random);
      cue.azimuth = 2 * M_PI * unit(random);
    }
    play(broke, "break " + std::to_string(seed), table, physics, balls, cue);
  }
  for (std::uint64_t seed = first; seed < first + shots; ++seed) {
    std::mt19937_64 random(seed ^ 0x5eed5eed5eedULL);
    std::uniform_real_distribution<double> unit(0, 1);
    const PoolTable table = table_of(seed);
    const std::vector<PoolBall> balls = scatter(table, physics, 1 + seed % 16, seed);
    const double r = 0.7 * std::sqrt(unit(random)), angle = 2 * M_PI * unit(random);
    const billiards::Cue<double> cue{0.567, 0.1 + 11.9 * unit(random), 2 * M_PI * unit(random),
                                     30 * M_PI / 180 * unit(random), r * std::cos(angle), r * std::sin(angle), 1.0};
    play(shot, "shot " + std::to_string(seed), table, physics, balls, cue);
  }
  std::printf("| played | shots | least events | mean | median | 90 %% | 99 %% | most |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
  std::printf("| %s breaks (seeds %llu to %llu) %s\n", kind.c_str(), static_cast<unsigned long long>(first),
              static_cast<unsigned long long>(first + breaks - 1), distribution(broke.events).c_str());
  std::printf("| %s random shots (seeds %llu to %llu) %s\n", kind.c_str(), static_cast<unsigned long long>(first),
              static_cast<unsigned long long>(first + shots - 1), distribution(shot.events).c_str());
  std::printf("\nballs pocketed: %zu in the breaks, %zu in the shots\n", broke.pocketed, shot.pocketed);
  const std::size_t failures = broke.failures.size() + shot.failures.size();
  std::printf("failures: %zu (overlaps, balls off the cloth, energy gained, runaway shots)\n", failures);
  for (const auto* list : {&broke.failures, &shot.failures}) {
    for (const std::string& failure : *list) std::printf("- %s\n", failure.c_str());
  }
  return failures == 0 ? 0 : 1;
}
