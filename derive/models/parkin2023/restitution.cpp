#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

Restitution restitution(Recorder& record, const Definitions& d) {
  const Symbols& s = symbols();
  const ex e = s.restitution;
  const ex speed = s.relative_normal_speed;
  const auto through_speed = [&](const ex& x) { return GiNaC::normal(x.subs(s.v2n == s.v1n + speed)); };
  // Momentum conservation and Newton's law of restitution, solved for the normal components.
  const ex restitution_solution =
      GiNaC::lsolve(lst{scalar_momentum(d, s.x1n, s.x2n) == scalar_momentum(d, s.v1n, s.v2n),
                        s.x2n - s.x1n == -e * (s.v2n - s.v1n)},
                    lst{s.x1n, s.x2n});
  const ex x1n_e = GiNaC::normal(ex(s.x1n).subs(restitution_solution));
  const ex x2n_e = GiNaC::normal(ex(s.x2n).subs(restitution_solution));
  const ex paper_x1n = s.v1n + 2 * s.m2 / (s.m1 + s.m2) * (s.v2n - s.v1n);
  const ex paper_x2n = s.v2n + 2 * s.m1 / (s.m1 + s.m2) * (s.v1n - s.v2n);
  const std::vector<std::string> restitution_premises = {"definition.momentum", "definition.restitution"};
  record.add({
      .id = "beyond.restitution.elastic_is_the_paper",
      .statement = "With restitution e = 1, momentum conservation and Newton's law give exactly the "
                   "paper's selected result.",
      .method = "lsolve() of m1 x1·n + m2 x2·n = P·n and (x2 − x1)·n = −e (v2 − v1)·n; e = 1 "
                "substituted; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = lst{paper_x1n, paper_x2n},
      .derived_expression = lst{x1n_e.subs(e == 1), x2n_e.subs(e == 1)},
      .paper_display = lst{paper_x1n, paper_x2n},
      .derived_display = factored_form(lst{x1n_e.subs(e == 1), x2n_e.subs(e == 1)}),
      .depends_on = restitution_premises,
  });
  record.add({
      .id = "beyond.restitution.elastic_conserves_energy",
      .statement = "With e = 1 the kinetic energy is conserved.",
      .method = "K of the solved normal components at e = 1; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = scalar_kinetic(d, s.v1n, s.v2n),
      .derived_expression = scalar_kinetic(d, x1n_e, x2n_e).subs(e == 1),
      .paper_display = s.K_parallel,
      .derived_label = s.K_of_x_parallel,
      .display_definitions = shorthand(d),
      .depends_on = {"beyond.restitution.elastic_is_the_paper", "definition.kinetic_energy"},
  });
  const ex reduced_mass = s.m1 * s.m2 / (s.m1 + s.m2);
  const ex energy_loss = GiNaC::normal(scalar_kinetic(d, s.v1n, s.v2n) - scalar_kinetic(d, x1n_e, x2n_e));
  const ex printed_loss = numeric(1, 2) * reduced_mass * (1 - e * e) * GiNaC::pow(s.v2n - s.v1n, 2);
  record.add({
      .id = "beyond.restitution.energy_loss",
      .statement = "The kinetic energy lost is ½ μ (1 − e²) ((v2 − v1)·n)², μ = m1 m2/(m1 + m2).",
      .method = "K before minus K after, the solved normal components; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = printed_loss,
      .derived_expression = energy_loss,
      .paper_display = printed_loss,
      .derived_display = factored_form(energy_loss),
      .depends_on = {"beyond.restitution.elastic_is_the_paper", "definition.kinetic_energy"},
  });
  const GiNaC::possymbol t("t");
  record.add({
      .id = "beyond.restitution.energy_loss_nonnegative",
      .statement = "For 0 ≤ e ≤ 1 no energy is created: the loss is ≥ 0 (zero at e = 1).",
      .method = "sign: e = t/(1 + t) with t ≥ 0 covers [0, 1); factor() of the loss is then a product "
                "of positive factors and even powers; e = 1 is beyond.restitution.elastic_conserves_energy",
      .comparison = Comparison::nonnegative,
      .paper_expression = 0,
      .derived_expression = GiNaC::normal(energy_loss.subs(e == t / (1 + t))),
      .paper_display = 0,
      .derived_display = factored_form(energy_loss.subs(e == t / (1 + t))),
      .depends_on = {"beyond.restitution.energy_loss"},
  });
  record.add({
      .id = "beyond.restitution.perfectly_inelastic",
      .statement = "With e = 0 the balls leave with equal normal velocities: x1·n = x2·n.",
      .method = "e = 0 substituted; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = 0,
      .derived_expression = (x2n_e - x1n_e).subs(e == 0),
      .paper_display = 0,
      .derived_display = factored_form((x2n_e - x1n_e).subs(e == 0)),
      .note = "This restates Newton's law of restitution (definition.restitution) at e = 0, which the "
              "solution was solved from: it checks lsolve(), not new physics.",
      .depends_on = {"beyond.restitution.elastic_is_the_paper"},
  });
  const ex first_coefficient_e = GiNaC::normal(through_speed(x1n_e - s.v1n) / speed);
  const ex second_coefficient_e = GiNaC::normal(through_speed(x2n_e - s.v2n) / speed);
  const lst printed_coefficients{(1 + e) * s.m2 / (s.m1 + s.m2), -(1 + e) * s.m1 / (s.m1 + s.m2)};
  record.add({
      .id = "beyond.restitution.impulse_coefficients",
      .statement = "x1·n − v1·n = (1 + e) m2/(m1 + m2) (v2 − v1)·n and x2·n − v2·n = −(1 + e) m1/(m1 + "
                   "m2) (v2 − v1)·n: the change depends on the velocities only through (v2 − v1)·n.",
      .method = "v2·n = v1·n + (v2 − v1)·n substituted, divided by (v2 − v1)·n; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = printed_coefficients,
      .derived_expression = lst{first_coefficient_e, second_coefficient_e},
      .paper_display = printed_coefficients,
      .derived_display = factored_form(lst{first_coefficient_e, second_coefficient_e}),
      .depends_on = {"beyond.restitution.elastic_is_the_paper"},
  });
  return {x1n_e, x2n_e, first_coefficient_e, second_coefficient_e};
}

}  // namespace billiards::derive::parkin2023
