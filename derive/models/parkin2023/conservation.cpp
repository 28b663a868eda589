#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

void end_to_end(Recorder& record, const Setting& setting, const Selection& selection) {
  const Symbols& s = symbols();
  const ex &plus_root = selection.x1n, &x2n_selected = selection.x2n;
  const Definitions& d = setting.definitions;
  const Space& plane = setting.plane;
  const Space& space = setting.space;
  record.section("conservation", "End to end: the result conserves momentum and kinetic energy",
                 "The final x1, x2 in full symbolic components, substituted into P and K.");
  for (const Space* sp : {&plane, &space}) {
    const Vec x1 = sp->after_collision(sp->v1, plus_root), x2 = sp->after_collision(sp->v2, x2n_selected);
    record.add({
        .id = "conservation.momentum" + sp->suffix,
        .paper = "P(v1, v2) = P(x1, x2)",
        .paper_tex = R"tex(P(v_1, v_2) = P(x_1, x_2))tex",
        .statement = "P(x1, x2) = P(v1, v2) for the final x1, x2 (" + std::to_string(sp->dimension) + "-D).",
        .method = "identity after normal(), componentwise",
        .comparison = Comparison::identity,
        .paper_expression = to_lst(momentum(d, sp->v1, sp->v2)),
        .derived_expression = to_lst(momentum(d, x1, x2)),
        .constraints = {sp->unit_normal},
        .paper_label = s.P_of_v,
        .derived_label = s.P_of_x,
        .depends_on = {"result.x1_simplified_form", "result.x2_by_symmetry", "definition.conservation"},
    });
    record.add({
        .id = "conservation.kinetic_energy" + sp->suffix,
        .paper = "K(v1, v2) = K(x1, x2)",
        .paper_tex = R"tex(K(v_1, v_2) = K(x_1, x_2))tex",
        .statement = "K(x1, x2) = K(v1, v2) for the final x1, x2 (" + std::to_string(sp->dimension) +
                     "-D), given n·n = 1.",
        .method = std::string("identity after normal()") + unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = kinetic(d, sp->v1, sp->v2),
        .derived_expression = kinetic(d, x1, x2),
        .constraints = {sp->unit_normal},
        .paper_label = s.K_of_v,
        .derived_label = s.K_of_x,
        .depends_on = {"result.x1_simplified_form", "result.x2_by_symmetry", "definition.conservation"},
    });
  }
}

}  // namespace billiards::derive::parkin2023
