#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

Selection choosing_the_root(Recorder& record, const Quadratic& quadratic, const Discriminant& discriminant,
                            const Roots& roots) {
  const Symbols& s = symbols();
  const ex &x2n_solved = quadratic.x2n_solved, &relative = discriminant.relative;
  const ex &plus_root = roots.plus_root, &minus_root = roots.minus_root;
  record.section("selection", "Choosing the root",
                 "The paper rejects the \"−\" root because x1 would not depend on v2. A stronger "
                 "criterion: the \"−\" root is the state before the collision.");
  const ex x2_of = [&](const ex& x1n) { return GiNaC::normal(x2n_solved.subs(s.x1n == x1n)); }(minus_root);
  record.add({
      .id = "selection.minus_root_independent_of_v2",
      .paper = "\"x1 no longer becomes dependent upon v2\"",
      .statement = "The \"−\" root does not depend on v2·n (the paper's argument).",
      .method = "diff() of the \"−\" root by v2·n; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = 0,
      .derived_expression = GiNaC::diff(minus_root, s.v2n),
      .derived_display = factored_form(GiNaC::diff(minus_root, s.v2n)),
      .depends_on = {"general.x1_both_roots"},
  });
  record.add({
      .id = "selection.minus_root_is_no_collision",
      .paper = "the negative case",
      .statement = "The \"−\" root gives x1·n = v1·n and x2·n = v2·n: x1 = v1 and x2 = v2, no momentum "
                   "exchanged — the state before the collision, which trivially conserves everything.",
      .method = "the \"−\" root and x2·n from momentum; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = lst{s.v1n, s.v2n},
      .derived_expression = lst{minus_root, x2_of},
      .paper_display = lst{s.v1n, s.v2n},
      .derived_display = factored_form(lst{minus_root, x2_of}),
      .note = "Stronger than the paper's intuition: the \"−\" root is not merely implausible, it is "
              "the trivial solution that every pair of conservation laws admits.",
      .depends_on = {"general.x1_both_roots", "quadratic.x2_from_momentum"},
  });
  const ex x2n_selected = GiNaC::normal(x2n_solved.subs(s.x1n == plus_root));
  record.add({
      .id = "selection.plus_root_reverses_relative_normal_velocity",
      .paper = "\"the case we care about must be the positive case\"",
      .statement = "The \"+\" root reverses the relative normal velocity: (x2 − x1)·n = −(v2 − v1)·n.",
      .method = "the \"+\" root and x2·n from momentum; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = -relative,
      .derived_expression = x2n_selected - plus_root,
      .derived_display = factored_form(x2n_selected - plus_root),
      .note = "A perfectly elastic collision in Newton's sense (restitution 1): the balls separate as "
              "fast as they approached.",
      .depends_on = {"general.x1_both_roots", "quadratic.x2_from_momentum"},
  });
  // The "+" root is the collision only for balls that approach: with n from ball 1 to ball 2 and
  // s = (v2 − v1)·n = −σ (σ > 0, approaching), the closing rate afterwards is (x2 − x1)·n = σ ≥ 0.
  const GiNaC::possymbol approach("sigma", "\\sigma");
  const ex separation_after = GiNaC::normal((x2n_selected - plus_root).subs(s.v2n == s.v1n - approach));
  record.add({
      .id = "selection.plus_root_separates_only_approaching_balls",
      .paper = "\"the case we care about must be the positive case\"",
      .statement = "With n pointing from ball 1 to ball 2, the \"+\" root leaves the balls separating, "
                   "(x2 − x1)·n ≥ 0, exactly when they approached, (v2 − v1)·n < 0: it is the collision "
                   "only then; for balls already separating the physical answer is the \"−\" root (nothing "
                   "happens).",
      .method = "sign: v2·n = v1·n − σ with σ > 0 substituted into (x2 − x1)·n of the \"+\" root; it factors "
                "into positive symbols",
      .comparison = Comparison::nonnegative,
      .paper_expression = 0,
      .derived_expression = separation_after,
      .note = "The paper takes the \"+\" root whatever the sign of (v2 − v1)·n, and says the direction of "
              "n does not matter; that holds for the formula, not for the choice of root. "
              "beyond.approaching.resolve_only_approaching makes the choice for any sign.",
      .depends_on = {"definition.masses", "selection.plus_root_reverses_relative_normal_velocity"},
  });
  return {plus_root, x2n_selected};
}

}  // namespace billiards::derive::parkin2023
