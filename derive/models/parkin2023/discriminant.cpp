#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

Discriminant the_discriminant(Recorder& record, const Definitions& d, const Quadratic& quadratic) {
  const Symbols& s = symbols();
  const ex &A = quadratic.A, &B = quadratic.B, &C = quadratic.C;
  const GiNaC::exmap& paper_shorthand = quadratic.paper_shorthand;
  record.section("discriminant", "The discriminant", "D = B² − 4AC from the coefficients read off.");
  const ex D = GiNaC::normal(B * B + d.discriminant_ac_coefficient * A * C);
  const ex relative = s.v2n - s.v1n;  // (v2 − v1)·n
  {
    const ex paper_first = 2 * s.m1 * (1 + s.m1 / s.m2) * s.K_parallel - s.m1 / s.m2 * GiNaC::pow(s.Pn, 2);
    const ex paper_expanded =
        GiNaC::pow(s.m1, 2) * (GiNaC::pow(s.v1n, 2) + GiNaC::pow(s.v2n, 2) - 2 * s.v1n * s.v2n);
    const ex paper_factored = GiNaC::pow(s.m1, 2) * GiNaC::pow(relative, 2);
    const std::vector<std::string> from_coefficients = {"quadratic.coefficient_a", "quadratic.coefficient_b",
                                                        "quadratic.coefficient_c"};
    record.add({
        .id = "discriminant.paper_form",
        .paper = "\"if we examine the discriminant D\"",
        .paper_tex =
            R"tex(D = 2m_1 \left(1 + \frac{m_1}{m_2}\right) K^\parallel - \frac{m_1}{m_2} (P \cdot n)^2)tex",
        .statement = "B² − 4AC = 2 m1 (1 + m1/m2) K∥ − (m1/m2)(P·n)².",
        .method = "B² − 4AC from the coefficients; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = paper_first.subs(paper_shorthand),
        .derived_expression = D,
        .paper_display = paper_first,
        .derived_display = factored_form(D),
        .display_definitions = paper_shorthand,
        .depends_on = from_coefficients,
    });
    record.add({
        .id = "discriminant.expanded",
        .paper = "\"If we continue to expand this\"",
        .paper_tex = R"tex(D = m_1^2 ((v_1 \cdot n)^2 + (v_2 \cdot n)^2 - 2(v_1 \cdot n)(v_2 \cdot n)))tex",
        .statement = "D = m1² ((v1·n)² + (v2·n)² − 2 (v1·n)(v2·n)).",
        .method = "identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = paper_expanded,
        .derived_expression = D,
        .paper_display = paper_expanded,
        .derived_display = factored_form(D),
        .depends_on = from_coefficients,
    });
    record.add({
        .id = "discriminant.factored",
        .paper = "\"it is clear that this factors as\"",
        .paper_tex = R"tex(D = m_1^2 ((v_2 - v_1) \cdot n)^2)tex",
        .statement = "D = m1² ((v2 − v1)·n)².",
        .method = "identity after normal(); factor() of D shown as derived",
        .comparison = Comparison::identity,
        .paper_expression = paper_factored,
        .derived_expression = D,
        .paper_display = paper_factored,
        .derived_display = factored_form(D),
        .depends_on = from_coefficients,
    });
    record.add({
        .id = "discriminant.nonnegative",
        .paper = "\"Immediately we see that D ≥ 0\"",
        .paper_tex = R"tex(D \geq 0)tex",
        .statement = "D ≥ 0: it factors as m1² times a square, so the quadratic always has a real root.",
        .method = "sign: factor() of D is a product of even powers and positive factors",
        .comparison = Comparison::nonnegative,
        .paper_expression = paper_factored,
        .derived_expression = D,
        .paper_display = paper_factored,
        .derived_display = factored_form(D),
        .note = "Masses are positive (GiNaC possymbol); D = 0 exactly when (v2 − v1)·n = 0, a "
                "grazing contact, where both roots coincide and nothing happens.",
        .depends_on = {"definition.masses", "discriminant.factored"},
    });
  }
  return {D, relative};
}

}  // namespace billiards::derive::parkin2023
