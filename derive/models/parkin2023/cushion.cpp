#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

void the_cushion(Recorder& record, const Setting& setting, const Selection& selection) {
  const Symbols& s = symbols();
  const ex& plus_root = selection.x1n;
  const Space& plane = setting.plane;
  const Space& space = setting.space;
  const Vec x1_selected = space.after_collision(space.v1, plus_root);
  record.section("cushion", "The cushion: m2 → ∞ with v2 = 0",
                 "The limit is taken as a series in ε = 1/m2 about 0; the reflection is checked "
                 "against the geometric-algebra sandwich −n v1 n computed with GiNaC's Clifford "
                 "algebra.");
  {
    GiNaC::exmap wall{{s.m2, 1 / s.inverse_m2}};
    for (const ex& component : space.v2) wall[component] = 0;
    lst limit;
    for (const ex& component : x1_selected) {
      const ex in_epsilon = GiNaC::normal(component.subs(wall));
      limit.append(GiNaC::series_to_poly(in_epsilon.series(s.inverse_m2 == 0, 1)));
    }
    const Vec reflection = subtract(space.v1, scale(2 * dot(space.v1, space.n), space.n));
    record.add({
        .id = "cushion.limit",
        .paper = "\"we take the limit as m2 goes to ∞, and let v2 = 0\"",
        .paper_tex = R"tex(x_1 = v_1 - 2(v_1 \cdot n)n)tex",
        .statement = "With v2 = 0, x1 → v1 − 2 (v1·n) n as m2 → ∞.",
        .method = "series() in ε = 1/m2 about 0 to order ε⁰ of each component; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = to_lst(reflection),
        .derived_expression = limit,
        .constraints = {space.unit_normal},
        .paper_display = s.v1 - 2 * s.v1n * s.n,
        .derived_display =
            s.v1 + factored_form(GiNaC::series_to_poly(
                       GiNaC::normal((plus_root - s.v1n).subs(lst{s.m2 == 1 / s.inverse_m2, s.v2n == 0}))
                           .series(s.inverse_m2 == 0, 1))) *
                       s.n,
        .display_definitions = space.normal_components(),
        .display_components = space.vector_components(),
        .note = "v2 = 0 matters: the limit of x1 for a moving wall is v1 + 2((v2 − v1)·n) n.",
        .depends_on = {"result.x1_simplified_form"},
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
