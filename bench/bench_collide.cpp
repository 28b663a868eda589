// Figures, not pass/fail: one collision per call for the generated code beside hand-written
// formulas and a plain Eigen expression, over the same 4096 random cases; and the batch path
// against memcpy of the same number of bytes. Report ratios from one run (the machines are shared).
//
// BILLIARDS_BENCH_MAX_PAIRS (environment) caps the batch sizes: 10^7 by default, small for CI's
// smoke run.
#include <billiards/batch.hpp>
#include <billiards/collision.hpp>
#include <billiards/reference_kernels.hpp>

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr std::size_t cases = 4096;

template <typename Scalar>
struct Case {
  Scalar m1, m2;
  Eigen::Matrix<Scalar, 3, 1> v1, v2, n;
};

template <typename Scalar>
const std::vector<Case<Scalar>>& random_cases() {
  static const std::vector<Case<Scalar>> all = [] {
    std::mt19937_64 random(2023);
    std::uniform_real_distribution<double> component(-10, 10), decade(-3, 3);
    std::vector<Case<Scalar>> made(cases);
    for (Case<Scalar>& c : made) {
      c.m1 = static_cast<Scalar>(std::pow(10.0, decade(random)));
      c.m2 = static_cast<Scalar>(std::pow(10.0, decade(random)));
      c.v1 = Eigen::Vector3d(component(random), component(random), component(random)).cast<Scalar>();
      c.v2 = Eigen::Vector3d(component(random), component(random), component(random)).cast<Scalar>();
      c.n = Eigen::Vector3d(component(random), component(random), component(random))
                .normalized()
                .cast<Scalar>();
    }
    return made;
  }();
  return all;
}

// The paper's formula as printed, x1 = v1 + (2 m2/(m1 + m2)) ((v2 − v1)·n) n, typed by hand.
template <typename Scalar>
billiards::Collision<Eigen::Matrix<Scalar, 3, 1>> paper_formula(const Case<Scalar>& c) {
  const Scalar relative = (c.v2 - c.v1).dot(c.n);
  return {c.v1 + (Scalar(2) * c.m2 / (c.m1 + c.m2)) * relative * c.n,
          c.v2 - (Scalar(2) * c.m1 / (c.m1 + c.m2)) * relative * c.n};
}

// The overflow-safe form the generator emits, typed by hand: 2/(1 + m1/m2), and where that coefficient
// falls below the smallest normal number the small-mass form m2 (2 s/(m1 + m2)), chosen factor by
// factor as the generator does.
template <typename Scalar>
billiards::Collision<Eigen::Matrix<Scalar, 3, 1>> ratio_formula(const Case<Scalar>& c) {
  const Scalar relative = c.v2.dot(c.n) - c.v1.dot(c.n);
  const Scalar c1 = Scalar(2) / (Scalar(1) + c.m1 / c.m2), c2 = Scalar(2) / (Scalar(1) + c.m2 / c.m1);
  const Scalar per_mass = Scalar(2) * relative / (c.m1 + c.m2);
  const Scalar tiny = std::numeric_limits<Scalar>::min();
  const Scalar first = (c1 < tiny ? per_mass : c1) * (c1 < tiny ? c.m2 : relative);
  const Scalar second = (c2 < tiny ? per_mass : c2) * (c2 < tiny ? c.m1 : relative);
  return {c.v1 + first * c.n, c.v2 - second * c.n};
}

// The same ratio form without the small-mass select: what that select costs.
template <typename Scalar>
billiards::Collision<Eigen::Matrix<Scalar, 3, 1>> ratio_formula_without_select(const Case<Scalar>& c) {
  const Scalar relative = c.v2.dot(c.n) - c.v1.dot(c.n);
  return {c.v1 + (Scalar(2) / (Scalar(1) + c.m1 / c.m2)) * relative * c.n,
          c.v2 - (Scalar(2) / (Scalar(1) + c.m2 / c.m1)) * relative * c.n};
}

template <typename Scalar, typename Collide>
void one_collision_per_call(benchmark::State& state, Collide collide) {
  const auto& all = random_cases<Scalar>();
  std::size_t i = 0;
  for (auto _ : state) {
    auto result = collide(all[i]);
    benchmark::DoNotOptimize(result);
    i = (i + 1) % cases;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

template <typename Scalar>
void generated_collide(benchmark::State& state) {
  one_collision_per_call<Scalar>(
      state, [](const Case<Scalar>& c) { return billiards::collide(c.m1, c.v1, c.m2, c.v2, c.n); });
}
template <typename Scalar>
void hand_written_paper_formula(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, paper_formula<Scalar>);
}
template <typename Scalar>
void hand_written_ratio_formula(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, ratio_formula<Scalar>);
}
template <typename Scalar>
void hand_written_ratio_formula_without_select(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, ratio_formula_without_select<Scalar>);
}
// The raw derivation before simplification (quadratic formula with √D), emitted by derive as a
// reference kernel, in the same wrapper as collide().
template <typename Scalar>
void raw_derivation(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, [](const Case<Scalar>& c) {
    const auto change =
        billiards::reference_kernels::raw_normal_velocity_change(c.m1, c.m2, c.v1.dot(c.n), c.v2.dot(c.n));
    return billiards::Collision<Eigen::Matrix<Scalar, 3, 1>>{c.v1 + change.first * c.n,
                                                             c.v2 + change.second * c.n};
  });
}
template <typename Scalar>
void plain_eigen_expression(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, [](const Case<Scalar>& c) {
    const Eigen::Matrix<Scalar, 3, 1> impulse = (c.v2 - c.v1).dot(c.n) * c.n;
    return billiards::Collision<Eigen::Matrix<Scalar, 3, 1>>{c.v1 + (2 * c.m2 / (c.m1 + c.m2)) * impulse,
                                                             c.v2 - (2 * c.m1 / (c.m1 + c.m2)) * impulse};
  });
}

// Bytes the batch path moves per pair in 3-D: reads m1, m2, v1, v2, n (11 scalars), writes v1, v2 (6).
template <typename Scalar>
constexpr std::int64_t bytes_per_pair = 17 * sizeof(Scalar);

template <typename Scalar>
void batch(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  std::vector<Scalar> m1(count, Scalar(1)), m2(count, Scalar(2));
  std::array<std::vector<Scalar>, 3> v1, v2, n;
  for (std::size_t k = 0; k < 3; ++k) {
    v1[k].assign(count, Scalar(k + 1));
    v2[k].assign(count, -Scalar(k + 1));
    n[k].assign(count, k == 0 ? Scalar(1) : Scalar(0));
  }
  billiards::Components<Scalar, 3> x1{v1[0], v1[1], v1[2]}, x2{v2[0], v2[1], v2[2]};
  const billiards::Components<const Scalar, 3> normal{n[0], n[1], n[2]};
  for (auto _ : state) {
    billiards::collide_batch<Scalar, 3>(m1, x1, m2, x2, normal);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * count));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * count) * bytes_per_pair<Scalar>);
}

// The arithmetic limit of the batch path: its five divisions per pair (m1/m2, m2/m1, 2/(1 + ρ1),
// 2/(1 + ρ2) and 2 s/(m1 + m2)) are the slowest operations of the kernel by far, so the throughput of
// five independent vectorised divisions per pair over the same arrays bounds it from below.
template <typename Scalar>
void division_limit(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  std::vector<Scalar> a(count, Scalar(1.5)), b(count, Scalar(2.5)), out(count, Scalar(0));
  Scalar* __restrict result = out.data();
  const Scalar* __restrict x = a.data();
  const Scalar* __restrict y = b.data();
  for (auto _ : state) {
    for (std::size_t i = 0; i < count; ++i) {
      result[i] = x[i] / y[i] + y[i] / x[i] + Scalar(2) / (Scalar(1) + x[i]) +
                  Scalar(2) / (Scalar(1) + y[i]) + result[i] / (x[i] + y[i]);
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * count));
}

// The memory bandwidth reference: memcpy of the same number of bytes.
template <typename Scalar>
void memcpy_reference(benchmark::State& state) {
  const auto bytes = static_cast<std::size_t>(state.range(0) * bytes_per_pair<Scalar> / 2);
  std::vector<char> from(bytes, 1), to(bytes, 0);
  for (auto _ : state) {
    std::memcpy(to.data(), from.data(), bytes);
    benchmark::ClobberMemory();
  }
  // memcpy reads and writes each byte: the same bytes moved as the batch of range(0) pairs.
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(2 * bytes));
}

std::int64_t max_pairs() {
  const char* text = std::getenv("BILLIARDS_BENCH_MAX_PAIRS");
  return text != nullptr ? std::max<std::int64_t>(100, std::atoll(text)) : 10'000'000;
}

// Every benchmark for one scalar type, named "<group>/<variant>/<type>" ("batch/<type>" with N).
template <typename Scalar>
void register_type(const std::string& type) {
  using Function = void (*)(benchmark::State&);
  const std::pair<const char*, Function> one_call[] = {
      {"generated", generated_collide<Scalar>},
      {"paper_formula", hand_written_paper_formula<Scalar>},
      {"ratio_formula", hand_written_ratio_formula<Scalar>},
      {"ratio_formula_without_select", hand_written_ratio_formula_without_select<Scalar>},
      {"raw_derivation", raw_derivation<Scalar>},
      {"eigen_expression", plain_eigen_expression<Scalar>},
  };
  for (const auto& [variant, function] : one_call) {
    benchmark::RegisterBenchmark(("collide/" + std::string(variant) + "/" + type).c_str(), function);
  }
  const std::pair<const char*, Function> per_pair[] = {
      {"batch", batch<Scalar>}, {"memcpy", memcpy_reference<Scalar>}, {"divisions", division_limit<Scalar>}};
  for (std::int64_t pairs = 100; pairs <= max_pairs(); pairs *= 10) {
    for (const auto& [group, function] : per_pair) {
      benchmark::RegisterBenchmark((std::string(group) + "/" + type).c_str(), function)->Arg(pairs);
    }
  }
}

void register_all() {
  register_type<double>("double");
  register_type<float>("float");
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
