#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

Approaching approaching_contacts(Recorder& record, const Definitions& d, const Selection& selection,
                                 const Restitution& restitution) {
  const Symbols& s = symbols();
  const ex e = s.restitution;
  const ex speed = s.relative_normal_speed;
  const auto through_speed = [&](const ex& x) { return GiNaC::normal(x.subs(s.v2n == s.v1n + speed)); };
  const ex &x1n_e = restitution.x1n, &x2n_e = restitution.x2n, &plus_root = selection.x1n;
  const ex& c1 = restitution.first_coefficient;
  // Approaching contacts.
  record.add({
      .id = "beyond.approaching.collision_root_separates",
      .statement = "With n pointing from ball 1 to ball 2 the gap closes iff (v2 − v1)·n < 0. After the "
                   "collision (x2 − x1)·n = −e (v2 − v1)·n, which is ≥ 0 then: the non-trivial root "
                   "separates the balls (e > 0) exactly when they approach.",
      .method = "the solved normal components; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = -e * (s.v2n - s.v1n),
      .derived_expression = x2n_e - x1n_e,
      .paper_display = -e * (s.v2n - s.v1n),
      .derived_display = factored_form(x2n_e - x1n_e),
      .note = "This restates Newton's law of restitution (definition.restitution), which the solution was "
              "solved from; what it adds is the reading: for e > 0 the balls separate after the collision "
              "exactly when they approached before it.",
      .depends_on = {"beyond.restitution.elastic_is_the_paper"},
  });
  // The kernel form for any e: c1 (s − |s|)/2, which is c1 s when s < 0 and 0 when s ≥ 0.
  const ex approach_speed = (speed - GiNaC::abs(speed)) / 2;
  {
    // x1·n = (P·n − m2 |(v2 − v1)·n|)/(m1 + m2): the collision root when approaching, else v1·n.
    const ex minus_abs_root =
        (scalar_momentum(d, s.v1n, s.v2n) - s.m2 * GiNaC::abs(s.v2n - s.v1n)) / (s.m1 + s.m2);
    const auto in_sign = [&](const ex& x, int sign) {
      return GiNaC::normal(resolve_absolute_values(through_speed(x), speed, sign));
    };
    const lst cases{in_sign(minus_abs_root, -1), in_sign(minus_abs_root, +1)};
    const lst expected{through_speed(plus_root), s.v1n};
    record.add({
        .id = "beyond.approaching.resolve_only_approaching",
        .statement = "Resolving only approaching contacts is always taking x1·n = (P·n − m2 |(v2 − v1)·n|)/"
                     "(m1 + m2): the paper's collision root when (v2 − v1)·n < 0, and x1·n = v1·n (nothing "
                     "happens) when (v2 − v1)·n ≥ 0.",
        .method = "v2·n = v1·n + s, |s| resolved for s < 0 and s ≥ 0; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = expected,
        .derived_expression = cases,
        .paper_display = factored_form(expected),
        .derived_display = factored_form(cases),
        .depends_on = {"beyond.approaching.collision_root_separates", "result.x1_simplified_form"},
    });
    const lst kernel_cases{GiNaC::normal(resolve_absolute_values(c1 * approach_speed, speed, -1)),
                           GiNaC::normal(resolve_absolute_values(c1 * approach_speed, speed, +1))};
    const lst kernel_expected{through_speed(x1n_e - s.v1n), 0};
    record.add({
        .id = "beyond.approaching.kernel_form",
        .statement = "For any e, x1·n − v1·n = c1 ((v2 − v1)·n − |(v2 − v1)·n|)/2: the collision when the "
                     "balls approach, zero when they separate (likewise for ball 2).",
        .method = "|s| resolved for s < 0 and s ≥ 0; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = kernel_expected,
        .derived_expression = kernel_cases,
        .paper_display = lst{s.c1 * s.relative_normal_speed, 0},
        .derived_display = factored_form(kernel_cases),
        .display_definitions = {{s.c1, c1}},
        .depends_on = {"beyond.approaching.collision_root_separates",
                       "beyond.restitution.impulse_coefficients"},
    });
  }

  return {approach_speed};
}

}  // namespace billiards::derive::parkin2023
