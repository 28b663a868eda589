// Events per second of the event-driven table of billiards::simulation as the number of balls grows, at
// a constant density (the area per ball of 16 balls on a 9-ft table). Each event re-predicts the one or
// two balls it changed against every other ball: O(N) per event, all-pairs prediction (see
// docs/simulations.md for why). Overlap is checked for the event's balls only here (O(N)); the program
// checks every pair by default.
#include <billiards/simulation/gas.hpp>
#include <billiards/simulation/table.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>

namespace {

void table_events(benchmark::State& state) {
  const auto balls = static_cast<std::size_t>(state.range(0));
  billiards::simulation::TableSetup table;
  const double scale = std::sqrt(static_cast<double>(balls) / 16);
  table.width *= scale;
  table.height *= scale;
  billiards::simulation::Table simulation(billiards::simulation::random_setup(table, balls, 1), false);
  for (int i = 0; i < 1000; ++i) simulation.step();  // past the start, where every ball is predicted afresh
  for (auto _ : state) {
    const billiards::simulation::TableEvent event = *simulation.step();
    benchmark::DoNotOptimize(event);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["balls"] = static_cast<double>(balls);
}

// The hard-sphere gas of billiards/simulation/gas.hpp at a fixed packing fraction as N grows: each
// event predicts against the balls of the neighbouring cells only, so the cost per event should not
// grow with N (the caches aside). Equilibrated for max(N, 20000) collisions before
// the timing; each iteration runs 1000 collisions.
template <int D>
void gas_events(benchmark::State& state) {
  billiards::simulation::gas::Options options;
  options.dimension = D;
  options.balls = static_cast<std::size_t>(state.range(0));
  options.packing_fraction = 0.3;
  billiards::simulation::Gas<D> gas(billiards::simulation::gas::lattice<D>(options));
  gas.run_events(std::max<std::uint64_t>(options.balls, 20000));
  constexpr std::uint64_t per_iteration = 1000;
  for (auto _ : state) gas.run_events(per_iteration);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * per_iteration));
  state.counters["balls"] = static_cast<double>(options.balls);
}

// The largest gas benchmarked: BILLIARDS_BENCH_MAX_BALLS (default 10^6; CI's smoke run caps it).
std::int64_t max_balls() {
  const char* text = std::getenv("BILLIARDS_BENCH_MAX_BALLS");
  return text != nullptr ? std::max<std::int64_t>(1024, std::atoll(text)) : 1000000;
}

const bool gas_registered = [] {
  for (const std::int64_t balls :
       {std::int64_t(1024), std::int64_t(10000), std::int64_t(100000), std::int64_t(1000000)}) {
    if (balls > max_balls()) break;
    benchmark::RegisterBenchmark("gas/events/3d", gas_events<3>)
        ->Arg(balls)
        ->UseRealTime()
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark("gas/events/2d", gas_events<2>)
        ->Arg(balls)
        ->UseRealTime()
        ->Unit(benchmark::kMicrosecond);
  }
  return true;
}();

}  // namespace

BENCHMARK(table_events)->Name("table/events")->RangeMultiplier(4)->Range(16, 1024)->UseRealTime();
