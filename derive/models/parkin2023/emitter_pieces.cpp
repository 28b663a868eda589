#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

KernelPieces what_the_emitter_prints(Recorder& record, const Selection& selection) {
  const Symbols& s = symbols();
  const ex &plus_root = selection.x1n, &x2n_selected = selection.x2n;
  ex cushion_change;  // the cushion's change of v1·n, for its kernel below
  record.section("kernels", "What the code emitter prints",
                 "The emitted kernels are scalar functions of the masses and the normal components "
                 "v1·n, v2·n, so they serve vectors of any dimension. Their expressions are read off "
                 "the selected root, never typed again, and every kernel is proven equal to a verified "
                 "claim before it is printed (\"The emitted kernels\" at the end lists which); these "
                 "claims vouch for the pieces.");
  {
    const ex speed = s.relative_normal_speed;
    // Each ball's change of normal velocity, with v2·n written as v1·n + (v2 − v1)·n.
    const ex first_change = GiNaC::normal((plus_root - s.v1n).subs(s.v2n == s.v1n + speed));
    const ex second_change = GiNaC::normal((x2n_selected - s.v2n).subs(s.v2n == s.v1n + speed));
    record.add({
        .id = "kernel.velocity_change_depends_on_relative_normal_speed",
        .statement = "x1·n − v1·n and x2·n − v2·n depend on the velocities only through (v2 − v1)·n.",
        .method = "v2·n = v1·n + (v2 − v1)·n substituted; diff() by v1·n is zero; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = lst{0, 0},
        .derived_expression = lst{GiNaC::diff(first_change, s.v1n), GiNaC::diff(second_change, s.v1n)},
        .paper_display = lst{0, 0},
        .derived_display =
            factored_form(lst{GiNaC::diff(first_change, s.v1n), GiNaC::diff(second_change, s.v1n)}),
        .note = "So the kernel computes the relative normal speed once and scales it.",
        .depends_on = {"result.x1_simplified_form", "result.x2_by_symmetry"},
    });
    const ex first_coefficient = GiNaC::normal(first_change / speed);
    const ex second_coefficient = GiNaC::normal(second_change / speed);
    const ex paper_first = 2 * s.m2 / (s.m1 + s.m2), paper_second = -2 * s.m1 / (s.m1 + s.m2);
    record.add({
        .id = "kernel.impulse_coefficient_first",
        .paper = "\"This form makes it easier to see the impulse magnitude\"",
        .paper_tex = R"tex(x_1 = v_1 + \left(\frac{2m_2}{m_1 + m_2} (v_2 - v_1) \cdot n \right) n)tex",
        .statement = "x1·n − v1·n = (2 m2/(m1 + m2)) (v2 − v1)·n.",
        .method = "(x1·n − v1·n)/((v2 − v1)·n) with the selected root; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = paper_first,
        .derived_expression = first_coefficient,
        .paper_display = paper_first,
        .derived_display = factored_form(first_coefficient),
        .depends_on = {"kernel.velocity_change_depends_on_relative_normal_speed"},
    });
    record.add({
        .id = "kernel.impulse_coefficient_second",
        .paper = "\"By symmetry of the preservation equations\"",
        .statement = "x2·n − v2·n = −(2 m1/(m1 + m2)) (v2 − v1)·n.",
        .method = "(x2·n − v2·n)/((v2 − v1)·n) with x2·n from momentum; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = paper_second,
        .derived_expression = second_coefficient,
        .paper_display = paper_second,
        .derived_display = factored_form(second_coefficient),
        .depends_on = {"kernel.velocity_change_depends_on_relative_normal_speed"},
    });
    // The cushion: the limit m2 → ∞ of the first ball's change with v2 = 0.
    cushion_change = GiNaC::series_to_poly(
        GiNaC::normal((plus_root - s.v1n).subs(lst{s.m2 == 1 / s.inverse_m2, s.v2n == 0}))
            .series(s.inverse_m2 == 0, 1));
    record.add({
        .id = "kernel.cushion_velocity_change",
        .paper = "\"we take the limit as m2 goes to ∞, and let v2 = 0\"",
        .paper_tex = R"tex(x_1 = v_1 - 2(v_1 \cdot n)n)tex",
        .statement = "At a cushion x1·n − v1·n = −2 (v1·n).",
        .method = "series() in ε = 1/m2 about 0 of x1·n − v1·n with v2·n = 0; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = -2 * s.v1n,
        .derived_expression = cushion_change,
        .paper_display = -2 * s.v1n,
        .derived_display = factored_form(cushion_change),
        .depends_on = {"cushion.limit"},
    });
  }

  return {cushion_change};
}

}  // namespace billiards::derive::parkin2023
