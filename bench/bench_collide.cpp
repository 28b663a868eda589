// Figures, not pass/fail: one collision per call for the generated code beside hand-written
// formulas (the paper's, an engine's with stored inverse masses) and a plain Eigen expression, over the
// same 4096 random cases; the restitution, direction, friction and time-of-impact calls beside their
// plain forms; and the batch path against a bandwidth ceiling with its own access pattern and against its
// division limit. Every benchmark is timed in real (wall-clock) time. Report ratios from one run (the
// machines are shared).
//
// BILLIARDS_BENCH_MAX_PAIRS (environment) caps the batch sizes: 10^7 by default, small for CI's
// smoke run.
#include <billiards/batch.hpp>
#include <billiards/cloth.hpp>
#include <billiards/collision.hpp>
#include <billiards/detail/arithmetic.hpp>
#include <billiards/kernels.hpp>
#include <billiards/reference_kernels.hpp>
#include <billiards/spin.hpp>

#include <billiards/simulation/core/prefetch.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

// Before a loop over the batch's arrays: they do not overlap, as collide_batch tells the compilers
// (otherwise neither vectorises a loop over this many arrays).
#if defined(__clang__)
// clang warns where it cannot honour the request (under the sanitizers it never can); the figures of
// an unvectorised build are slower, not wrong, so that warning must not fail the -Werror build.
#pragma clang diagnostic ignored "-Wpass-failed"
#define BILLIARDS_BENCH_ARRAYS_DO_NOT_OVERLAP _Pragma("clang loop vectorize(assume_safety)")
#elif defined(__GNUC__)
#define BILLIARDS_BENCH_ARRAYS_DO_NOT_OVERLAP _Pragma("GCC ivdep")
#else
#define BILLIARDS_BENCH_ARRAYS_DO_NOT_OVERLAP
#endif

namespace {

constexpr std::size_t cases = 4096;

template <typename Scalar>
struct Case {
  Scalar m1, m2;
  Scalar inverse_m1, inverse_m2;  ///< what an engine stores beside (or instead of) the masses
  Scalar restitution, friction;
  Eigen::Matrix<Scalar, 3, 1> v1, v2, n, d;  ///< d: a direction of any length
  Eigen::Matrix<Scalar, 3, 1> w1, w2;        ///< spins, rad/s
  Scalar r1, r2;                             ///< radii
};

template <typename Scalar>
const std::vector<Case<Scalar>>& random_cases() {
  static const std::vector<Case<Scalar>> all = [] {
    std::mt19937_64 random(2023);
    std::uniform_real_distribution<double> component(-10, 10), decade(-3, 3), unit(0, 1);
    std::vector<Case<Scalar>> made(cases);
    const auto vector = [&]() -> Eigen::Matrix<Scalar, 3, 1> {
      return Eigen::Vector3d(component(random), component(random), component(random)).cast<Scalar>();
    };
    for (Case<Scalar>& c : made) {
      c.m1 = static_cast<Scalar>(std::pow(10.0, decade(random)));
      c.m2 = static_cast<Scalar>(std::pow(10.0, decade(random)));
      c.inverse_m1 = Scalar(1) / c.m1;
      c.inverse_m2 = Scalar(1) / c.m2;
      c.restitution = static_cast<Scalar>(unit(random));
      c.friction = static_cast<Scalar>(0.1 * unit(random));
      c.v1 = vector();
      c.v2 = vector();
      c.n = vector().normalized();
      c.d = vector();
      c.w1 = Scalar(10) * vector();
      c.w2 = Scalar(10) * vector();
      c.r1 = static_cast<Scalar>(0.02 + 0.02 * unit(random));
      c.r2 = static_cast<Scalar>(0.02 + 0.02 * unit(random));
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

// An engine's form: inverse masses stored, x1 = v1 + w1 J n, x2 = v2 − w2 J n with J = 2 s/(w1 + w2).
template <typename Scalar>
billiards::Collision<Eigen::Matrix<Scalar, 3, 1>> engine_formula(const Case<Scalar>& c) {
  const Scalar impulse = Scalar(2) * (c.v2 - c.v1).dot(c.n) / (c.inverse_m1 + c.inverse_m2);
  return {c.v1 + (c.inverse_m1 * impulse) * c.n, c.v2 - (c.inverse_m2 * impulse) * c.n};
}

// Restitution, by hand: (1 + e) m2/(m1 + m2) in place of 2 m2/(m1 + m2).
template <typename Scalar>
billiards::Collision<Eigen::Matrix<Scalar, 3, 1>> paper_formula_with_restitution(const Case<Scalar>& c) {
  const Scalar relative = (c.v2 - c.v1).dot(c.n), factor = (Scalar(1) + c.restitution) / (c.m1 + c.m2);
  return {c.v1 + (factor * c.m2 * relative) * c.n, c.v2 - (factor * c.m1 * relative) * c.n};
}

// Along a direction d of any length, by hand: s = (v2 − v1)·d/(d·d).
template <typename Scalar>
billiards::Collision<Eigen::Matrix<Scalar, 3, 1>> paper_formula_along_direction(const Case<Scalar>& c) {
  const Scalar relative = (c.v2 - c.v1).dot(c.d) / c.d.squaredNorm();
  const Scalar factor = (Scalar(1) + c.restitution) / (c.m1 + c.m2);
  return {c.v1 + (factor * c.m2 * relative) * c.d, c.v2 - (factor * c.m1 * relative) * c.d};
}

// The library's calls with their promises taken away, built from the same pieces (the generated
// kernels, detail::difference_dot, detail::dot and detail::plus_multiple), so that bench/report.py can
// say what the promises cost a call where a goal is not met. None of these is offered to users:
// - Dropped::direction_scaling: collide_along_direction without scaling d (detail::collide_along): the
//   kernel on d as given, mass-range test and −0 kept; it loses a heavy ball's subnormal change by up
//   to |d|, and the same bits for every 2^k d;
// - Dropped::every_promise: also the plain kernel straight away, without the mass-range test (wrong,
//   even ∞ or NaN, for masses outside [plain_mass_low, plain_mass_high]), and the update as v + c n,
//   one multiply-add, which turns an unchanged −0 into +0. (The range test alone, −0 kept, measured
//   slower than the library's call: GCC's code for the plain kernel without the branch before it.)
enum class Dropped { direction_scaling, every_promise };

template <typename Scalar, Dropped dropped>
[[gnu::always_inline]] inline billiards::Collision<Eigen::Matrix<Scalar, 3, 1>> restitution_without(
    const Case<Scalar>& c) {
  static_assert(dropped == Dropped::every_promise, "a restitution call has no direction to scale");
  const auto change = billiards::kernels::plain_normal_velocity_change(
      c.m1, c.m2, Scalar(0), billiards::detail::difference_dot(c.v1, c.v2, c.n), c.restitution);
  return {c.v1 + change.first * c.n, c.v2 + change.second * c.n};
}

template <typename Scalar, Dropped dropped>
[[gnu::always_inline]] inline billiards::Collision<Eigen::Matrix<Scalar, 3, 1>> direction_without(
    const Case<Scalar>& c) {
  namespace kernels = billiards::kernels;
  namespace detail = billiards::detail;
  const Scalar relative = detail::difference_dot(c.v1, c.v2, c.d), dd = detail::dot(c.d, c.d);
  if constexpr (dropped == Dropped::direction_scaling) {
    const auto change =
        kernels::direction_velocity_change(c.m1, c.m2, Scalar(0), relative, dd, c.restitution);
    return {detail::plus_multiple(c.v1, change.first, c.d), detail::plus_multiple(c.v2, change.second, c.d)};
  } else {
    const auto change =
        kernels::plain_direction_velocity_change(c.m1, c.m2, Scalar(0), relative, dd, c.restitution);
    return {c.v1 + change.first * c.d, c.v2 + change.second * c.d};
  }
}

template <typename Scalar>
using Spinning = billiards::Collision<billiards::SpinningBall<Scalar>>;

// Friction, by hand as it is usually written: J_n = (1 + e) m1 m2/(m1 + m2) |s|, k = (7/2)(1/m1 + 1/m2),
// j = min(μ J_n, |u_t|/k), J = J_n n − j û_t on ball 2, Δω = (5 j/(2 m R)) (n × û_t).
template <typename Scalar>
Spinning<Scalar> friction_formula(const Case<Scalar>& c) {
  using V = Eigen::Matrix<Scalar, 3, 1>;
  Spinning<Scalar> out{{c.v1, c.w1, c.m1, c.r1}, {c.v2, c.w2, c.m2, c.r2}};
  const Scalar s = (c.v2 - c.v1).dot(c.n);
  if (!(s < 0)) return out;
  const Scalar normal = -(Scalar(1) + c.restitution) * c.m1 * c.m2 / (c.m1 + c.m2) * s;
  const V u = (c.v2 + c.w2.cross(-c.r2 * c.n)) - (c.v1 + c.w1.cross(c.r1 * c.n));
  const V ut = u - u.dot(c.n) * c.n;
  const Scalar slip = ut.norm();
  const Scalar k = Scalar(3.5) * (Scalar(1) / c.m1 + Scalar(1) / c.m2);
  const Scalar j = std::min(c.friction * normal, slip / k);
  const V direction = ut / slip, J = normal * c.n - j * direction, axis = c.n.cross(direction);
  out.first.velocity -= J / c.m1;
  out.second.velocity += J / c.m2;
  out.first.angular_velocity += (Scalar(2.5) * j / (c.m1 * c.r1)) * axis;
  out.second.angular_velocity += (Scalar(2.5) * j / (c.m2 * c.r2)) * axis;
  return out;
}

// One call per iteration, cycling through `all` (4096 cases). The index wraps by a comparison: an earlier
// `(i + 1) % all.size()` put a 64-bit division on the loop's dependency chain, which held every call at
// about 3.2 ns on the recorded machine (the paper's formula and the engine's form alike, where without
// it they take 2.7 and 2.4 ns), so the ratios to it understated what the generated calls cost.
template <typename Case, typename Call>
void one_call_per_case(benchmark::State& state, const std::vector<Case>& all, Call call) {
  std::size_t i = 0;
  for (auto _ : state) {
    auto result = call(all[i]);
    benchmark::DoNotOptimize(result);
    if (++i == all.size()) i = 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

// A hand-written form as a call of its own type: passed as a plain function pointer, every form of one
// signature shared one instantiation of the loop, which called it indirectly (never inlined), while the
// library's calls were inlined into theirs. Each form now gets its own loop, as each library call does.
template <auto Form>
constexpr auto by_hand = [](const auto& c) { return Form(c); };

template <typename Scalar, typename Collide>
void one_collision_per_call(benchmark::State& state, Collide collide) {
  one_call_per_case(state, random_cases<Scalar>(), collide);
}

template <typename Scalar>
void generated_collide(benchmark::State& state) {
  one_collision_per_call<Scalar>(
      state, [](const Case<Scalar>& c) { return billiards::collide(c.m1, c.v1, c.m2, c.v2, c.n); });
}
template <typename Scalar>
void hand_written_paper_formula(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, by_hand<paper_formula<Scalar>>);
}
template <typename Scalar>
void hand_written_ratio_formula(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, by_hand<ratio_formula<Scalar>>);
}
template <typename Scalar>
void hand_written_ratio_formula_without_select(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, by_hand<ratio_formula_without_select<Scalar>>);
}
template <typename Scalar>
void engine_form(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, by_hand<engine_formula<Scalar>>);
}
template <typename Scalar>
void generated_restitution(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, [](const Case<Scalar>& c) {
    return billiards::collide(c.m1, c.v1, c.m2, c.v2, c.n, c.restitution);
  });
}
template <typename Scalar>
void hand_written_restitution(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, by_hand<paper_formula_with_restitution<Scalar>>);
}
template <typename Scalar>
void generated_direction(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, [](const Case<Scalar>& c) {
    return billiards::collide_along_direction(c.m1, c.v1, c.m2, c.v2, c.d, c.restitution);
  });
}
template <typename Scalar>
void hand_written_direction(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, by_hand<paper_formula_along_direction<Scalar>>);
}
template <typename Scalar, Dropped dropped>
void restitution_dropping(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, by_hand<restitution_without<Scalar, dropped>>);
}
template <typename Scalar, Dropped dropped>
void direction_dropping(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, by_hand<direction_without<Scalar, dropped>>);
}
template <typename Scalar>
void generated_friction(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, [](const Case<Scalar>& c) {
    return billiards::collide_with_friction(billiards::SpinningBall<Scalar>{c.v1, c.w1, c.m1, c.r1},
                                            billiards::SpinningBall<Scalar>{c.v2, c.w2, c.m2, c.r2}, c.n,
                                            c.restitution, c.friction);
  });
}
template <typename Scalar>
void hand_written_friction(benchmark::State& state) {
  one_collision_per_call<Scalar>(state, by_hand<friction_formula<Scalar>>);
}
// When two spheres touch: centres p1 and p2 a gap of 0 to 9 apart beyond the contact distance 1, along
// a random direction, with the collide cases' velocities (about half the pairs approach, and some of
// those miss), as an event-driven simulation predicts its neighbours.
template <typename Scalar>
struct Impact {
  Eigen::Matrix<Scalar, 3, 1> p1, v1, p2, v2;
};

template <typename Scalar>
const std::vector<Impact<Scalar>>& impact_cases() {
  static const std::vector<Impact<Scalar>> all = [] {
    std::mt19937_64 random(2024);
    std::uniform_real_distribution<double> coordinate(-5, 5), gap(0, 9);
    std::normal_distribution<double> gaussian;
    const std::vector<Case<Scalar>>& collisions = random_cases<Scalar>();
    std::vector<Impact<Scalar>> made(collisions.size());
    for (std::size_t i = 0; i < made.size(); ++i) {
      const Eigen::Vector3d p1(coordinate(random), coordinate(random), coordinate(random));
      const Eigen::Vector3d direction =
          Eigen::Vector3d(gaussian(random), gaussian(random), gaussian(random)).normalized();
      made[i] = {p1.cast<Scalar>(), collisions[i].v1, (p1 + (1 + gap(random)) * direction).cast<Scalar>(),
                 collisions[i].v2};
    }
    return made;
  }();
  return all;
}

template <typename Scalar>
void generated_time_of_impact(benchmark::State& state) {
  one_call_per_case(state, impact_cases<Scalar>(), [](const Impact<Scalar>& c) {
    return billiards::time_of_impact(c.p1, c.v1, c.p2, c.v2, Scalar(1));
  });
}
// By hand: a = w·w, b = p·w, c = p·p − r², the earlier root (−b − √(b² − a c))/a; +∞ when they
// separate or miss, 0 when they already touch.
template <typename Scalar>
void hand_written_time_of_impact(benchmark::State& state) {
  one_call_per_case(state, impact_cases<Scalar>(), [](const Impact<Scalar>& c) {
    const Eigen::Matrix<Scalar, 3, 1> p = c.p2 - c.p1, w = c.v2 - c.v1;
    const Scalar b = p.dot(w), a = w.dot(w), gap = p.dot(p) - Scalar(1);
    const Scalar discriminant = b * b - a * gap;
    if (b >= 0 || discriminant <= 0) return std::numeric_limits<Scalar>::infinity();
    if (gap < 0) return Scalar(0);
    return (-b - std::sqrt(discriminant)) / a;
  });
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

// The arrays of a batch of `count` pairs, structure of arrays: masses, and v1, v2, n by component.
template <typename Scalar>
struct BatchArrays {
  std::vector<Scalar> m1, m2;
  std::array<std::vector<Scalar>, 3> v1, v2, n;
  explicit BatchArrays(std::size_t count) : m1(count, Scalar(1)), m2(count, Scalar(2)) {
    for (std::size_t k = 0; k < 3; ++k) {
      v1[k].assign(count, Scalar(k + 1));
      v2[k].assign(count, -Scalar(k + 1));
      n[k].assign(count, k == 0 ? Scalar(1) : Scalar(0));
    }
  }
};

template <typename Scalar>
void batch(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  BatchArrays<Scalar> arrays(count);
  auto& [m1, m2, v1, v2, n] = arrays;
  billiards::Components<Scalar, 3> x1{v1[0], v1[1], v1[2]}, x2{v2[0], v2[1], v2[2]};
  const billiards::Components<const Scalar, 3> normal{n[0], n[1], n[2]};
  for (auto _ : state) {
    billiards::collide_batch<Scalar, 3>(m1, x1, m2, x2, normal);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * count));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * count) * bytes_per_pair<Scalar>);
}

// A ball sliding on the cloth, advanced by half its slide time: billiards::evolve beside the sliding
// phase's closed form typed by hand (v0 − μ_s g t û, ω_h + (5 μ_s g t/(2R)) ẑ × û, p0 + v0 t − ½ μ_s g t² û,
// the spin about ẑ decaying at 5 μ_sp g/(2R)).
template <typename Scalar>
struct SlidingCase {
  billiards::BallOnCloth<Scalar> ball;
  Scalar t;
};

template <typename Scalar>
const billiards::Cloth<Scalar>& bench_cloth() {
  static const billiards::Cloth<Scalar> cloth{Scalar(0.2), Scalar(0.01), Scalar(0.044)};
  return cloth;
}

template <typename Scalar>
const std::vector<SlidingCase<Scalar>>& sliding_cases() {
  static const std::vector<SlidingCase<Scalar>> all = [] {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> speed(-3, 3), spin(-100, 100);
    std::vector<SlidingCase<Scalar>> made;
    const Scalar radius = Scalar(0.028575);
    while (made.size() < cases) {
      using V = Eigen::Matrix<Scalar, 3, 1>;
      const billiards::BallOnCloth<Scalar> ball{
          V(0, 0, radius), V(Scalar(speed(random)), Scalar(speed(random)), 0),
          V(Scalar(spin(random)), Scalar(spin(random)), Scalar(spin(random))), radius};
      if (billiards::motion(ball, bench_cloth<Scalar>()) != billiards::Motion::sliding) continue;
      made.push_back({ball, billiards::transition_time(ball, bench_cloth<Scalar>()) / 2});
    }
    return made;
  }();
  return all;
}

template <typename Scalar>
billiards::BallOnCloth<Scalar> sliding_formula(const SlidingCase<Scalar>& c) {
  using V = Eigen::Matrix<Scalar, 3, 1>;
  const billiards::Cloth<Scalar>& cloth = bench_cloth<Scalar>();
  billiards::BallOnCloth<Scalar> later = c.ball;
  const V u = c.ball.velocity + c.ball.angular_velocity.cross(V(0, 0, -c.ball.radius));
  const V direction = V(u.x(), u.y(), 0).normalized();
  const Scalar change = cloth.sliding_friction * cloth.gravity * c.t;
  later.velocity = c.ball.velocity - change * direction;
  later.position = c.ball.position + c.ball.velocity * c.t - (change * c.t / 2) * direction;
  later.angular_velocity += (Scalar(2.5) * change / c.ball.radius) * V(0, 0, 1).cross(direction);
  const Scalar decay = Scalar(2.5) * cloth.spinning_friction * cloth.gravity * c.t / c.ball.radius;
  later.angular_velocity.z() = std::copysign(
      std::max(std::fabs(c.ball.angular_velocity.z()) - decay, Scalar(0)), c.ball.angular_velocity.z());
  return later;
}

template <typename Scalar, typename Advance>
void one_slide_per_call(benchmark::State& state, Advance advance) {
  one_call_per_case(state, sliding_cases<Scalar>(), advance);
}
template <typename Scalar>
void generated_evolve(benchmark::State& state) {
  one_slide_per_call<Scalar>(state, [](const SlidingCase<Scalar>& c) {
    return billiards::evolve(c.ball, bench_cloth<Scalar>(), c.t);
  });
}
template <typename Scalar>
void hand_written_evolve(benchmark::State& state) {
  one_slide_per_call<Scalar>(state, by_hand<sliding_formula<Scalar>>);
}

// One pair's velocities and normal, each component read once into a local before anything is written:
// the compilers do not take __restrict on an array of pointers as a promise that a store through one
// pointer leaves another's element unchanged, so a loop that reads x[k][i] after writing y[k][i]
// reloads it (collide_batch read its normals two and three times a pair that way, which cost it a third
// of its speed in cache). collide_batch reads them this way; the loops it is measured against do too.
template <typename Scalar>
struct PairLoad {
  Scalar x[3], y[3], d[3];
  template <typename Velocities, typename Normals>
  PairLoad(const Velocities& v1, const Velocities& v2, const Normals& n, std::size_t i) {
    for (int k = 0; k < 3; ++k) {
      x[k] = v1[k][i];
      y[k] = v2[k][i];
      d[k] = n[k][i];
    }
  }
};

// The paper's plain formula over the same arrays, the loop a user would write instead of collide_batch
// (PlainStep::paper): x1 = v1 + (2 m2/(m1 + m2)) s n, x2 = v2 − (2 m1/(m1 + m2)) s n, one division by
// m1 + m2 and a multiply-add a component. The later steps turn it into collide_batch's pass one promise
// at a time, so that bench/report.py can say what each costs in cache:
// - keeping_zero_signs: the update v − (0 − c n) of detail::plus_multiple, which leaves v's bits alone
//   where c n is 0 (−0 stays −0: "unchanged" means bit for bit) — two operations a component for one;
// - generated_form: also the coefficients of kernels::plain_elastic_normal_velocity_change, 2 m2/(m1 + m2)
//   and 2 m1/(m1 + m2), two divisions by the one sum, which give equal masses their exact exchange
//   (2 m/(2 m) = 1) — collide_batch's pass over a block, without the mass-range test before it.
enum class PlainStep { paper, keeping_zero_signs, generated_form };

template <typename Scalar, PlainStep step>
void plain_batch(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  BatchArrays<Scalar> arrays(count);
  auto& [m1, m2, v1, v2, n] = arrays;
  Scalar* __restrict x[3] = {v1[0].data(), v1[1].data(), v1[2].data()};
  Scalar* __restrict y[3] = {v2[0].data(), v2[1].data(), v2[2].data()};
  const Scalar* __restrict d[3] = {n[0].data(), n[1].data(), n[2].data()};
  const Scalar* __restrict a = m1.data();
  const Scalar* __restrict b = m2.data();
  for (auto _ : state) {
    // Told, as collide_batch tells them, that the arrays do not overlap: otherwise neither compiler
    // vectorises a loop over this many arrays.
    BILLIARDS_BENCH_ARRAYS_DO_NOT_OVERLAP
    for (std::size_t i = 0; i < count; ++i) {
      // Each component read once into a local, as collide_batch reads them (see PairLoad).
      const PairLoad<Scalar> pair(x, y, d, i);
      const Scalar s = (pair.y[0] - pair.x[0]) * pair.d[0] + (pair.y[1] - pair.x[1]) * pair.d[1] +
                       (pair.y[2] - pair.x[2]) * pair.d[2];
      if constexpr (step == PlainStep::paper) {
        const Scalar per_mass = Scalar(2) * s / (a[i] + b[i]);
        const Scalar first = per_mass * b[i], second = per_mass * a[i];
        for (int k = 0; k < 3; ++k) {
          x[k][i] = pair.x[k] + first * pair.d[k];
          y[k][i] = pair.y[k] - second * pair.d[k];
        }
      } else {
        Scalar first, second;
        if constexpr (step == PlainStep::keeping_zero_signs) {
          const Scalar per_mass = Scalar(2) * s / (a[i] + b[i]);
          first = per_mass * b[i];
          second = -(per_mass * a[i]);
        } else {
          const auto change =
              billiards::kernels::plain_elastic_normal_velocity_change(a[i], b[i], Scalar(0), s);
          first = change.first;
          second = change.second;
        }
        for (int k = 0; k < 3; ++k) {
          x[k][i] = billiards::detail::plus_multiple(pair.x[k], first, pair.d[k]);
          y[k][i] = billiards::detail::plus_multiple(pair.y[k], second, pair.d[k]);
        }
      }
    }
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

// The bandwidth ceiling: the batch's own access pattern — read m1, m2 and the three components of v1,
// v2 and n, each component once a pair, write v1 and v2 in place — with trivial arithmetic (a
// multiply-add per component), in two forms: one pass left to the hardware prefetcher, and blocks of
// 1024 pairs, each asking memory for the next block's arrays first (a software prefetch, which can beat
// the hardware prefetcher alone). bench/report.py takes the fastest of them and the plain formula's
// loop as the ceiling. memcpy is no ceiling: below glibc's non-temporal threshold it uses cached
// stores, and the batch once showed twice its bandwidth at 10^6 pairs.
constexpr std::size_t prefetch_block = 1024;

// Asks memory for the cache lines of pairs [begin, end) of each of `arrays`.
template <typename Pointer, std::size_t count>
void prefetch_pairs(const Pointer (&arrays)[count], std::size_t begin, std::size_t end) {
  constexpr std::size_t per_line = 64 / sizeof(*arrays[0]);
  for (std::size_t i = begin; i < end; i += per_line) {
    for (const Pointer array : arrays) billiards::simulation::detail::prefetch(array + i);
  }
}

template <typename Scalar, bool prefetched>
void bandwidth_ceiling(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  BatchArrays<Scalar> arrays(count);
  auto& [m1, m2, v1, v2, n] = arrays;
  Scalar* __restrict x[3] = {v1[0].data(), v1[1].data(), v1[2].data()};
  Scalar* __restrict y[3] = {v2[0].data(), v2[1].data(), v2[2].data()};
  const Scalar* __restrict d[3] = {n[0].data(), n[1].data(), n[2].data()};
  const Scalar* __restrict a = m1.data();
  const Scalar* __restrict b = m2.data();
  const Scalar* const masses[2] = {a, b};
  const std::size_t block = prefetched ? prefetch_block : count;
  for (auto _ : state) {
    // Each array read once and v1, v2 written once, as collide_batch makes.
    for (std::size_t begin = 0; begin < count; begin += block) {
      const std::size_t end = std::min(count, begin + block);
      if (prefetched) {
        const std::size_t next_end = std::min(count, end + block);
        prefetch_pairs(masses, end, next_end);
        prefetch_pairs(d, end, next_end);
        prefetch_pairs(x, end, next_end);
        prefetch_pairs(y, end, next_end);
      }
      BILLIARDS_BENCH_ARRAYS_DO_NOT_OVERLAP
      for (std::size_t i = begin; i < end; ++i) {
        const PairLoad<Scalar> pair(x, y, d, i);
        for (int k = 0; k < 3; ++k) {
          x[k][i] = pair.x[k] + a[i] * pair.d[k];
          y[k][i] = pair.y[k] - b[i] * pair.d[k];
        }
      }
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * count));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * count) * bytes_per_pair<Scalar>);
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
      {"engine_formula", engine_form<Scalar>},
      {"restitution", generated_restitution<Scalar>},
      {"restitution_formula", hand_written_restitution<Scalar>},
      {"direction", generated_direction<Scalar>},
      {"direction_formula", hand_written_direction<Scalar>},
      {"restitution_without_promises", restitution_dropping<Scalar, Dropped::every_promise>},
      {"direction_unscaled", direction_dropping<Scalar, Dropped::direction_scaling>},
      {"direction_without_promises", direction_dropping<Scalar, Dropped::every_promise>},
      {"friction", generated_friction<Scalar>},
      {"friction_formula", hand_written_friction<Scalar>},
      {"evolve", generated_evolve<Scalar>},
      {"evolve_formula", hand_written_evolve<Scalar>},
      {"time_of_impact", generated_time_of_impact<Scalar>},
      {"time_of_impact_formula", hand_written_time_of_impact<Scalar>},
  };
  for (const auto& [variant, function] : one_call) {
    benchmark::RegisterBenchmark(("collide/" + std::string(variant) + "/" + type).c_str(), function)
        ->UseRealTime();
  }
  const std::pair<const char*, Function> per_pair[] = {
      {"batch", batch<Scalar>},
      {"plain_batch", plain_batch<Scalar, PlainStep::paper>},
      {"bandwidth", bandwidth_ceiling<Scalar, false>},
      {"bandwidth_prefetched", bandwidth_ceiling<Scalar, true>},
      {"divisions", division_limit<Scalar>}};
  // The steps from the plain formula's loop to collide_batch (PlainStep), where the goal is against
  // that loop: in cache, up to 10^4 pairs.
  const std::pair<const char*, Function> in_cache[] = {
      {"plain_batch_keeping_zero_signs", plain_batch<Scalar, PlainStep::keeping_zero_signs>},
      {"plain_batch_generated_form", plain_batch<Scalar, PlainStep::generated_form>}};
  for (std::int64_t pairs = 100; pairs <= max_pairs(); pairs *= 10) {
    for (const auto& [group, function] : per_pair) {
      benchmark::RegisterBenchmark((std::string(group) + "/" + type).c_str(), function)
          ->Arg(pairs)
          ->UseRealTime();
    }
    for (const auto& [group, function] : in_cache) {
      if (pairs > 10'000) break;
      benchmark::RegisterBenchmark((std::string(group) + "/" + type).c_str(), function)
          ->Arg(pairs)
          ->UseRealTime();
    }
  }
}

void register_all() {
  register_type<double>("double");
  register_type<float>("float");
}

}  // namespace

// The CPU model as the system names it ("model name" in /proc/cpuinfo), for the report's machine line:
// these machines vary (Intel and AMD), so it is read, never written down.
std::string cpu_model() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      return line.substr(line.find(':') + 2);
    }
  }
  return "unknown (no model name in /proc/cpuinfo)";
}

int main(int argc, char** argv) {
  register_all();
  benchmark::AddCustomContext("cpu_model", cpu_model());
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
