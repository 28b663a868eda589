// Shots played to rest by billiards::simulation::Shot (billiards/simulation/shot.hpp), invariant checks
// off as in a user's release build:
// - shot/break/9ball and shot/break/8ball: the breaks pooltool's bench plays (../shared/peers/pooltool/
//   bench_breaks.py): the 7-ft table, racks with 1e-3 R of jitter, the cue ball struck straight at the
//   apex at 8 m/s a quarter radius above its centre. Each iteration plays the next of 64 seeded racks;
//   the time per break and per event.
// - shot/random and shot/random/threads:N: random shots (1–16 balls scattered, some frozen to a ball or
//   a cushion; 0.1–12 m/s, any direction, tip offsets within 0.7 R, elevation up to 17°) on one core,
//   and, where BILLIARDS_BENCH_THREADS is set, one shot per thread on every core: shots per second.
// - games/play/<game> and games/rules/<game> (9ball, 8ball, snooker, 3cushion): 256 shots of games a
//   seeded random player plays (games::Game; any cue in pool, a cue aimed with a random cut at a ball it
//   may meet first in snooker and three-cushion), replayed from where each started, against the rules'
//   decision alone on each shot's events: the rules' share of a game's time.
#include <billiards/simulation/games.hpp>
#include <billiards/simulation/shot.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <tuple>
#include <type_traits>
#include <variant>
#include <thread>
#include <vector>

namespace {

using namespace billiards::simulation;

void breaks(benchmark::State& state, Rack kind) {
  const PoolTable table = pool_table("7ft");
  const PoolPhysics physics;
  ShotOptions options;
  options.check_invariants = false;
  std::vector<std::vector<PoolBall>> racks;
  for (std::uint64_t seed = 0; seed < 64; ++seed) racks.push_back(rack(table, physics, kind, 1e-3, seed));
  const billiards::Cue<double> cue{0.567, 8.0, 0.0, 0.0, 0.0, 0.25, 1.0};
  std::size_t next = 0;
  std::uint64_t events = 0;
  for (auto _ : state) {
    Shot shot(table, physics, racks[next], options);
    next = (next + 1) % racks.size();
    shot.strike(0, cue);
    shot.play();
    events += shot.events().size();
    benchmark::DoNotOptimize(shot.time());
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["events_per_break"] = static_cast<double>(events) / static_cast<double>(state.iterations());
  state.counters["events_per_second"] = benchmark::Counter(static_cast<double>(events), benchmark::Counter::kIsRate);
}

// The random shot of `seed`: its table, balls and cue.
struct RandomShot {
  PoolTable table;
  std::vector<PoolBall> balls;
  billiards::Cue<double> cue;
};
RandomShot random_shot(std::uint64_t seed, const PoolPhysics& physics) {
  static const char* const sizes[] = {"7ft", "8ft", "9ft"};
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  RandomShot shot{pool_table(sizes[seed % 3]), {}, {}};
  shot.balls = scatter(shot.table, physics, 1 + static_cast<std::size_t>(unit(random) * 16) % 16, seed);
  const double r = 0.7 * std::sqrt(unit(random)), angle = 2 * M_PI * unit(random);
  shot.cue = {0.567, 0.1 + 11.9 * unit(random), 2 * M_PI * unit(random), 0.3 * unit(random),
              r * std::cos(angle), r * std::sin(angle), 1.0};
  return shot;
}

void random_shots(benchmark::State& state) {
  const PoolPhysics physics;
  ShotOptions options;
  options.check_invariants = false;
  // Each thread its own shots: seeds thread, thread + threads, …
  std::vector<RandomShot> shots;
  for (std::uint64_t k = 0; k < 256; ++k)
    shots.push_back(random_shot(k * static_cast<std::uint64_t>(state.threads()) + static_cast<std::uint64_t>(state.thread_index()), physics));
  std::size_t next = 0;
  std::uint64_t events = 0;
  for (auto _ : state) {
    const RandomShot& s = shots[next];
    next = (next + 1) % shots.size();
    Shot shot(s.table, physics, s.balls, options);
    shot.strike(0, s.cue);
    shot.play();
    events += shot.events().size();
    benchmark::DoNotOptimize(shot.time());
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["events_per_shot"] = static_cast<double>(events) / static_cast<double>(state.iterations());
}

// A shot of a game: where it started, who struck with which cue, the state before it and its events.
struct GameShot {
  std::vector<PoolBall> balls;
  std::size_t striker = 0;
  billiards::Cue<double> cue;
  games::Game::State before;
  std::vector<ShotEvent> events;
};

// The direction from the struck ball to a ball the player may meet first (pool: any direction), cut at
// random.
double aim(const games::Game& game, std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(0, 1);
  const auto& balls = game.balls();
  const std::size_t from = game.striker();
  std::vector<std::size_t> candidates;
  for (std::size_t b = 0; b < balls.size(); ++b)
    if (!balls[b].pocketed && game.may_meet_first(b)) candidates.push_back(b);
  if (candidates.empty() || balls[from].pocketed || game.kind() == games::GameKind::nine_ball ||
      game.kind() == games::GameKind::eight_ball)
    return 2 * M_PI * unit(random);
  const Eigen::Vector3d d = balls[candidates[random() % candidates.size()]].position - balls[from].position;
  return std::atan2(d.y(), d.x()) + 0.08 * (2 * unit(random) - 1);
}

std::vector<GameShot> game_shots(games::GameKind kind, const char* table_name) {
  games::Game game(kind, table_preset(table_name), physics_preset(table_name), {}, 2);
  std::mt19937_64 random(2026);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<GameShot> shots;
  while (shots.size() < 256) {
    GameShot s;
    s.before = game.state();
    s.cue = {0.567, 0.3 + 6.7 * unit(random), aim(game, random), 0.0, 0.8 * unit(random) - 0.4,
             0.8 * unit(random) - 0.4, 1.0};
    s.striker = game.striker();
    game.step(s.cue, TableVector(0.4 + 0.35 * unit(random), 0.6 + 0.6 * unit(random)));
    s.balls = game.last_shot()->placed();
    s.events = game.last_shot()->events();
    shots.push_back(std::move(s));
    if (game.over()) game.reset(1e-3, shots.size());
  }
  return shots;
}

void game_play(benchmark::State& state, games::GameKind kind, const char* table_name) {
  const std::vector<GameShot> shots = game_shots(kind, table_name);
  const PoolTable table = table_preset(table_name);
  const PoolPhysics physics = physics_preset(table_name);
  std::size_t next = 0;
  for (auto _ : state) {
    const GameShot& s = shots[next];
    next = (next + 1) % shots.size();
    Shot shot(table, physics, s.balls);
    shot.strike(s.striker, s.cue);
    shot.play();
    benchmark::DoNotOptimize(shot.time());
  }
  state.SetItemsProcessed(state.iterations());
}

void game_rules(benchmark::State& state, games::GameKind kind, const char* table_name) {
  const std::vector<GameShot> shots = game_shots(kind, table_name);
  std::size_t next = 0;
  for (auto _ : state) {
    const GameShot& s = shots[next];
    next = (next + 1) % shots.size();
    const bool legal = std::visit(
        [&](const auto& before) {
          using State = std::decay_t<decltype(before)>;
          if constexpr (std::is_same_v<State, games::NineBallState>) return games::nine_ball(before, s.events).verdict.legal();
          if constexpr (std::is_same_v<State, games::EightBallState>) return games::eight_ball(before, s.events).verdict.legal();
          if constexpr (std::is_same_v<State, games::SnookerState>) return games::snooker(before, s.events).verdict.legal();
          if constexpr (std::is_same_v<State, games::ThreeCushionState>) return games::three_cushion(before, s.events).verdict.legal();
        },
        s.before);
    benchmark::DoNotOptimize(legal);
  }
  state.SetItemsProcessed(state.iterations());
}

const bool games_registered = [] {
  const std::tuple<const char*, games::GameKind, const char*> all[] = {
      {"9ball", games::GameKind::nine_ball, "7ft"}, {"8ball", games::GameKind::eight_ball, "7ft"},
      {"snooker", games::GameKind::snooker, "snooker"}, {"3cushion", games::GameKind::three_cushion, "carom"}};
  for (const auto& [name, kind, table] : all) {
    benchmark::RegisterBenchmark((std::string("games/play/") + name).c_str(), game_play, kind, table)->UseRealTime();
    benchmark::RegisterBenchmark((std::string("games/rules/") + name).c_str(), game_rules, kind, table)->UseRealTime();
  }
  return true;
}();

const bool shot_registered = [] {
  benchmark::RegisterBenchmark("shot/break/9ball", breaks, Rack::nine_ball)->UseRealTime();
  benchmark::RegisterBenchmark("shot/break/8ball", breaks, Rack::eight_ball)->UseRealTime();
  benchmark::RegisterBenchmark("shot/random", random_shots)->UseRealTime();
  // One shot per thread on every core: unpinned, so it runs where bench/run.sh runs it apart from the
  // rest (BILLIARDS_BENCH_THREADS set; a run pinned to one core would share that core).
  const int cores = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  if (cores > 1 && std::getenv("BILLIARDS_BENCH_THREADS") != nullptr)
    benchmark::RegisterBenchmark("shot/random", random_shots)->Threads(cores)->UseRealTime();
  return true;
}();

}  // namespace
