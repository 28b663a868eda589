#include "models/parkin2023/steps.hpp"

#include "core/named_constants.hpp"

namespace billiards::derive::parkin2023 {

PlainRange plain_range(Recorder& record, const Restitution& restitution, const MassRatios& ratios) {
  const Symbols& s = symbols();
  const ex e = s.restitution;
  // The mass form of the coefficients, each (1 + e) m_other/(m1 + m2) with one division by the sum;
  // magnitudes (the second coefficient is −(1 + e) m1/(m1 + m2)).
  // factor() keeps 1 + e whole, so the kernels compute it once (restitution_factor) and multiply.
  const ex first_mass_form = GiNaC::factor(GiNaC::normal(restitution.first_coefficient));
  const ex second_mass_form = GiNaC::factor(GiNaC::normal(-restitution.second_coefficient));
  const lst typed{(1 + e) * s.m2 / (s.m1 + s.m2), (1 + e) * s.m1 / (s.m1 + s.m2)};
  const ex rho1 = s.first_mass_ratio, rho2 = s.second_mass_ratio;
  const lst ratio_forms{ratios.first_ratio_form.subs(rho1 == s.m1 / s.m2),
                        -ratios.second_ratio_form.subs(rho2 == s.m2 / s.m1)};
  record.add({
      .id = "beyond.plain_range.one_division_form",
      .statement = "Where both are defined the one-division coefficients (1 + e) m2/(m1 + m2) and "
                   "(1 + e) m1/(m1 + m2) equal the ratio form's (1 + e)/(1 + ρ1) and (1 + e)/(1 + ρ2), "
                   "ρ1 = m1/m2, ρ2 = m2/m1.",
      .method = "the ratio form with ρ1 = m1/m2, ρ2 = m2/m1 substituted, against the restitution "
                "coefficients as typed; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = typed,
      .derived_expression = ratio_forms,
      .paper_display = typed,
      .derived_display = lst{ratios.first_ratio_form, -ratios.second_ratio_form},
      .display_definitions = {{rho1, s.m1 / s.m2}, {rho2, s.m2 / s.m1}},
      .note = "The kernels' fast path: for masses in [m_low, m_high] = [4 √x_min, 1/(4 √x_min)] "
              "(2^−509 to 2^509 in double, 2^−61 to 2^61 in float) they compute these, two divisions "
              "by one sum, and skip the ratio form's five divisions; outside it, or for an infinite "
              "mass, the ratio form is taken. Equal masses and e = 1 still give exactly 1 "
              "(2 m/(2 m)), so the paper's exchange stays exact.",
      .depends_on = {"beyond.immovable.mass_ratio_form", "beyond.restitution.impulse_coefficients"},
  });
  // Why the range keeps every intermediate normal: a ball's share m2/(m1 + m2) of the sum grows with
  // its own mass and falls with the other's, so over the range it is least at m2 = m_low, m1 = m_high.
  const ex share = s.m2 / (s.m1 + s.m2);
  const ex growth = GiNaC::normal(GiNaC::diff(share, s.m2));
  const ex fall = GiNaC::normal(-GiNaC::diff(share, s.m1));
  record.add({
      .id = "beyond.plain_range.share_grows_with_own_mass",
      .statement = "∂/∂m2 of the share m2/(m1 + m2) is m1/(m1 + m2)² ≥ 0.",
      .method = "diff() and normal(); a sign: positive symbols over an even power",
      .comparison = Comparison::nonnegative,
      .paper_expression = s.m1 / GiNaC::pow(s.m1 + s.m2, 2),
      .derived_expression = growth,
      .depends_on = {"definition.masses"},
  });
  record.add({
      .id = "beyond.plain_range.share_falls_with_other_mass",
      .statement = "−∂/∂m1 of the share m2/(m1 + m2) is m2/(m1 + m2)² ≥ 0.",
      .method = "diff() and normal(); a sign: positive symbols over an even power",
      .comparison = Comparison::nonnegative,
      .paper_expression = s.m2 / GiNaC::pow(s.m1 + s.m2, 2),
      .derived_expression = fall,
      .depends_on = {"definition.masses"},
  });
  const ex low = plain_mass_low();
  const ex smallest_share = GiNaC::normal(share.subs(lst{s.m2 == low, s.m1 == 1 / low}));
  record.add({
      .id = "beyond.plain_range.smallest_share",
      .statement = "Over masses in [m_low, 1/m_low] the smallest share is m_low²/(1 + m_low²), at m2 = m_low "
                   "and m1 = 1/m_low.",
      .method = "the share at the corner the two signs above pick; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = GiNaC::pow(low, 2) / (1 + GiNaC::pow(low, 2)),
      .derived_expression = smallest_share,
      .note = "With m_low = 4 √x_min, m_low² = 16 x_min, so every coefficient (1 + e) × share, 1 ≤ 1 + e "
              "≤ 2, is at least 16 x_min/(1 + 16 x_min) > 8 x_min: a normal number, which the relative "
              "speed then multiplies with one rounding. The largest intermediates are (1 + e) m ≤ 2 m_high "
              "and m1 + m2 ≤ 2 m_high = 2^510 (double), far from overflow; the smallest, m1 + m2 ≥ "
              "2 m_low, is normal. So the fast path rounds four times, like the ratio form, and is "
              "finite wherever the speed times 2 is.",
      .depends_on = {"beyond.plain_range.share_grows_with_own_mass",
                     "beyond.plain_range.share_falls_with_other_mass"},
  });
  return {first_mass_form, second_mass_form};
}

}  // namespace billiards::derive::parkin2023
