#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

void the_collision_formula(Recorder& record, const Setting& setting, const Discriminant& discriminant,
                           const Selection& selection) {
  const Symbols& s = symbols();
  const Space& space = setting.space;
  const ex &plus_root = selection.x1n, &x2n_selected = selection.x2n, &relative = discriminant.relative;
  record.section("result", "The collision formula",
                 "The selected root in the paper's expanded and simplified forms, x2 by symmetry, "
                 "and independence of the sign of n (3-D components).");
  const Vec x1_selected = space.after_collision(space.v1, plus_root);
  const Vec x2_selected = space.after_collision(space.v2, x2n_selected);
  const ex simplified_coefficient = 2 * s.m2 / (s.m1 + s.m2) * relative;
  const auto paper_simplified = [&](const Space& sp) {
    return add(sp.v1, scale(sp.components_of(simplified_coefficient), sp.n));
  };
  {
    const ex expanded_coefficient =
        2 * s.m2 / (s.m1 + s.m2) * s.v2n + ((s.m1 - s.m2) / (s.m1 + s.m2) - 1) * s.v1n;
    record.add({
        .id = "result.x1_expanded_form",
        .paper = "\"In that case, we get\"",
        .paper_tex =
            R"tex(x_1 = v_1 + \left(\frac{2m_2}{m_1 + m_2} (v_2 \cdot n) + \left(\frac{m_1 - m_2}{m_1 + m_2} - 1 \right) (v_1 \cdot n) \right) n)tex",
        .statement = "x1 = v1 + (2m2/(m1 + m2) (v2·n) + ((m1 − m2)/(m1 + m2) − 1)(v1·n)) n.",
        .method = "x1 = v1⊥ + (x1·n) n with the \"+\" root; identity after normal(), componentwise",
        .comparison = Comparison::identity,
        .paper_expression = to_lst(add(space.v1, scale(space.components_of(expanded_coefficient), space.n))),
        .derived_expression = to_lst(x1_selected),
        .constraints = {space.unit_normal},
        .paper_display = s.v1 + expanded_coefficient * s.n,
        .derived_display = s.v1 + factored_form(plus_root - s.v1n) * s.n,
        .display_definitions = space.normal_components(),
        .display_components = space.vector_components(),
        .depends_on = {"selection.plus_root_reverses_relative_normal_velocity",
                       "selection.minus_root_is_no_collision"},
    });
    record.add({
        .id = "result.x1_simplified_form",
        .paper = "\"The equation simplifies further as\"",
        .paper_tex = R"tex(x_1 = v_1 + \left(\frac{2m_2}{m_1 + m_2} (v_2 - v_1) \cdot n \right) n)tex",
        .statement = "x1 = v1 + (2 m2/(m1 + m2)) ((v2 − v1)·n) n.",
        .method = "identity after normal(), componentwise",
        .comparison = Comparison::identity,
        .paper_expression = to_lst(paper_simplified(space)),
        .derived_expression = to_lst(x1_selected),
        .constraints = {space.unit_normal},
        .paper_display = s.v1 + simplified_coefficient * s.n,
        .derived_display = s.v1 + factored_form(plus_root - s.v1n) * s.n,
        .display_definitions = space.normal_components(),
        .display_components = space.vector_components(),
        .depends_on = {"result.x1_expanded_form"},
    });
  }
  // The paper: "By symmetry ... Just replace subscript 1 with 2 and vice-versa."
  const auto swap_balls = [&](const Space& sp) {
    GiNaC::exmap swap{{s.m1, s.m2}, {s.m2, s.m1}};
    for (std::size_t i = 0; i < sp.dimension; ++i) {
      swap[sp.v1[i]] = sp.v2[i];
      swap[sp.v2[i]] = sp.v1[i];
    }
    return swap;
  };
  record.add({
      .id = "result.x2_by_symmetry",
      .paper = "\"By symmetry of the preservation equations\"",
      .statement = "x2 from momentum conservation equals the paper's x1 with subscripts 1 and 2 "
                   "swapped: x2 = v2 + (2 m1/(m1 + m2)) ((v1 − v2)·n) n.",
      .method = "x2 = v2⊥ + (x2·n) n with x2·n from momentum; the paper's x1 with 1 ↔ 2 by "
                "simultaneous subs(); identity after normal(), componentwise",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(paper_simplified(space)).subs(swap_balls(space)),
      .derived_expression = to_lst(x2_selected),
      .constraints = {space.unit_normal},
      .paper_display = s.v2 + 2 * s.m1 / (s.m1 + s.m2) * (s.v1n - s.v2n) * s.n,
      .derived_display = s.v2 + factored_form(x2n_selected - s.v2n) * s.n,
      .display_definitions = space.normal_components(),
      .display_components = space.vector_components(),
      .depends_on = {"result.x1_simplified_form", "quadratic.x2_from_momentum"},
  });
  {
    GiNaC::exmap flip;
    for (const ex& component : space.n) flip[component] = -component;
    record.add({
        .id = "result.independent_of_normal_sign",
        .paper = "\"it didn't matter which direction n pointed\"",
        .statement = "Replacing n by −n leaves x1 and x2 unchanged.",
        .method = "subs() n → −n in the derived x1, x2; identity after normal(), componentwise",
        .comparison = Comparison::identity,
        .paper_expression = concatenate(x1_selected, x2_selected),
        .derived_expression = concatenate(x1_selected, x2_selected).subs(flip),
        .paper_label = s.results,
        .derived_label = s.results_flipped,
        .depends_on = {"result.x1_simplified_form", "result.x2_by_symmetry"},
    });
  }
}

}  // namespace billiards::derive::parkin2023
