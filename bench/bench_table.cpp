// Events per second of the event-driven table in examples/ as the number of balls grows, at a
// constant density (the area per ball of 16 balls on a 9-ft table). Each event re-predicts the one or
// two balls it changed against every other ball: O(N) per event, naive all-pairs prediction (see the
// README for why). Overlap is checked for the event's balls only here (O(N)); the example program
// checks every pair by default.
#include "table.hpp"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

void table_events(benchmark::State& state) {
  const auto balls = static_cast<std::size_t>(state.range(0));
  billiards_example::Setup table;
  const double scale = std::sqrt(static_cast<double>(balls) / 16);
  table.width *= scale;
  table.height *= scale;
  billiards_example::Simulation simulation(billiards_example::random_setup(table, balls, 1), false);
  for (int i = 0; i < 1000; ++i) simulation.step();  // past the start, where every ball is predicted afresh
  for (auto _ : state) {
    const billiards_example::Event event = simulation.step();
    benchmark::DoNotOptimize(event);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["balls"] = static_cast<double>(balls);
}

}  // namespace

BENCHMARK(table_events)->Name("table/events")->RangeMultiplier(4)->Range(16, 1024)->UseRealTime();
