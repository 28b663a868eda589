#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

void putting_it_together(Recorder& record, const Setting& setting, const Quadratic& quadratic,
                         const Discriminant& discriminant, const Roots& roots) {
  const Symbols& s = symbols();
  const ex& relative = discriminant.relative;
  const GiNaC::exmap& paper_shorthand = quadratic.paper_shorthand;
  const ex &plus_root = roots.plus_root, &minus_root = roots.minus_root;
  const Space& space = setting.space;
  record.section("general", "Putting it together", "x1 = v1⊥ + (x1·n) n with either root (3-D components).");
  {
    const ex printed_coefficient_plus = (s.Pn + s.m2 * relative) / (s.m1 + s.m2) - s.v1n;
    const ex printed_coefficient_minus = (s.Pn - s.m2 * relative) / (s.m1 + s.m2) - s.v1n;
    const auto paper_x1 = [&](const ex& coefficient) {
      return add(space.v1, scale(space.components_of(coefficient.subs(paper_shorthand)), space.n));
    };
    record.add({
        .id = "general.x1_both_roots",
        .paper = "\"Putting it all together now\"",
        .paper_tex =
            R"tex(x_1 = v_1^\perp + (x_1 \cdot n)n = v_1 + \left(\frac{P \cdot n \pm m_2 (v_2 - v_1) \cdot n}{m_1 + m_2} - v_1 \cdot n \right) n)tex",
        .statement = "x1 = v1 + ((P·n ± m2 (v2 − v1)·n)/(m1 + m2) − v1·n) n for either root.",
        .method = std::string("x1 = v1⊥ + (x1·n) n with each root; identity after normal(), "
                              "componentwise") +
                  unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression =
            concatenate(paper_x1(printed_coefficient_plus), paper_x1(printed_coefficient_minus)),
        .derived_expression = concatenate(space.after_collision(space.v1, plus_root),
                                          space.after_collision(space.v1, minus_root)),
        .constraints = {space.unit_normal},
        .paper_display = lst{s.v1 + printed_coefficient_plus * s.n, s.v1 + printed_coefficient_minus * s.n},
        .derived_display = lst{s.v1 + factored_form(plus_root - s.v1n) * s.n,
                               s.v1 + factored_form(minus_root - s.v1n) * s.n},
        .display_definitions = merged({paper_shorthand, space.normal_components()}),
        .display_components = space.vector_components(),
        .depends_on = {"roots.absolute_value_dropped.relative_speed_nonnegative",
                       "roots.absolute_value_dropped.relative_speed_negative",
                       "assumption.tangential_velocity_unchanged"},
    });
  }
}

}  // namespace billiards::derive::parkin2023
