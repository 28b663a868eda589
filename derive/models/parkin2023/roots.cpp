#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

Roots the_roots(Recorder& record, const Quadratic& quadratic, const Discriminant& discriminant) {
  const Symbols& s = symbols();
  const ex &A = quadratic.A, &B = quadratic.B, &D = discriminant.D, &relative = discriminant.relative;
  const GiNaC::exmap& paper_shorthand = quadratic.paper_shorthand;
  record.section("roots", "The roots",
                 "The quadratic formula (−B ± √D)/(2A), with √D = m1 |(v2 − v1)·n| for m1 > 0.");
  const ex root_of_D = square_root_of_perfect_square(D);
  const lst roots{GiNaC::normal((-B + root_of_D) / (2 * A)), GiNaC::normal((-B - root_of_D) / (2 * A))};
  // The paper's roots, as printed, with |(v2 − v1)·n|.
  const ex printed_abs = s.m2 * GiNaC::abs(relative);
  const lst paper_roots{(s.Pn + printed_abs) / (s.m1 + s.m2), (s.Pn - printed_abs) / (s.m1 + s.m2)};
  const lst paper_roots_no_abs{(s.Pn + s.m2 * relative) / (s.m1 + s.m2),
                               (s.Pn - s.m2 * relative) / (s.m1 + s.m2)};
  // Cases on the sign of (v2 − v1)·n: write v2·n = v1·n + s and resolve every |…| for s ≥ 0, s < 0.
  const auto in_case = [&](const ex& e, int sign) {
    return GiNaC::normal(
        resolve_absolute_values(e.subs(paper_shorthand).subs(s.v2n == s.v1n + s.relative_normal_speed),
                                s.relative_normal_speed, sign));
  };
  const auto in_case_lst = [&](const lst& l, int sign) {
    lst out;
    for (const ex& e : l) out.append(in_case(e, sign));
    return out;
  };
  struct SignCase {
    const char* suffix;
    const char* words;
    int sign;
  };
  const SignCase sign_cases[] = {{"relative_speed_nonnegative", "(v2 − v1)·n ≥ 0", +1},
                                 {"relative_speed_negative", "(v2 − v1)·n < 0", -1}};
  for (const SignCase& c : sign_cases) {
    record.add({
        .id = std::string("roots.quadratic_formula.") + c.suffix,
        .paper = "\"Applying our quadratic formula\"",
        .paper_tex = R"tex(x_1 \cdot n = \frac{P \cdot n \pm m_2 |(v_2 - v_1) \cdot n|}{m_1 + m_2})tex",
        .statement = std::string("For ") + c.words +
                     ", the roots (−B ± √D)/(2A) are (P·n ± m2 |(v2 − v1)·n|)/(m1 + m2), sign for sign.",
        .method = "quadratic formula with √D from factor(); v2·n = v1·n + s, |…| resolved for the "
                  "sign of s; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = in_case_lst(paper_roots, c.sign),
        .derived_expression = in_case_lst(roots, c.sign),
        .paper_display = factored_form(in_case_lst(paper_roots, c.sign)),
        .derived_display = factored_form(in_case_lst(roots, c.sign)),
        .depends_on = {"definition.masses", "discriminant.factored", "discriminant.nonnegative"},
    });
    record.add({
        .id = std::string("roots.absolute_value_dropped.") + c.suffix,
        .paper = "\"we could drop the absolute value because of the plus or minus\"",
        .paper_tex =
            R"tex(x_1 = v_1 + \left(\frac{P \cdot n \pm m_2 (v_2 - v_1) \cdot n}{m_1 + m_2} - v_1 \cdot n \right) n)tex",
        .statement = std::string("For ") + c.words +
                     ", the set of roots equals {(P·n ± m2 (v2 − v1)·n)/(m1 + m2)}: dropping |…| "
                     "only swaps the two roots.",
        .method = "same set: identity after normal() for some pairing",
        .comparison = Comparison::same_set,
        .paper_expression = in_case_lst(paper_roots_no_abs, c.sign),
        .derived_expression = in_case_lst(roots, c.sign),
        .paper_display = factored_form(in_case_lst(paper_roots_no_abs, c.sign)),
        .derived_display = factored_form(in_case_lst(roots, c.sign)),
        .note = c.sign > 0 ? "Here the pairing is sign for sign." : "Here ± pair crosswise.",
        .depends_on = {std::string("roots.quadratic_formula.") + c.suffix},
    });
  }
  // The roots with |…| dropped, as derived: the s ≥ 0 case, written back in v2·n.
  const auto without_abs = [&](const ex& root) {
    return GiNaC::normal(in_case(root, +1).subs(s.relative_normal_speed == relative));
  };
  return {without_abs(roots.op(0)), without_abs(roots.op(1))};
}

}  // namespace billiards::derive::parkin2023
