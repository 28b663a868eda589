#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

void the_cushion(Recorder& record, const Setting& setting, const Selection& selection) {
  const Symbols& s = symbols();
  const ex& plus_root = selection.x1n;
  const Space& plane = setting.plane;
  const Space& space = setting.space;
  const Vec x1_selected = space.after_collision(space.v1, plus_root);
  record.section("cushion", "The cushion: m2 → ∞ with v2·n = 0",
                 "The limit is taken as a series in ε = 1/m2 about 0, first for a wall moving with any v2, "
                 "then for one that does not move along n; the reflection is checked against the "
                 "geometric-algebra sandwich −n v1 n computed with GiNaC's Clifford algebra.");
  {
    // The limit m2 → ∞ of each component of x1, for a wall moving with v2.
    lst moving_limit;
    for (const ex& component : x1_selected) {
      const ex in_epsilon = GiNaC::normal(component.subs(s.m2 == 1 / s.inverse_m2));
      moving_limit.append(GiNaC::series_to_poly(in_epsilon.series(s.inverse_m2 == 0, 1)));
    }
    const Vec moving_wall = add(space.v1, scale(2 * dot(subtract(space.v2, space.v1), space.n), space.n));
    record.add({
        .id = "cushion.moving_wall_limit",
        .statement = "For a wall of mass m2 → ∞ moving with v2, x1 → v1 + 2 ((v2 − v1)·n) n: the ball leaves "
                     "with its relative normal velocity reversed, whatever the wall does across n.",
        .method = "series() in ε = 1/m2 about 0 to order ε⁰ of each component; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = to_lst(moving_wall),
        .derived_expression = moving_limit,
        .constraints = {space.unit_normal},
        .paper_display = s.v1 + 2 * (s.v2n - s.v1n) * s.n,
        .display_definitions = space.normal_components(),
        .display_components = space.vector_components(),
        .note = "The paper quotes the cushion only for v2 = 0; this is the limit it rests on.",
        .depends_on = {"result.x1_simplified_form"},
    });
    // A wall that does not move along n, v2·n = 0: v2_z through the other components, v2 otherwise free.
    const ex across_only = space.v2[2] == -(space.v2[0] * space.n[0] + space.v2[1] * space.n[1]) / space.n[2];
    lst limit;
    for (const ex& component : moving_limit) limit.append(GiNaC::normal(component.subs(across_only)));
    const Vec reflection = subtract(space.v1, scale(2 * dot(space.v1, space.n), space.n));
    record.add({
        .id = "cushion.limit",
        .paper = "\"we take the limit as m2 goes to ∞, and let v2 = 0\"",
        .paper_tex = R"tex(x_1 = v_1 - 2(v_1 \cdot n)n)tex",
        .statement = "With v2·n = 0 (a wall that does not move along n; the paper's v2 = 0 is one), "
                     "x1 → v1 − 2 (v1·n) n as m2 → ∞.",
        .method = "the moving-wall limit with v2_z = −(v2_x n_x + v2_y n_y)/n_z, so v2·n = 0 and v2 is free "
                  "across n; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = to_lst(reflection),
        .derived_expression = limit,
        .constraints = {space.unit_normal},
        .paper_display = s.v1 - 2 * s.v1n * s.n,
        .display_definitions = space.normal_components(),
        .display_components = space.vector_components(),
        .note = "The paper asks for v2 = 0, more than needed: only v2·n = 0 matters (a wall sliding "
                "across n still reflects), and a wall moving along n does not reflect "
                "(cushion.moving_wall_limit).",
        .depends_on = {"cushion.moving_wall_limit"},
    });
    for (const Space* sp : {&plane, &space}) {
      const GiNaC::varidx mu(GiNaC::symbol("mu"), static_cast<unsigned>(sp->dimension));
      GiNaC::lst ones;
      for (std::size_t i = 0; i < sp->dimension; ++i) ones.append(1);
      const ex e = GiNaC::clifford_unit(mu, GiNaC::diag_matrix(ones));
      const ex n_ga = GiNaC::lst_to_clifford(to_lst(sp->n), e);
      const ex v_ga = GiNaC::lst_to_clifford(to_lst(sp->v1), e);
      const ex sandwich = clifford_components((-n_ga * v_ga * n_ga).expand(), e, true);
      record.add({
          .id = "cushion.reflection_is_sandwich" + sp->suffix,
          .paper = "\"= −n v1 n, which we clearly recognize as a reflection\"",
          .paper_tex = R"tex(x_1 = v_1 - 2(v_1 \cdot n)n = -nv_1n)tex",
          .statement = "v1 − 2 (v1·n) n = −n v1 n in geometric algebra (" + std::to_string(sp->dimension) +
                       "-D), given n² = 1.",
          .method = std::string("Clifford product with lst_to_clifford() over a Euclidean metric, read "
                                "back with clifford_to_lst()") +
                    unit_normal_method,
          .comparison = Comparison::identity,
          .paper_expression = to_lst(subtract(sp->v1, scale(2 * dot(sp->v1, sp->n), sp->n))),
          .derived_expression = sandwich,
          .constraints = {sp->unit_normal},
          .paper_display = s.v1 - 2 * s.v1n * s.n,
          .derived_label = -s.sandwich,
          .display_definitions = sp->normal_components(),
          .display_components = sp->vector_components(),
          .note = "In geometric algebra n v n = 2 (n·v) n − (n·n) v, so −n v n is the reflection in "
                  "the plane normal to n only when n² = n·n = 1.",
          .depends_on = {"definition.split"},
      });
    }
  }
}

}  // namespace billiards::derive::parkin2023
