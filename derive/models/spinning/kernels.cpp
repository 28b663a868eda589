// The spinning-ball model's kernels: what the runtime (spin.hpp, cloth.hpp) composes into vectors.
// Each is proven equal to the derived side of a claim before it is printed.
#include "models/spinning/steps.hpp"

#include "core/named_constants.hpp"
#include "core/powers_of_two.hpp"

#include <stdexcept>

namespace billiards::derive::spinning {

void kernel_claims(Recorder& record, const Contact& c, const Impulse& impulse, const Friction& friction) {
  const Symbols& s = symbols();
  record.section("kernel_outputs", "What each emitted kernel computes",
                 "The claims the kernels are proven against, where the steps above do not state the "
                 "emitted quantity on its own: the tangential impulse of Coulomb friction, the velocity and "
                 "spin changes it makes, and these in forms that depend on the masses only through their "
                 "ratio, so that no mass's size can overflow them.");
  // u_t' = u_t + k J_t (impulse.decoupled) with J_t = −j û_t: the slip's length |u_t| − k j.
  const ex j = s.tangential_impulse, sigma = s.tangential_slip, k = s.k;
  const ex sticking = GiNaC::lsolve(sigma - k * j == 0, j);
  record.add({
      .id = "kernel.friction_impulse",
      .statement = "The tangential impulse is j = min(μ J_n, |u_t|/k): the impulse that stops the slip where "
                   "Coulomb's bound allows it (sticking), μ J_n where it does not (sliding).",
      .method = "|u_t| − k j = 0 (the length of u_t' = u_t + k J_t, impulse.decoupled) solved for j with "
                "lsolve(); identity; the sliding case is definition.coulomb_friction",
      .comparison = Comparison::identity,
      .paper_expression = sigma / k,
      .derived_expression = sticking,
      .depends_on = {"impulse.decoupled", "friction.sticking_impulse", "definition.coulomb_friction"},
      .cases = {{lst{s.friction * s.normal_impulse < sigma / k}, s.friction * s.normal_impulse}},
  });
  // A tangential impulse J = −t (t = n × a) on ball 2, +t on ball 1: the changes of each ball's velocity
  // and spin per unit of it, from the impulse equations.
  const Vec tangent = c.tangent();
  const std::vector<Vec> after = c.after(scale(-1, tangent));
  const GiNaC::exmap solid{{s.I1, numeric(2, 5) * s.m1 * s.R1 * s.R1},
                           {s.I2, numeric(2, 5) * s.m2 * s.R2 * s.R2}};
  const Vec n_cross_t = cross(c.n, tangent);
  const ex first = GiNaC::normal(((after[1][0] - c.w1[0]) / n_cross_t[0]).subs(solid));
  const ex second = GiNaC::normal(((after[3][0] - c.w2[0]) / n_cross_t[0]).subs(solid));
  record.add({
      .id = "kernel.spin_change_per_impulse",
      .statement =
          "A tangential impulse j against the slip û_t (J = −j û_t on ball 2) turns ball 1's spin by "
          "(5 j/(2 m1 R1)) (n × û_t): the coefficient is R/I = 5/(2 m R).",
      .method = "Δω1 of the impulse equations for J = −t (t = n × a), its x component over (n × t)_x, "
                "I = (2/5) m R²; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = 5 / (2 * s.m1 * s.R1),
      .derived_expression = first,
      .depends_on = {"definition.impulse", "definition.solid_sphere"},
  });
  record.add({
      .id = "kernel.spin_change_per_impulse_second_ball",
      .statement = "The same impulse turns ball 2's spin by (5 j/(2 m2 R2)) (n × û_t): the same coefficient "
                   "R/I, and the same sense as ball 1's.",
      .method = "Δω2 of the impulse equations for J = −t, as for ball 1; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = 5 / (2 * s.m2 * s.R2),
      .derived_expression = second,
      .depends_on = {"kernel.spin_change_per_impulse"},
  });
  // Per unit of impulse: ball 1's velocity changes by +t/m1, ball 2's by −t/m2.
  const ex per_impulse_first = GiNaC::normal((after[0][0] - c.v1[0]) / tangent[0]);
  const ex per_impulse_second = GiNaC::normal((c.v2[0] - after[2][0]) / tangent[0]);
  // The sticking impulse |u_t|/k and the normal impulse as derived (friction.sticking_impulse,
  // friction.normal_impulse), for solid spheres.
  const ex stick = GiNaC::normal(friction.sticking_impulse.subs(solid));
  const ex Jn = friction.normal_impulse;
  const ex e = s.restitution, un = s.normal_slip, mu = s.friction;
  const ex sliding_condition = -(1 + e) * mu * un < numeric(2, 7) * sigma;
  record.add({
      .id = "kernel.tangential_velocity_change_sliding_condition",
      .statement = "Coulomb's bound decides without the masses: (μ J_n − |u_t|/k)(1/m1 + 1/m2) = −(1 + e) μ "
                   "u·n − 2|u_t|/7, and 1/m1 + 1/m2 > 0, so μ J_n < |u_t|/k (sliding) exactly where "
                   "−(1 + e) μ u·n < 2|u_t|/7.",
      .method = "friction.normal_impulse and friction.sticking_impulse (I = (2/5) m R²) times "
                "1/m1 + 1/m2 as derived in impulse.decoupled; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = -(1 + e) * mu * un - numeric(2, 7) * sigma,
      .derived_expression = GiNaC::normal((mu * Jn - stick) * impulse.normal_inverse),
      .depends_on = {"friction.normal_impulse", "friction.sticking_impulse", "impulse.decoupled"},
  });
  record.add({
      .id = "kernel.tangential_velocity_change",
      .statement = "The impulse j against the slip changes ball 1's velocity by +(j/m1) û_t and ball 2's by "
                   "−(j/m2) û_t, where j/m1 = min(−(1 + e) μ u·n, 2|u_t|/7)/(1 + m1/m2) and j/m2 = the "
                   "same/(1 + m2/m1): sticking gives (2|u_t|/7)/(1 + m1/m2), sliding (the case) −(1 + e) μ "
                   "u·n/(1 + m1/m2). Only the mass ratio enters.",
      .method = "the velocity changes per unit of impulse from the impulse equations (J = −t on ball 2) "
                "times friction.sticking_impulse for solid spheres, and times μ J_n "
                "(friction.normal_impulse) in the sliding case; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression =
          lst{numeric(2, 7) * sigma / (1 + s.m1 / s.m2), numeric(2, 7) * sigma / (1 + s.m2 / s.m1)},
      .derived_expression =
          lst{GiNaC::normal(stick * per_impulse_first), GiNaC::normal(stick * per_impulse_second)},
      .depends_on = {"definition.impulse", "friction.sticking_impulse", "friction.normal_impulse",
                     "kernel.tangential_velocity_change_sliding_condition"},
      .cases = {{lst{sliding_condition}, lst{GiNaC::normal(mu * Jn * per_impulse_first),
                                             GiNaC::normal(mu * Jn * per_impulse_second)}}},
  });
  // The spin change per velocity change: Δω/Δv of the same impulse, for each ball.
  const ex dv = s.velocity_change;
  record.add({
      .id = "kernel.spin_change",
      .statement =
          "Ball 1, whose velocity the tangential impulse changes by Δv along û_t, turns by "
          "(5 Δv/(2 R1)) (n × û_t): the spin change per velocity change is 5/(2R), free of the mass.",
      .method = "kernel.spin_change_per_impulse over ball 1's velocity change per unit of impulse (J = −t on "
                "ball 2); identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = 5 * dv / (2 * s.R1),
      .derived_expression = GiNaC::normal(dv * first / per_impulse_first),
      .depends_on = {"kernel.spin_change_per_impulse", "definition.impulse"},
  });
  record.add({
      .id = "kernel.spin_change_second_ball",
      .statement = "Ball 2, whose velocity the same impulse changes by Δv against û_t, turns by "
                   "(5 Δv/(2 R2)) (n × û_t): the same coefficient, the same sense as ball 1's.",
      .method = "kernel.spin_change_per_impulse_second_ball over ball 2's velocity change per unit of "
                "impulse; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = 5 * dv / (2 * s.R2),
      .derived_expression = GiNaC::normal(dv * second / per_impulse_second),
      .depends_on = {"kernel.spin_change_per_impulse_second_ball", "definition.impulse"},
  });
}

namespace {

// The rounding proof's case for a kernel scaled by powers of two (scaled_monomial): every parameter in one
// binade, 1 ≤ x < 2, where each exponent is 0; the kernel scales exactly with each (its validation holds
// for every exponent), so the bound holds wherever its intermediates and its output are normal numbers.
std::vector<ex> in_one_binade(const std::vector<ex>& parameters) {
  std::vector<ex> ranges;
  for (const ex& parameter : parameters) {
    ranges.push_back(1 <= parameter);
    ranges.push_back(parameter < 2);
  }
  return ranges;
}

// normal_impulse's rounding cases: masses in neighbouring binades, [1, 2) and [2, 4), and beyond the
// plain range (beyond_plain_mass_cases), either way round (either branch of the lighter mass); e in
// [0, 1] and the approaching speed in one binade, (−2k, −k], so that every exponent is fixed.
std::vector<std::vector<ex>> normal_impulse_cases(const ex& speed) {
  const Symbols& s = symbols();
  std::vector<MassCase> masses = {{{1 <= s.m1, s.m1 < 2, 2 <= s.m2, s.m2 < 4}},
                                  {{2 <= s.m1, s.m1 < 4, 1 <= s.m2, s.m2 < 2}}};
  for (const MassCase& beyond : beyond_plain_mass_cases(s.m1, s.m2)) masses.push_back(beyond);
  std::vector<std::vector<ex>> cases;
  for (const MassCase& mass : masses) {
    std::vector<ex> ranges = mass.masses;
    const ex k = mass.speed_scale;
    for (const ex r : {-2 * k < speed, speed <= -k, 0 <= s.restitution, s.restitution <= 1})
      ranges.push_back(r);
    cases.push_back(ranges);
  }
  return cases;
}

// `plain`, a faster form of `full`'s claim where every one of `conditions` holds (its domain), and `full`
// taking it there first through the predicate `predicate`: both appended, `plain` first.
void push_with_fast_path(std::vector<Kernel>& kernels, Kernel plain, Kernel full,
                         const std::vector<ex>& conditions, const std::string& predicate,
                         const std::string& brief) {
  plain.domain = conditions;
  full.fast_path = FastPath{
      .predicate = predicate,
      .brief = brief,
      .conditions = conditions,
      .kernel = plain.name,
      .claim = full.equals,
  };
  kernels.push_back(plain);
  kernels.push_back(full);
}

// The impulse of a contact: k, J_n and j.
void impulse_kernels(std::vector<Kernel>& kernels) {
  const Symbols& s = symbols();
  using Kind = Guard::Kind;
  {
    // 3.5/m1 + 3.5/m2: each term rounds once and neither exceeds the sum, so nothing overflows that the
    // result does not (7/m1 before a halving would, for m1 just above the smallest normal number).
    const GiNaC::symbol first("first_term"), second("second_term");
    kernels.push_back({
        .name = "tangential_inverse_effective_mass",
        .brief =
            "The tangential inverse effective mass k = (7/2)(1/m1 + 1/m2) of a contact between two solid "
            "spheres: a tangential impulse j changes the tangential slip by k j.",
        .parameters = {s.m1, s.m2},
        .steps = {{first, numeric(7, 2) / s.m1}, {second, numeric(7, 2) / s.m2}},
        .outputs = {first + second},
        .equals = "impulse.tangential_inverse_effective_mass_solid_spheres",
        .claims = {"impulse.decoupled"},
        // Rounding proven over masses in the plain range (it keeps its digits beyond it too).
        .rounding_cases = {plain_mass_range(s.m1, s.m2)},
    });
  }
  {
    // J_n = −(1 + e) m s/(1 + m/M), m the lighter mass and M the heavier: the product m s on the
    // significands of m and s (binary_exponent), scaled back once, so that neither a subnormal mass nor
    // a huge speed loses digits or overflows before the result does.
    const GiNaC::realsymbol speed("relative_normal_speed");
    const GiNaC::symbol lighter("lighter_mass"), heavier("heavier_mass"), ratio("mass_ratio");
    const auto heavier_first = [&](const ex& alternative) {
      return Guard{s.m2 < s.m1, alternative, Kind::same_value, "friction.normal_impulse"};
    };
    const ScaledMonomial product =
        scaled_monomial("impulse", lighter * speed / (1 + ratio), {lighter, speed});
    std::vector<KernelStep> steps = {{lighter, s.m1, {heavier_first(s.m2)}},
                                     {heavier, s.m2, {heavier_first(s.m1)}},
                                     {ratio, lighter / heavier}};
    steps.insert(steps.end(), product.steps.begin(), product.steps.end());
    kernels.push_back({
        .name = "normal_impulse",
        .brief = "The normal impulse J_n = −(1 + e) μ_red (v2 − v1)·n, μ_red = m1 m2/(m1 + m2), from the "
                 "relative normal speed (v2 − v1)·n (negative for approaching balls). The reduced mass is "
                 "taken as m/(1 + m/M) with m the smaller mass, so neither the product nor the sum of the "
                 "masses is formed, and m times the speed on their significands, scaled back once.",
        .parameters = {s.m1, s.m2, s.restitution, speed},
        .steps = steps,
        // (1 + e) ∈ [1, 2] times the significand, before the scaling back: as printed.
        .outputs = {-(1 + s.restitution) * product.value},
        .equals = "friction.normal_impulse",
        .in_claim_terms = {{speed, s.normal_slip}},
        .rounding_cases = normal_impulse_cases(speed),
    });
  }
  {
    const GiNaC::possymbol normal("normal_impulse"), slip("tangential_slip"),
        k("tangential_inverse_effective_mass");
    const GiNaC::symbol stick("impulse");
    kernels.push_back({
        .name = "friction_impulse",
        .brief =
            "The magnitude j = min(μ J_n, |u_t|/k) of the tangential impulse of Coulomb friction, from the "
            "friction coefficient μ, the normal impulse J_n, the tangential slip |u_t| and the tangential "
            "inverse effective mass k; it acts against the slip.",
        .parameters = {s.friction, normal, slip, k},
        .steps = {{stick,
                   slip / k,
                   {{s.friction * normal < slip / k, s.friction * normal, Kind::piecewise,
                     "kernel.friction_impulse"}}}},
        .outputs = {stick},
        .equals = "kernel.friction_impulse",
        .in_claim_terms = {{normal, s.normal_impulse}, {slip, s.tangential_slip}, {k, s.k}},
        .claims = {"friction.sticking_impulse", "friction.sliding_never_reverses"},
        // Rounding proven in each branch, every quantity in one binade: sticking (|u_t|/k the smaller)
        // and sliding (μ J_n the smaller).
        .rounding_cases = {{ex(1) / 2 <= s.friction, s.friction <= 1, 4 <= normal, normal <= 8,
                            ex(1) / 2 <= slip, slip <= 1, 1 <= k, k <= 2},
                           {ex(1) / 2 <= s.friction, s.friction <= 1, ex(1) / 16 <= normal,
                            normal <= ex(1) / 8, ex(1) / 2 <= slip, slip <= 1, 1 <= k, k <= 2}},
    });
  }
}

// The velocity changes the tangential impulse makes, with their plain form over one sum.
void tangential_velocity_kernels(std::vector<Kernel>& kernels) {
  const Symbols& s = symbols();
  using Kind = Guard::Kind;
  {
    const GiNaC::realsymbol speed("relative_normal_speed");
    const GiNaC::possymbol slip("tangential_slip");
    const GiNaC::symbol first_ratio("first_mass_ratio"), second_ratio("second_mass_ratio"),
        first("first_fraction"), second("second_fraction"), sticking("sticking_change"),
        coulomb("coulomb_speed"), sliding("sliding_change"), bound("bound"), change1("first"),
        change2("second");
    // Where a fraction falls below the normal range (a mass ratio beyond 2^126 in float) the heavy
    // ball's change is the bound times m_light/m_heavy over 1 + m_light/m_heavy: formed on the
    // significands of the bound and the masses and scaled back once (scaled_monomial), so that neither
    // a subnormal ratio loses digits nor a huge bound over a mass below 1 overflows before the result.
    // Ball 1's form is built first; ball 2's reuses its exponents and significands.
    const ScaledMonomial light_first = scaled_monomial(
        "first_small_mass_change", bound * s.m2 / (s.m1 * (1 + second_ratio)), {bound, s.m1, s.m2});
    const GiNaC::symbol light_second("scaled_second_small_mass_change"),
        light_second_exponent("second_small_mass_change_exponent");
    // The bound min(−(1 + e) μ (v2 − v1)·n, 2|u_t|/7), shared by the full kernel and its plain form.
    const std::vector<KernelStep> bound_steps = {
        {sticking, numeric(2, 7) * slip},
        // μ (v2 − v1)·n first: (1 + e) ∈ [1, 2] then cannot overflow a product the
        // result stays below, as (1 + e) μ could for a huge μ beside a tiny approach.
        {coulomb, s.friction * speed},
        {sliding, -(1 + s.restitution) * coulomb},
        {bound,
         sticking,
         {{sliding < sticking, sliding, Kind::piecewise, "kernel.tangential_velocity_change"}}}};
    std::vector<KernelStep> steps = {{first_ratio, s.m1 / s.m2},
                                     {second_ratio, s.m2 / s.m1},
                                     {first, 1 / (1 + first_ratio)},
                                     {second, 1 / (1 + second_ratio)}};
    steps.insert(steps.end(), bound_steps.begin(), bound_steps.end());
    steps.insert(steps.end(), light_first.steps.begin(), light_first.steps.end());
    const GiNaC::exmap& scaled = light_first.scaled;
    const GiNaC::exmap& exponent = light_first.exponent;
    steps.push_back(
        {light_second, scaled.at(bound) * scaled.at(s.m1) / (scaled.at(s.m2) * (1 + first_ratio))});
    steps.push_back({light_second_exponent, exponent.at(bound) + exponent.at(s.m1) - exponent.at(s.m2)});
    const auto tiny = [](const GiNaC::symbol& fraction, const ex& alternative) {
      return Guard{fraction < smallest_normal(), alternative, Kind::same_value,
                   "kernel.tangential_velocity_change"};
    };
    steps.push_back({change1, first * bound, {tiny(first, light_first.value)}});
    steps.push_back(
        {change2, second * bound, {tiny(second, times_power_of_two(light_second, light_second_exponent))}});
    // Where both masses lie in the collision kernels' plain range the shares m2/(m1 + m2) and
    // m1/(m1 + m2) over one sum: no ratio, no scaling, and each share at least 2^−123 (float), a normal
    // number (beyond.plain_range.smallest_share of the paper's model), so the changes round three times
    // where the ratio form rounds four.
    const GiNaC::symbol total("total_mass"), first_share("first_share"), second_share("second_share");
    const std::vector<ex> plain_range = plain_mass_range(s.m1, s.m2);
    std::vector<KernelStep> plain_steps = bound_steps;
    plain_steps.push_back({total, s.m1 + s.m2});
    plain_steps.push_back({first_share, s.m2 / total});
    plain_steps.push_back({second_share, s.m1 / total});
    plain_steps.push_back({change1, bound * first_share});
    plain_steps.push_back({change2, bound * second_share});
    Kernel full{
        .name = "tangential_velocity_change",
        .brief =
            "The changes j/m1 and j/m2 of the two balls' velocities along û_t (ball 1 +, ball 2 −) that "
            "the tangential impulse j = min(μ J_n, |u_t|/k) makes, as min(−(1 + e) μ (v2 − v1)·n, "
            "2|u_t|/7)/(1 + m1/m2) and /(1 + m2/m1): only the mass ratio enters, so no mass's size can "
            "overflow it; beyond the normal range of a fraction the heavy ball's change is the bound "
            "times m_light/m_heavy over 1 + m_light/m_heavy, formed on significands and scaled back once.",
        .parameters = {s.m1, s.m2, s.restitution, s.friction, speed, slip},
        .steps = steps,
        .outputs = {change1, change2},
        .equals = "kernel.tangential_velocity_change",
        .in_claim_terms = {{speed, s.normal_slip}, {slip, s.tangential_slip}},
        .claims = {"kernel.tangential_velocity_change_sliding_condition", "friction.sticking_impulse",
                   "friction.sliding_never_reverses"},
        .names = {{"first_denominator", 1 + first_ratio}, {"second_denominator", 1 + second_ratio}},
    };
    Kernel plain = full;
    plain.name = "plain_" + full.name;
    plain.brief =
        "The same as tangential_velocity_change for masses in [plain_mass_low, plain_mass_high] "
        "(within_plain_mass_range): the bound times the shares m2/(m1 + m2) and m1/(m1 + m2) of one "
        "sum, normal numbers there. tangential_velocity_change takes it there itself.";
    plain.steps = plain_steps;
    plain.names = {};
    // The rounding proof's two cases, one for each branch of the bound: sticking (2|u_t|/7 the smaller)
    // and sliding (−(1 + e) μ (v2 − v1)·n the smaller); in each, every quantity in one binade, or e in
    // [0, 1].
    const auto ranges = [&](const ex& slip_low) {
      return std::vector<ex>{slip_low <= slip,   slip <= 2 * slip_low, ex(1) / 2 <= s.friction,
                             s.friction <= 1,    -2 <= speed,          speed <= -1,
                             0 <= s.restitution, s.restitution <= 1};
    };
    plain.rounding_cases = {ranges(ex(1) / 2), ranges(16)};
    // The full form where it is taken, masses beyond the plain range (beyond_plain_mass_cases), in each
    // branch with the bound in one binade [k, 2k), so that its exponent is fixed: sticking (2|u_t|/7 in
    // [k, 13k/7], the sliding bound at least 2k) and sliding ((1 + e) μ |(v2 − v1)·n| in [k, 1.96k], the
    // sticking bound at least 2k).
    const auto branch = [&](bool sticking, const ex& k) {
      if (sticking)
        return std::vector<ex>{ex(7) / 2 * k <= slip,      slip <= ex(13) / 2 * k, ex(1) / 2 <= s.friction,
                               s.friction <= 1,            -8 * k <= speed,        speed <= -4 * k,
                               0 <= s.restitution,         s.restitution <= 1};
      return std::vector<ex>{7 * k <= slip,           slip <= 14 * k,          ex(1) / 2 <= s.friction,
                             s.friction <= ex(5) / 8, -ex(5) / 2 * k <= speed, speed <= -2 * k,
                             0 <= s.restitution,      s.restitution <= ex(1) / 4};
    };
    for (const MassCase& masses : beyond_plain_mass_cases(s.m1, s.m2)) {
      for (const bool sticking : {true, false}) {
        std::vector<ex> ranges = masses.masses;
        const std::vector<ex> rest = branch(sticking, masses.speed_scale);
        ranges.insert(ranges.end(), rest.begin(), rest.end());
        full.rounding_cases.push_back(ranges);
      }
    }
    push_with_fast_path(
        kernels, plain, full, plain_range, "within_plain_mass_range",
        "True when both masses lie in [plain_mass_low<Scalar>(), plain_mass_high<Scalar>()], "
        "where tangential_velocity_change takes its plain form over one sum (false for +∞ and "
        "NaN).");
  }
}

// The spin changes of the tangential impulse.
void spin_change_kernels(std::vector<Kernel>& kernels) {
  const Symbols& s = symbols();
  {
    const GiNaC::possymbol change("velocity_change"), radius("radius");
    const GiNaC::symbol per_radius("change_per_radius");
    kernels.push_back({
        .name = "spin_change",
        .brief = "The spin change 5 Δv/(2R) along n × û_t of a ball of radius R whose velocity a tangential "
                 "impulse changes by Δv (tangential_velocity_change's first for ball 1, second for ball 2).",
        .parameters = {change, radius},
        // Δv/R first, then 2.5 times it: 5 Δv would overflow before the result does.
        .steps = {{per_radius, change / radius}},
        .outputs = {numeric(5, 2) * per_radius},
        .equals = "kernel.spin_change",
        .in_claim_terms = {{change, s.velocity_change}, {radius, s.R1}},
        .claims = {"kernel.spin_change_second_ball"},
        // Δv and R in one binade: the output scales exactly with each.
        .rounding_cases = {in_one_binade({change, radius})},
    });
  }
  {
    const GiNaC::possymbol mass("mass"), radius("radius");
    const ScaledMonomial per_impulse =
        scaled_monomial("per_impulse", numeric(5, 2) / (mass * radius), {mass, radius});
    kernels.push_back({
        .name = "spin_change_per_impulse",
        .brief = "R/I = 5/(2 m R) for a solid sphere of mass m and radius R: a tangential impulse j against "
                 "the slip û_t turns its spin by (5 j/(2 m R)) (n × û_t).",
        .parameters = {mass, radius},
        .steps = per_impulse.steps,
        .outputs = {per_impulse.value},
        .equals = "kernel.spin_change_per_impulse",
        .in_claim_terms = {{mass, s.m1}, {radius, s.R1}},
        .claims = {"kernel.spin_change_per_impulse_second_ball"},
        .rounding_cases = {in_one_binade({mass, radius})},
    });
  }
}

// The durations of the phases on the cloth.
void phase_time_kernels(std::vector<Kernel>& kernels, const Cloth& cloth) {
  const Symbols& s = symbols();
  using Kind = Guard::Kind;
  // A phase's duration `time`, a monomial in the kernel's parameters (its speed, friction, gravity and
  // radius), over the whole exponent range: on their significands, scaled back once (scaled_monomial),
  // and `frictionless` where the friction is zero. Where every input lies in [moderate_low,
  // moderate_high] the plain form, the duration as derived, keeps every digit and needs no scaling: the
  // kernel takes it there first, a kernel of its own (plain_<name>) printed before it.
  const GiNaC::symbol duration("duration");
  const auto push_phase_time = [&](Kernel full, const ex& time, const Guard& frictionless) {
    ScaledMonomial scaled = scaled_monomial("duration", time, full.parameters);
    scaled.steps.push_back({duration, scaled.value, {frictionless}});
    full.steps = scaled.steps;
    full.outputs = {duration};
    full.rounding_cases = {in_one_binade(full.parameters)};
    std::vector<ex> conditions;
    for (const ex& parameter : full.parameters) {
      conditions.push_back(moderate_low() <= parameter);
      conditions.push_back(parameter <= moderate_high());
    }
    Kernel plain{
        .name = "plain_" + full.name,
        .brief = "The same as " + full.name + " where every input lies in [moderate_low, moderate_high] (" +
                 full.name + "_is_moderate), where the plain form keeps every digit without scaling. " +
                 full.name + " takes it there itself.",
        .parameters = full.parameters,
        .steps = {{duration, time, {frictionless}}},
        .outputs = {duration},
        .equals = full.equals,
        .in_claim_terms = full.in_claim_terms,
    };
    push_with_fast_path(kernels, plain, full, conditions, full.name + "_is_moderate",
                        "True when every input of " + full.name +
                            " lies in [moderate_low<Scalar>(), moderate_high<Scalar>()], where it takes its "
                            "plain form (false for 0, +∞ and NaN).");
  };
  {
    const GiNaC::possymbol slip("slip_speed"), mu("sliding_friction"), gravity("gravity");
    push_phase_time(
        {
            .name = "slide_time",
            .brief = "The time t_s = 2 |u0|/(7 μ_s g) a ball slides on the cloth before it rolls, from its "
                     "slip speed |u0|; +∞ without sliding friction.",
            .parameters = {slip, mu, gravity},
            .equals = "sliding.slide_time",
            .in_claim_terms = {{slip, s.slip_speed}, {mu, s.sliding_friction}, {gravity, s.g}},
        },
        cloth.slide_time.subs(lst{s.slip_speed == slip, s.sliding_friction == mu, s.g == gravity}),
        {mu <= 0, infinity(), Kind::piecewise, "sliding.frictionless_slides_on"});
  }
  {
    const GiNaC::possymbol speed("speed"), mu("rolling_friction"), gravity("gravity");
    push_phase_time(
        {
            .name = "roll_time",
            .brief = "The time t_r = |v0|/(μ_r g) a rolling ball takes to stop, from its speed |v0|; +∞ "
                     "without rolling resistance.",
            .parameters = {speed, mu, gravity},
            .equals = "rolling.stop_time",
            .in_claim_terms = {{speed, s.ball_speed}, {mu, s.rolling_friction}, {gravity, s.g}},
        },
        cloth.roll_time.subs(lst{s.ball_speed == speed, s.rolling_friction == mu, s.g == gravity}),
        {mu <= 0, infinity(), Kind::piecewise, "rolling.frictionless_rolls_on"});
  }
  {
    const GiNaC::possymbol spin("spin_speed"), radius("radius"), mu("spinning_friction"), gravity("gravity");
    push_phase_time(
        {
            .name = "spin_time",
            .brief = "The time t_z = 2 R |ω_z|/(5 μ_sp g) until the spin about ẑ stops, from |ω_z| and the "
                     "radius R; +∞ without spinning friction.",
            .parameters = {spin, radius, mu, gravity},
            .equals = "spinning.stop_time",
            .in_claim_terms = {{spin, s.spin}, {radius, s.R}, {mu, s.spinning_friction}, {gravity, s.g}},
        },
        cloth.spin_time.subs(lst{s.spin == spin, s.R == radius, s.spinning_friction == mu, s.g == gravity}),
        {mu <= 0, infinity(), Kind::piecewise, "spinning.frictionless_spins_on"});
  }
}

// The coefficients of the event polynomials (the section "Event times on the cloth"), one kernel each.
// Each is a short sum of products; its bound is proven where the terms share a sign (the case below,
// one binade or two of each input, which scales exactly with any common power of two of the lengths,
// speeds and accelerations); where they cancel, as c0 does near a contact, its error is a few ε of the
// terms' size instead.
void event_kernels(std::vector<Kernel>& kernels) {
  const EventSymbols& p = event_symbols();
  const auto within = [](const ex& x, const ex& low, const ex& high) { return std::vector<ex>{low <= x, x <= high}; };
  const auto box = [](std::vector<std::vector<ex>> ranges) {
    std::vector<ex> all;
    for (const std::vector<ex>& range : ranges) all.insert(all.end(), range.begin(), range.end());
    return all;
  };
  const std::string contact = " of the contact polynomial |Δr + Δv t + ½ Δa t²|² − D² of two balls (Δ: ball 2 "
                              "less ball 1, D = R1 + R2) or of a ball and a circle (Δ: the ball less the "
                              "circle's centre, D = R + ρ or ρ)";
  {
    // c0 = |Δr|² − D² without the cancellation near a contact: each square's rounding error taken exactly
    // by a fused multiply-add; the larger square less D² (exact by Sterbenz's lemma where the gap is small:
    // the larger square then lies within a factor 2 of D²) plus the smaller (exact again, or without
    // cancellation); the errors added last. Its error is a few ε of c0 itself plus ε² of the squares.
    const GiNaC::symbol xx("xx"), xx_error("xx_error"), yy("yy"), yy_error("yy_error"), dd("dd"),
        dd_error("dd_error"), larger("larger"), smaller("smaller"), difference("difference"), nearest("nearest"),
        errors("errors"), constant_term("constant_term");
    using Kind = Guard::Kind;
    const std::string why = "events.contact_constant_term";
    // The script's names (rounding.hpp): how the kept errors cancel the squares' rounding.
    const std::vector<std::string> hints = {
        "c_xx + c_xx_error - p_dx * p_dx -> c_xx_error - (p_dx * p_dx - c_xx);",
        "c_yy + c_yy_error - p_dy * p_dy -> c_yy_error - (p_dy * p_dy - c_yy);",
        "c_dd + c_dd_error - p_distance * p_distance -> c_dd_error - (p_distance * p_distance - c_dd);",
        "c_constant_term - e_constant_term -> (c_constant_term - (c_errors + c_nearest)) + (c_nearest - "
        "(c_difference + c_smaller)) + (c_difference - (c_larger - c_dd)) + (c_errors - ((c_xx_error + "
        "c_yy_error) - c_dd_error)) + ((c_xx + c_xx_error - p_dx * p_dx) + (c_yy + c_yy_error - p_dy * p_dy) - "
        "(c_dd + c_dd_error - p_distance * p_distance));",
    };
    const ex gap_scale = GiNaC::numeric(1, 4096);  // 2^-12: a gap of 2^-12 D to 2^-11 D, in float and double
    kernels.push_back({
        .name = "contact_constant_term",
        .brief = "c0 = Δr·Δr − D², the coefficient of t⁰" + contact +
                 ": its sign is the gap's. Without cancellation where the bodies nearly touch: its error is "
                 "a few ε of c0 itself.",
        .parameters = {p.dx, p.dy, p.distance},
        .steps = {{xx, p.dx * p.dx},
                  {xx_error, fused_multiply_add_held(p.dx, p.dx, -xx)},
                  {yy, p.dy * p.dy},
                  {yy_error, fused_multiply_add_held(p.dy, p.dy, -yy)},
                  {dd, p.distance * p.distance},
                  {dd_error, fused_multiply_add_held(p.distance, p.distance, -dd)},
                  {larger, xx, {Guard{yy > xx, yy, Kind::same_value, why}}},
                  {smaller, yy, {Guard{yy > xx, xx, Kind::same_value, why}}},
                  {difference, larger - dd},
                  {nearest, difference + smaller},
                  {errors, xx_error + yy_error - dd_error},
                  {constant_term, nearest + errors}},
        .outputs = {constant_term},
        .equals = "events.contact_constant_term",
        .claims = {"events.contact_now_and_approach"},
        .rounding_cases = {box({within(p.dx, 4, 8), within(p.dy, 1, 2), within(p.distance, 1, 2)}),
                           box({within(p.dx, 1, 2), within(p.dy, 4, 8), within(p.distance, 1, 2)}),
                           // Nearly touching, along x and along y: c0 = 2^-12 D² to 2^-9 D².
                           box({within(p.dx, 1 + gap_scale, 1 + 2 * gap_scale), within(p.dy, 0, gap_scale * gap_scale),
                                within(p.distance, 1, 1 + gap_scale / 2)}),
                           box({within(p.dx, 0, gap_scale * gap_scale), within(p.dy, 1 + gap_scale, 1 + 2 * gap_scale),
                                within(p.distance, 1, 1 + gap_scale / 2)})},
        .gappa_hints = hints,
        .promised_error = 8,
    });
  }
  kernels.push_back({
      .name = "contact_linear_term",
      .brief = "c1 = 2 Δr·Δv, the coefficient of t" + contact + ": negative iff the bodies approach.",
      .parameters = {p.dx, p.dy, p.dvx, p.dvy},
      .outputs = {2 * (p.dx * p.dvx + p.dy * p.dvy)},
      .equals = "events.contact_linear_term",
      .claims = {"events.contact_now_and_approach"},
      .rounding_cases = {box({within(p.dx, 1, 2), within(p.dy, 1, 2), within(p.dvx, 1, 2), within(p.dvy, 1, 2)})},
  });
  kernels.push_back({
      .name = "contact_quadratic_term",
      .brief = "c2 = Δv·Δv + Δr·Δa, the coefficient of t²" + contact + ".",
      .parameters = {p.dx, p.dy, p.dvx, p.dvy, p.dax, p.day},
      .outputs = {p.dvx * p.dvx + p.dvy * p.dvy + p.dx * p.dax + p.dy * p.day},
      .equals = "events.contact_quadratic_term",
      .claims = {"events.contact_degree"},
      .rounding_cases = {box({within(p.dx, 1, 2), within(p.dy, 1, 2), within(p.dvx, 1, 2), within(p.dvy, 1, 2),
                              within(p.dax, 1, 2), within(p.day, 1, 2)})},
  });
  kernels.push_back({
      .name = "contact_cubic_term",
      .brief = "c3 = Δv·Δa, the coefficient of t³" + contact + ".",
      .parameters = {p.dvx, p.dvy, p.dax, p.day},
      .outputs = {p.dvx * p.dax + p.dvy * p.day},
      .equals = "events.contact_cubic_term",
      .claims = {"events.contact_degree"},
      .rounding_cases = {box({within(p.dvx, 1, 2), within(p.dvy, 1, 2), within(p.dax, 1, 2), within(p.day, 1, 2)})},
  });
  kernels.push_back({
      .name = "contact_quartic_term",
      .brief = "c4 = ¼ Δa·Δa, the coefficient of t⁴" + contact + ": zero exactly where the accelerations are equal.",
      .parameters = {p.dax, p.day},
      .outputs = {(p.dax * p.dax + p.day * p.day) / 4},
      .equals = "events.contact_quartic_term",
      .claims = {"events.contact_degree"},
      .rounding_cases = {box({within(p.dax, 1, 2), within(p.day, 1, 2)})},
  });
  kernels.push_back({
      .name = "cushion_contact_constant_term",
      .brief = "c0 = s0 − R of the cushion polynomial s0 − R + v_n t + ½ a_n t² (s0 the centre's distance from "
               "the cushion's line, v_n and a_n along its normal into the table, c1 = v_n): the gap.",
      .parameters = {p.gap, p.radius},
      .outputs = {p.gap - p.radius},
      .equals = "events.cushion_constant_term",
      .rounding_cases = {box({within(p.gap, 4, 8), within(p.radius, 1, 2)})},
  });
  kernels.push_back({
      .name = "cushion_contact_quadratic_term",
      .brief = "c2 = ½ a_n of the cushion polynomial s0 − R + v_n t + ½ a_n t².",
      .parameters = {p.normal_acceleration},
      .outputs = {p.normal_acceleration / 2},
      .equals = "events.cushion_quadratic_term",
      .rounding_cases = {box({within(p.normal_acceleration, 1, 2)})},
  });
}

}  // namespace

std::vector<Kernel> spin_kernels(const Cloth& cloth) {
  std::vector<Kernel> kernels;
  impulse_kernels(kernels);
  tangential_velocity_kernels(kernels);
  spin_change_kernels(kernels);
  phase_time_kernels(kernels, cloth);
  event_kernels(kernels);
  return kernels;
}

}  // namespace billiards::derive::spinning
