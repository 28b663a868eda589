#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

void sanity_checks(Recorder& record, const Setting& setting, const Selection& selection) {
  const Symbols& s = symbols();
  const Space& space = setting.space;
  const ex &plus_root = selection.x1n, &x2n_selected = selection.x2n;
  const Vec x1_selected = space.after_collision(space.v1, plus_root);
  const Vec x2_selected = space.after_collision(space.v2, x2n_selected);
  record.section("sanity", "The paper's sanity checks",
                 "Equal masses with the first ball at rest, then head-on (3-D components).");
  {
    GiNaC::exmap at_rest{{s.m2, s.m1}};
    for (const ex& component : space.v1) at_rest[component] = 0;
    const Vec v2_par = parallel_part(space.v2, space.n);
    // The same substitutions in the scalar form x = v + κ n, for the audit.
    const ex x1_shown = s.v1 + factored_form(plus_root - s.v1n) * s.n;
    const ex x2_shown = s.v2 + factored_form(x2n_selected - s.v2n) * s.n;
    const ex at_rest_shown = lst{s.m2 == s.m1, s.v1 == 0, s.v1n == 0};
    const ex head_on_shown =
        lst{s.m2 == s.m1, s.v1 == 0, s.v1n == 0, s.v2 == s.head_on_speed * s.n, s.v2n == s.head_on_speed};
    record.add({
        .id = "sanity.equal_masses_at_rest.x1",
        .paper = "\"m1 = m2 and v1 = 0\"",
        .paper_tex = R"tex(x_1 = (v_2 \cdot n)n = v_2^{\parallel})tex",
        .statement = "m1 = m2, v1 = 0: x1 = (v2·n) n = v2∥.",
        .method = std::string("subs() into the derived x1; identity after normal()") + unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = to_lst(v2_par),
        .derived_expression = to_lst(x1_selected).subs(at_rest),
        .constraints = {space.unit_normal},
        .paper_display = s.v2n * s.n,
        .derived_display = factored_form(x1_shown.subs(at_rest_shown)),
        .display_definitions = space.normal_components(),
        .display_components = space.vector_components(),
        .depends_on = {"result.x1_simplified_form"},
    });
    record.add({
        .id = "sanity.equal_masses_at_rest.x2",
        .paper = "\"we find that x2 = v2 − v2∥\"",
        .paper_tex = R"tex(x_2 = v_2 - v_2^{\parallel})tex",
        .statement = "m1 = m2, v1 = 0: x2 = v2 − v2∥.",
        .method = std::string("subs() into the derived x2; identity after normal()") + unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = to_lst(subtract(space.v2, v2_par)),
        .derived_expression = to_lst(x2_selected).subs(at_rest),
        .constraints = {space.unit_normal},
        .paper_display = s.v2 - s.v2n * s.n,
        .derived_display = x2_shown.subs(at_rest_shown),
        .display_definitions = space.normal_components(),
        .display_components = space.vector_components(),
        .depends_on = {"result.x2_by_symmetry"},
    });
    GiNaC::exmap head_on = at_rest;
    for (std::size_t i = 0; i < space.dimension; ++i) head_on[space.v2[i]] = s.head_on_speed * space.n[i];
    const Vec v2_head_on = scale(s.head_on_speed, space.n);
    record.add({
        .id = "sanity.head_on.x1",
        .paper = "\"If the first ball was hit head-on\"",
        .paper_tex = R"tex(x_1 = v_2)tex",
        .statement = "m1 = m2, v1 = 0, v2 = c n: x1 = v2, the first ball takes all the velocity.",
        .method = std::string("subs() into the derived x1; identity after normal()") + unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = to_lst(v2_head_on),
        .derived_expression = to_lst(x1_selected).subs(head_on),
        .constraints = {space.unit_normal},
        .paper_display = s.v2,
        .derived_display = factored_form(x1_shown.subs(head_on_shown)),
        .display_definitions = merged({space.normal_components(), {{s.v2, s.head_on_speed * s.n}}}),
        .display_components = space.vector_components(),
        .depends_on = {"sanity.equal_masses_at_rest.x1"},
    });
    record.add({
        .id = "sanity.head_on.x2",
        .paper = "\"we get x2 = 0\"",
        .paper_tex = R"tex(x_2 = 0)tex",
        .statement = "m1 = m2, v1 = 0, v2 = c n: x2 = 0, the second ball stops.",
        .method = std::string("subs() into the derived x2; identity after normal()") + unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = to_lst(scale(0, space.n)),
        .derived_expression = to_lst(x2_selected).subs(head_on),
        .constraints = {space.unit_normal},
        .paper_display = 0,
        .derived_display = factored_form(x2_shown.subs(head_on_shown)),
        .display_definitions = space.normal_components(),
        .display_components = space.vector_components(),
        .depends_on = {"sanity.equal_masses_at_rest.x2"},
    });
  }
}

}  // namespace billiards::derive::parkin2023
