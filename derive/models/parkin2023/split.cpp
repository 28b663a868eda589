#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

void split_along_and_across(Recorder& record, const Setting& setting) {
  const Symbols& s = symbols();
  const Definitions& d = setting.definitions;
  const Space& plane = setting.plane;
  const Space& space = setting.space;
  record.section("split", "Splitting P and K along and across n",
                 "The paper: \"it is not hard to show that P(x1, x2) = P(x1∥, x2∥) + P(x1⊥, x2⊥)\" "
                 "and the same for K. Shown in full components.");
  for (const Space* sp : {&plane, &space}) {
    const Vec x1_par = parallel_part(sp->x1, sp->n), x2_par = parallel_part(sp->x2, sp->n);
    const Vec x1_perp = perpendicular_part(sp->x1, sp->n), x2_perp = perpendicular_part(sp->x2, sp->n);
    record.add({
        .id = "split.momentum" + sp->suffix,
        .paper = "the split of P (\"it is not hard to show that\")",
        .paper_tex = R"tex(P(x_1, x_2) = P(x_1^\parallel, x_2^\parallel) + P(x_1^\perp, x_2^\perp))tex",
        .statement =
            "P(x1, x2) = P(x1∥, x2∥) + P(x1⊥, x2⊥) in " + std::to_string(sp->dimension) + "-D components.",
        .method = "identity after expand(), componentwise",
        .comparison = Comparison::identity,
        .paper_expression = to_lst(momentum(d, sp->x1, sp->x2)),
        .derived_expression = to_lst(add(momentum(d, x1_par, x2_par), momentum(d, x1_perp, x2_perp))),
        .paper_label = s.P_of_x,
        .derived_label = s.P_split,
        .note = "P is linear, so the split holds for any n; it needs only a = a∥ + a⊥.",
        .depends_on = {"definition.momentum", "definition.split"},
    });
    record.add({
        .id = "split.kinetic_cross_term" + sp->suffix,
        .paper = "footnote 1 (\"P and K are bilinear functions\")",
        .statement = "a∥·b⊥ = 0 for any a, b when n·n = 1: the cross terms of K vanish.",
        .method = std::string("identity after expand()") + unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = 0,
        .derived_expression = dot(x1_par, x2_perp),
        .constraints = {sp->unit_normal},
        .paper_display = 0,
        .derived_label = s.a_par_dot_b_perp,
        .note = "The footnote calls P and K \"bilinear\". P is linear and K is a quadratic form; "
                "K(a, b) splits because (a∥ + a⊥)² = (a∥)² + 2 a∥·a⊥ + (a⊥)² and the cross term "
                "a∥·a⊥ is zero when n is a unit vector.",
        .depends_on = {"definition.split"},
    });
    record.add({
        .id = "split.kinetic" + sp->suffix,
        .paper = "the split of K (\"it is not hard to show that\")",
        .paper_tex = R"tex(K(x_1, x_2) = K(x_1^\parallel, x_2^\parallel) + K(x_1^\perp, x_2^\perp))tex",
        .statement = "K(x1, x2) = K(x1∥, x2∥) + K(x1⊥, x2⊥) in " + std::to_string(sp->dimension) +
                     "-D components, given n·n = 1.",
        .method = std::string("identity after expand()") + unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = kinetic(d, sp->x1, sp->x2),
        .derived_expression = kinetic(d, x1_par, x2_par) + kinetic(d, x1_perp, x2_perp),
        .constraints = {sp->unit_normal},
        .paper_label = s.K_of_x,
        .derived_label = s.K_split,
        .note = "Holds only because n is a unit vector: without n·n = 1 the parallel part carries a "
                "factor (n·n)² and the cross terms do not cancel.",
        .depends_on = {"definition.kinetic_energy", "definition.split",
                       "split.kinetic_cross_term" + sp->suffix},
    });
  }
}

}  // namespace billiards::derive::parkin2023
