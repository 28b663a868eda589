#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

MassRatios immovable_bodies(Recorder& record, const Restitution& restitution) {
  const Symbols& s = symbols();
  const ex e = s.restitution;
  const ex speed = s.relative_normal_speed;
  const ex &first_coefficient_e = restitution.first_coefficient,
           &second_coefficient_e = restitution.second_coefficient;
  // Immovable bodies: the coefficients in the mass ratios ρ1 = m1/m2 and ρ2 = m2/m1.
  const ex rho1 = s.first_mass_ratio, rho2 = s.second_mass_ratio;
  const ex first_ratio_form = GiNaC::normal(first_coefficient_e.subs(s.m1 == rho1 * s.m2));
  const ex second_ratio_form = GiNaC::normal(second_coefficient_e.subs(s.m2 == rho2 * s.m1));
  const lst printed_ratio_forms{(1 + e) / (1 + rho1), -(1 + e) / (1 + rho2)};
  record.add({
      .id = "beyond.immovable.mass_ratio_form",
      .statement = "In the mass ratios ρ1 = m1/m2 and ρ2 = m2/m1 the coefficients are (1 + e)/(1 + ρ1) "
                   "and −(1 + e)/(1 + ρ2): no mass appears alone.",
      .method = "m1 = ρ1 m2 (resp. m2 = ρ2 m1) substituted; normal() cancels the other mass; identity",
      .comparison = Comparison::identity,
      .paper_expression = printed_ratio_forms,
      .derived_expression = lst{first_ratio_form, second_ratio_form},
      .paper_display = printed_ratio_forms,
      .derived_display = factored_form(lst{first_ratio_form, second_ratio_form}),
      .note = "Chosen for floating point: a ratio of two positive masses is finite or +∞ and never "
              "NaN unless both are infinite; 1 + ρ cannot overflow where m1 + m2 can (1e308 + 1e308), "
              "and no inverse mass overflows for a subnormal mass. An infinite m2 gives ρ1 = 0 and "
              "ρ2 = ∞, so the coefficients are exactly 1 + e and 0. Equal masses give ρ = 1 and a "
              "coefficient of exactly (1 + e)/2.",
      .depends_on = {"beyond.restitution.impulse_coefficients"},
  });
  record.add({
      .id = "beyond.immovable.equals_mass_form",
      .statement = "For finite masses the ratio form equals the mass form.",
      .method = "ρ1 = m1/m2, ρ2 = m2/m1 substituted back; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = lst{first_coefficient_e, second_coefficient_e},
      .derived_expression =
          lst{first_ratio_form.subs(rho1 == s.m1 / s.m2), second_ratio_form.subs(rho2 == s.m2 / s.m1)},
      .paper_display = factored_form(lst{first_coefficient_e, second_coefficient_e}),
      .derived_display = printed_ratio_forms,
      .display_definitions = {{rho1, s.m1 / s.m2}, {rho2, s.m2 / s.m1}},
      .note = "A round trip: the ratio form with ρ1 = m1/m2 and ρ2 = m2/m1 put back, which is how the "
              "kernels compute it. It restates beyond.immovable.mass_ratio_form for finite masses.",
      .depends_on = {"beyond.immovable.mass_ratio_form"},
  });
  const ex first_small_mass_form = (1 + e) * (speed * s.m2) / (s.m1 + s.m2);
  const ex second_small_mass_form = -(1 + e) * (speed * s.m1) / (s.m1 + s.m2);
  record.add({
      .id = "beyond.immovable.small_mass_form",
      .statement = "x1·n − v1·n = (1 + e)((v2 − v1)·n m2)/(m1 + m2), and likewise for ball 2: the mass form "
                   "with the speed multiplied in first.",
      .method = "the coefficients times (v2 − v1)·n; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = lst{first_small_mass_form, second_small_mass_form},
      .derived_expression = lst{first_coefficient_e * speed, second_coefficient_e * speed},
      .paper_display = lst{first_small_mass_form, second_small_mass_form},
      .derived_display = factored_form(lst{first_coefficient_e * speed, second_coefficient_e * speed}),
      .note = "The kernels use it where the ratio form would lose the answer: where the coefficient "
              "(1 + e)/(1 + ρ1) falls below the smallest normal number (ρ1 = m1/m2 beyond about 2^1022 "
              "in double, or infinite) it has rounded into the subnormal range or to 0, although the "
              "change itself may be a normal number (m1 = 1e308, m2 = 0.07). There m2 ≤ 4, so "
              "(v2 − v1)·n m2 cannot overflow, and m1 + m2 rounds to m1 without overflowing.",
      .depends_on = {"beyond.restitution.impulse_coefficients"},
  });
  {
    // m2 = ∞ is ρ1 = 0 and 1/ρ2 = 0: substituted, not a limit.
    const GiNaC::possymbol inverse_rho2("inverse_rho2");
    const ex first_at_wall = first_ratio_form.subs(rho1 == 0);
    const ex second_at_wall =
        GiNaC::normal(second_ratio_form.subs(rho2 == 1 / inverse_rho2)).subs(inverse_rho2 == 0);
    const lst changes{(first_at_wall * speed).subs(lst{e == 1, speed == -s.v1n}), second_at_wall};
    record.add({
        .id = "beyond.immovable.cushion_without_limit",
        .statement = "An infinite mass m2 (ρ1 = 0, 1/ρ2 = 0 substituted, no limit taken) with e = 1 and "
                     "v2 = 0 gives the paper's cushion x1 = v1 − 2 (v1·n) n and leaves ball 2 unmoved.",
        .method = "substitution into the ratio form; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = lst{-2 * s.v1n, 0},
        .derived_expression = changes,
        .paper_display = lst{-2 * s.v1n, 0},
        .derived_display = factored_form(changes),
        .note = "Both masses infinite is not a collision: ρ1 = ∞/∞ is undefined (NaN in floating point).",
        .depends_on = {"beyond.immovable.mass_ratio_form"},
    });
  }
  return {first_ratio_form, second_ratio_form, first_small_mass_form, second_small_mass_form};
}

}  // namespace billiards::derive::parkin2023
