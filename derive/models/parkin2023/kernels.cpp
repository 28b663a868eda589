// The kernels the emitter prints, built from the steps' results — never typed a second time — and
// validated against the claim each `equals` before anything is printed. Every collision kernel uses the
// mass-ratio form (beyond.immovable.mass_ratio_form); the paper's elastic one is the same with e = 1.
// Coefficients are emitted as magnitudes with the sign on the product, so swapping the balls swaps the
// results bit for bit, and equal masses give exactly (1 + e)/2.
#include "models/parkin2023/steps.hpp"

#include "core/named_constants.hpp"
#include "print/printer.hpp"

#include <functional>

namespace billiards::derive::parkin2023 {

namespace {

ex magnitude(const ex& coefficient) { return prints_negative(coefficient) ? ex(-coefficient) : coefficient; }

ex with_sign(const ex& coefficient, const ex& product) {
  return prints_negative(coefficient) ? ex(-product) : product;
}

std::vector<KernelStep> steps_then(std::vector<KernelStep> first, const std::vector<KernelStep>& then) {
  first.insert(first.end(), then.begin(), then.end());
  return first;
}

// The names of the collision kernels' steps.
struct ChangeNames {
  GiNaC::symbol first_ratio{"first_mass_ratio"}, second_ratio{"second_mass_ratio"};
  GiNaC::symbol first_coefficient{"first_impulse_coefficient"},
      second_coefficient{"second_impulse_coefficient"};
  GiNaC::symbol first_change{"first_change"}, second_change{"second_change"};
  GiNaC::symbol first_factor{"first_factor"}, second_factor{"second_factor"};
  GiNaC::symbol first_multiplier{"first_multiplier"}, second_multiplier{"second_multiplier"};
  GiNaC::symbol per_mass{"impulse_per_total_mass"};
};

// The two changes for restitution `restitution` (e, or 1) and speed `by`: the ratio form c1 · by, or
// the small-mass form where c1 = (1 + e)/(1 + m1/m2) has dropped below the smallest normal number
// and so lost digits (beyond.immovable.small_mass_form), likewise for ball 2. Each change is a
// product whose two factors are chosen, never computed, under the condition: so no operation
// depends on it, and compilers vectorise a loop of kernels with plain selects (GCC would not
// if-convert a division or product made conditional, short of AVX-512 masks).
std::vector<KernelStep> change_steps(const ChangeNames& names, const MassRatios& ratios,
                                     const ex& restitution, const ex& by) {
  const Symbols& s = symbols();
  const ex e = s.restitution, speed = s.relative_normal_speed;
  const ex first =
      ratios.first_ratio_form.subs(lst{e == restitution, s.first_mass_ratio == names.first_ratio});
  const ex second =
      ratios.second_ratio_form.subs(lst{e == restitution, s.second_mass_ratio == names.second_ratio});
  // In the small-mass form (1 + e) s/(m1 + m2) is computed first and the light mass multiplies it
  // last: the product then rounds once, even into the subnormal range, where m2 (1 + e) s would
  // round at every step; and (1 + e) s/(m1 + m2) cannot overflow there (c1 below the smallest
  // normal means m1/m2 > 2^1022 (double), so m1 + m2 ≥ 2 ε).
  const ex per_mass = (1 + restitution) * by / (s.m1 + s.m2);
  const ex in_per_mass = speed == names.per_mass * (s.m1 + s.m2) / (1 + restitution);
  const ex first_small = magnitude(ratios.first_small_mass_form.subs(e == restitution).subs(in_per_mass));
  const ex second_small = magnitude(ratios.second_small_mass_form.subs(e == restitution).subs(in_per_mass));
  const auto tiny = [](const GiNaC::symbol& coefficient, const ex& alternative) {
    return Guard{coefficient < smallest_normal(), alternative, Guard::Kind::same_value,
                 "beyond.immovable.small_mass_form"};
  };
  return {{names.first_ratio, s.m1 / s.m2},
          {names.second_ratio, s.m2 / s.m1},
          {names.first_coefficient, magnitude(first)},
          {names.second_coefficient, magnitude(second)},
          {names.per_mass, per_mass},
          // The small-mass form's factors, read off the derived form: per_mass times the light mass.
          {names.first_factor, names.first_coefficient, {tiny(names.first_coefficient, names.per_mass)}},
          {names.first_multiplier,
           by,
           {tiny(names.first_coefficient, GiNaC::normal(first_small / names.per_mass))}},
          {names.first_change, names.first_factor * names.first_multiplier},
          {names.second_factor, names.second_coefficient, {tiny(names.second_coefficient, names.per_mass)}},
          {names.second_multiplier,
           by,
           {tiny(names.second_coefficient, GiNaC::normal(second_small / names.per_mass))}},
          {names.second_change, names.second_factor * names.second_multiplier}};
}

// `full` preceded by its one-division form for masses in the plain range: the same speed steps (the
// first `speed_steps` of `full`), then (1 + e) m2/(m1 + m2) and (1 + e) m1/(m1 + m2) over one sum
// (beyond.plain_range.one_division_form), each times the speed `by`; `full` takes it first there.
std::vector<Kernel> with_fast_path(Kernel full, const PlainRange& plain, const MassRatios& ratios,
                                   const ex& restitution, const ex& by, std::size_t speed_steps,
                                   const std::function<std::vector<ex>(int)>& rounding_ranges) {
  const Symbols& s = symbols();
  const ex e = s.restitution;
  const GiNaC::symbol first_coefficient("first_impulse_coefficient"),
      second_coefficient("second_impulse_coefficient");
  const GiNaC::symbol first_change("first_change"), second_change("second_change");
  Kernel fast{
      .name = "plain_" + full.name,
      .brief = "The same as " + full.name + " for masses in [plain_mass_low, plain_mass_high] (" +
               "within_plain_mass_range), where it is as accurate: (1 + e) m2/(m1 + m2) and (1 + e) m1/(m1 + "
               "m2) by one sum, the paper's plain form. " +
               full.name +
               " takes it there itself; call it "
               "directly only where the masses are known to be in the range (collide_batch's vectorised "
               "pass).",
      .parameters = full.parameters,
      .steps = {full.steps.begin(), full.steps.begin() + static_cast<std::ptrdiff_t>(speed_steps)},
      .outputs = {with_sign(ratios.first_ratio_form, first_change),
                  with_sign(ratios.second_ratio_form, second_change)},
      .equals = full.equals,
      .in_claim_terms = full.in_claim_terms,
      .claims = {"beyond.plain_range.one_division_form", "beyond.plain_range.smallest_share"},
      .names = {{"total_mass", s.m1 + s.m2}, {"restitution_factor", 1 + e}},
      .domain = plain_mass_range(s.m1, s.m2),
      .rounding_cases = {rounding_ranges(1)},
  };
  fast.steps.push_back({first_coefficient, plain.first_mass_form.subs(e == restitution)});
  fast.steps.push_back({second_coefficient, plain.second_mass_form.subs(e == restitution)});
  fast.steps.push_back({first_change, first_coefficient * by});
  fast.steps.push_back({second_change, second_coefficient * by});
  // The full form where it is taken: masses beyond the plain range, each way round, and past where the
  // light ball's share leaves the normal range.
  for (const MassCase& masses : beyond_plain_mass_cases(s.m1, s.m2)) {
    std::vector<ex> ranges = masses.masses;
    const std::vector<ex> rest = rounding_ranges(masses.speed_scale);
    ranges.insert(ranges.end(), rest.begin(), rest.end());
    full.rounding_cases.push_back(ranges);
  }
  full.fast_path = FastPath{
      .predicate = "within_plain_mass_range",
      .brief =
          "True when both masses lie in [plain_mass_low<Scalar>(), plain_mass_high<Scalar>()], where the "
          "collision kernels take their plain one-division form (false for +∞ and NaN).",
      .conditions = plain_mass_range(s.m1, s.m2),
      .kernel = fast.name,
      .claim = "beyond.plain_range.one_division_form",
  };
  return {fast, full};
}

}  // namespace

std::vector<Kernel> collision_kernels(const Setting& setting, const KernelPieces& pieces,
                                      const MassRatios& ratios, const PlainRange& plain,
                                      const Direction& direction) {
  const Symbols& s = symbols();
  const Space& space = setting.space;
  const ex e = s.restitution;
  const ChangeNames names;
  const GiNaC::symbol speed_name("relative_normal_speed"), direction_speed("direction_speed");
  const GiNaC::symbol approach_name("approach_speed");
  const GiNaC::realsymbol v1d("v1d"), v2d("v2d");
  const GiNaC::possymbol ddot("dd");
  const auto change_steps = [&](const ex& restitution, const ex& by) {
    return parkin2023::change_steps(names, ratios, restitution, by);
  };
  const auto outputs = [&] {
    return std::vector<ex>{with_sign(ratios.first_ratio_form, names.first_change),
                           with_sign(ratios.second_ratio_form, names.second_change)};
  };
  const ex cushion_change = pieces.cushion_change;
  // The direction kernels' parameters in the claims' terms: dot products in 3-D components.
  const GiNaC::exmap direction_terms{
      {v1d, dot(space.v1, direction.d)}, {v2d, dot(space.v2, direction.d)}, {ddot, direction.dd}};
  std::vector<Kernel> kernels;
  // The rounding proof's ranges of what the mass range leaves free: restitution in [0, 1] and the speed
  // in one binade — approaching along d for the kernel that changes only approaching pairs (a separating
  // pair's change is exactly 0).
  const auto between = [](const ex& low, const ex& x, const ex& high) {
    return std::vector<ex>{low <= x, x <= high};
  };
  const auto joined = [](std::vector<ex> first, const std::vector<ex>& then) {
    first.insert(first.end(), then.begin(), then.end());
    return first;
  };
  // Each speed range from one binade, [k, 2k] for a scale k (1 for the plain forms).
  const std::vector<ex> in_restitution = between(0, e, 1), in_direction = joined(between(1, ddot, 2), in_restitution);
  const auto in_normal_speed = [&](int k) { return between(k, s.v2n - s.v1n, 2 * k); };
  const auto add = [&](const Kernel& full, const ex& restitution, const ex& by, std::size_t speed_steps,
                       const std::function<std::vector<ex>(int)>& ranges) {
    for (const Kernel& kernel : with_fast_path(full, plain, ratios, restitution, by, speed_steps, ranges))
      kernels.push_back(kernel);
  };
  add(
      {
          .name = "elastic_normal_velocity_change",
          .brief =
              "The paper's perfectly elastic collision in normal components: the changes x1·n − v1·n and "
              "x2·n − v2·n of the two balls' velocities along the unit contact normal n, from the masses "
              "and v1·n, v2·n. A mass may be +∞ (an immovable body), not both.",
          .parameters = {s.m1, s.m2, s.v1n, s.v2n},
          .steps = steps_then({{speed_name, s.v2n - s.v1n}}, change_steps(1, speed_name)),
          .outputs = outputs(),
          .equals = "kernel.elastic_normal_velocity_change",
          .claims = {"result.x1_simplified_form", "result.x2_by_symmetry", "kernel.impulse_coefficient_first",
                     "kernel.impulse_coefficient_second", "beyond.immovable.mass_ratio_form"},
      },
      1, speed_name, 1, in_normal_speed);
  add(
      {
          .name = "normal_velocity_change",
          .brief = "A collision with coefficient of restitution e (0 ≤ e ≤ 1; e = 1 is the paper's): the "
                   "changes x1·n − v1·n and x2·n − v2·n along the unit contact normal n. A mass may be +∞.",
          .parameters = {s.m1, s.m2, s.v1n, s.v2n, e},
          .steps = steps_then({{speed_name, s.v2n - s.v1n}}, change_steps(e, speed_name)),
          .outputs = outputs(),
          .equals = "kernel.normal_velocity_change",
          .claims = {"beyond.restitution.impulse_coefficients", "beyond.immovable.mass_ratio_form",
                     "beyond.restitution.energy_loss"},
          .names = {{"restitution_factor", 1 + e}},
      },
      e, speed_name, 1, [&](int k) { return joined(in_normal_speed(k), in_restitution); });
  add(
      {
          .name = "direction_velocity_change",
          .brief =
              "The same along a direction d that need not be a unit vector: the multiples of d to add to "
              "v1 and v2, from the masses, v1·d, v2·d, d·d and e. d must not be zero.",
          .parameters = {s.m1, s.m2, v1d, v2d, ddot, e},
          .steps = steps_then({{direction_speed, (v2d - v1d) / ddot}}, change_steps(e, direction_speed)),
          .outputs = outputs(),
          .equals = "kernel.direction_velocity_change",
          .in_claim_terms = direction_terms,
          .claims = {"beyond.any_normal.direction_form", "beyond.any_normal.scale_invariant",
                     "beyond.immovable.mass_ratio_form"},
          .names = {{"restitution_factor", 1 + e}},
      },
      e, direction_speed, 1, [&](int k) { return joined(between(k, v2d - v1d, 2 * k), in_direction); });
  add(
      {
          .name = "approaching_direction_velocity_change",
          .brief = "Like direction_velocity_change with d pointing from ball 1 to ball 2, but only for "
                   "approaching balls ((v2 − v1)·d < 0); separating or resting contacts are left unchanged "
                   "(zero change), so rounding can never make a separating pair collide again.",
          .parameters = {s.m1, s.m2, v1d, v2d, ddot, e},
          .steps = steps_then({{direction_speed, (v2d - v1d) / ddot},
                               {approach_name, (direction_speed - GiNaC::abs(direction_speed)) / 2}},
                              change_steps(e, approach_name)),
          .outputs = outputs(),
          .equals = "kernel.approaching_direction_velocity_change",
          .in_claim_terms = direction_terms,
          .claims = {"beyond.approaching.kernel_form", "beyond.approaching.resolve_only_approaching",
                     "beyond.any_normal.direction_form", "beyond.immovable.mass_ratio_form"},
          .names = {{"restitution_factor", 1 + e}},
      },
      e, approach_name, 2, [&](int k) { return joined(between(-2 * k, v2d - v1d, -k), in_direction); });
  const GiNaC::realsymbol vn("vn");
  kernels.push_back({
      .name = "cushion_normal_velocity_change",
      .brief = "A ball meeting an immovable cushion (the paper's limit m2 → ∞ with v2 = 0): the change "
               "x·n − v·n of its velocity along the unit contact normal n, from v·n.",
      .parameters = {vn},
      .steps = {},
      .outputs = {cushion_change.subs(s.v1n == vn)},
      .equals = "kernel.cushion_velocity_change",
      .in_claim_terms = {{vn, s.v1n}},
      .claims = {"cushion.limit"},
      // v·n in one binade: the output scales exactly with it.
      .rounding_cases = {{1 <= vn, vn <= 2}},
  });
  // The raw derivation, for the benchmark: the coefficients A, B, C as read off, D = B² − 4AC, and the
  // root (−B ± √D)/(2A) with the sign of (v2 − v1)·n, the collision root whichever the sign
  return kernels;
}

std::vector<Kernel> reference_kernels(const Quadratic& quadratic) {
  const Symbols& s = symbols();
  const ex &A = quadratic.A, &B = quadratic.B, &C = quadratic.C, &x2n_solved = quadratic.x2n_solved;
  std::vector<Kernel> kernels;
  // one); x2·n from momentum.
  {
    const GiNaC::symbol a_name("quadratic_a"), b_name("quadratic_b"), c_name("quadratic_c");
    const GiNaC::symbol d_name("discriminant"), root_name("signed_root"), x1_name("x1n"), x2_name("x2n");
    kernels.push_back({
        .name = "raw_normal_velocity_change",
        .brief = "For the benchmark only: the paper's derivation before simplification. The quadratic in "
                 "x1·n with its coefficients as read off, D = B² − 4AC, the root (−B ± √D)/(2A) with the "
                 "sign of (v2 − v1)·n (the collision root), x2·n from momentum; returns the changes x1·n − "
                 "v1·n and x2·n − v2·n. Finite masses only.",
        .parameters = {s.m1, s.m2, s.v1n, s.v2n},
        .steps = {{a_name, A},
                  {b_name, B},
                  {c_name, C},
                  // D ≥ 0 exactly (discriminant.nonnegative); rounding can make it negative when the
                  // contact is nearly tangent, and √ of that would be NaN.
                  {d_name,
                   b_name * b_name - 4 * a_name * c_name,
                   {{d_name < 0, 0, Guard::Kind::unreachable, "discriminant.nonnegative"}}},
                  {root_name,
                   GiNaC::sqrt(d_name),
                   {{s.v2n - s.v1n < 0, -GiNaC::sqrt(d_name), Guard::Kind::piecewise,
                     "roots.quadratic_formula.relative_speed_negative"}}},
                  {x1_name, (-b_name + root_name) / (2 * a_name)},
                  {x2_name, x2n_solved.subs(s.x1n == x1_name)}},
        .outputs = {x1_name - s.v1n, x2_name - s.v2n},
        .equals = "kernel.elastic_normal_velocity_change",
        .claims = {"quadratic.coefficient_a", "quadratic.coefficient_b", "quadratic.coefficient_c",
                   "discriminant.paper_form", "roots.quadratic_formula.relative_speed_nonnegative",
                   "quadratic.x2_from_momentum"},
    });
  }
  return kernels;
}

Kernel time_of_impact_kernel(const TimeOfImpact& toi) {
  const Vec &p = toi.p, &w = toi.w;
  const ex &coefficient_a = toi.a, &coefficient_b = toi.b, &coefficient_c = toi.c;
  const ex &quarter_discriminant = toi.quarter_discriminant, &stable_root = toi.stable_root;
  const Vec& cross = toi.cross;
  const GiNaC::possymbol &contact_distance = toi.r, &qa = toi.qa, &root_of_d = toi.root_of_d;
  const GiNaC::realsymbol &qb = toi.qb, &qc = toi.qc, &qd = toi.qd;
  // The time of impact in the dot products pp = p·p, pv = p·w, vv = w·w: the coefficients b and c read
  // off in components, the last component eliminated through each dot product.
  const GiNaC::realsymbol pp("pp"), pv("pv"), vv("vv");
  const ex b_in_dots = GiNaC::normal(coefficient_b.subs(p[2] == (pv - p[0] * w[0] - p[1] * w[1]) / w[2]));
  const ex c_in_dots = reduce_modulo(coefficient_c, GiNaC::pow(p[2], 2) == pp - p[0] * p[0] - p[1] * p[1]);
  // D in Lagrange's form, (w·w) r² − |p × w|² (beyond.time_of_impact.discriminant): D + |p × w|²
  // expanded in components is (w·w) r², written in vv. Unlike b² − a c it does not cancel when the
  // spheres are far apart (r ≪ |p|), where b² and a c agree in all but their last digits.
  const GiNaC::realsymbol cross_squared("cross_squared");
  const ex lagrange_in_dots = reduce_modulo((quarter_discriminant + dot(cross, cross)).expand(),
                                            GiNaC::pow(w[2], 2) == vv - w[0] * w[0] - w[1] * w[1]) -
                              cross_squared;
  const GiNaC::symbol gap("gap"), discriminant("discriminant"), root_argument("root_argument"),
      contact_time("contact_time");
  const lst in_kernel{qb == b_in_dots, qc == gap};  // the stable form c/(√D − b) has no a
  // What each parameter and each symbol of the claims means, written from the definitions (never solved
  // from the kernel's own expressions): pp = p·p, pv = p·w, vv = w·w, cross_squared = |p × w|² in
  // components, and the claims' a = w·w, b = p·w, c = p·p − r², D = b² − a c, √D. Both sides are
  // compared in the components, so a kernel that forms anything but these quantities fails.
  const GiNaC::exmap time_terms{{pp, dot(p, p)},
                                {pv, dot(p, w)},
                                {vv, dot(w, w)},
                                {cross_squared, dot(cross, cross)},
                                {qa, coefficient_a},
                                {qb, coefficient_b},
                                {qc, coefficient_c},
                                {qd, quarter_discriminant},
                                {root_of_d, GiNaC::sqrt(quarter_discriminant)}};
  using Kind = Guard::Kind;
  return {
      .name = "time_of_impact",
      .brief =
          "The time until two spheres moving in straight lines first touch: from pp = p·p, pv = p·w, "
          "vv = w·w and cross_squared = |p × w|² (in any dimension the sum over i < j of (p_i w_j − "
          "p_j w_i)²), with p = p2 − p1 and w = v2 − v1 (relative position and velocity), and the "
          "contact distance r1 + r2. Returns the earliest t ≥ 0 at which they touch while approaching; "
          "0 when they already touch (or overlap by rounding) and approach; +∞ when they never touch "
          "(separating, no relative motion, a miss or a graze).",
      .parameters = {pp, pv, vv, cross_squared, contact_distance},
      // √ is taken of D where D > 0 and of 0 elsewhere, where the time is +∞ whatever it is (an
      // overridden guard): √ of a negative D, on every miss, raised the invalid flag and went through
      // libm's errno path, which made time_of_impact 1.4 times slower on the benchmark's cases.
      .steps = {{gap, c_in_dots},
                {discriminant, lagrange_in_dots},
                {root_argument,
                 discriminant,
                 {{discriminant <= 0, 0, Kind::overridden, "beyond.time_of_impact.grazing"}}},
                {contact_time,
                 stable_root.subs(in_kernel).subs(root_of_d == GiNaC::sqrt(root_argument)),
                 {{gap < 0, 0, Kind::piecewise, "beyond.time_of_impact.touching_now"},
                  {discriminant <= 0, infinity(), Kind::piecewise, "beyond.time_of_impact.grazing"},
                  {pv >= 0, infinity(), Kind::piecewise, "beyond.time_of_impact.no_contact"}}}},
      .outputs = {contact_time},
      .equals = "beyond.time_of_impact.stable_form",
      .in_claim_terms = time_terms,
      .claims = {"beyond.time_of_impact.quadratic", "beyond.time_of_impact.discriminant"},
      // Rounding proven where the balls approach from apart and the paths cross well inside the contact
      // distance: p·p − r² and r² w·w − |p × w|² then keep their digits (near a graze or a touch they
      // cancel, and the time's relative error grows as they do).
      .rounding_cases = {{16 <= pp, pp <= 32, -8 <= pv, pv <= -4, 4 <= vv, vv <= 8, 0 <= cross_squared,
                          cross_squared <= 1, 1 <= contact_distance, contact_distance <= 2}},
  };
}

}  // namespace billiards::derive::parkin2023
