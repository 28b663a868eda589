#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

namespace {

// A scalar of the 3-D space (a polynomial in components over the masses) in the normal components:
// v1_z and v2_z written through v1·n and v2·n, then n_z² reduced by n·n = 1. What is left has no
// component of v1, v2 when the scalar depends on them only through v1·n and v2·n.
ex in_normal_components(const ex& scalar, const Space& space) {
  const Symbols& s = symbols();
  const Vec &v1 = space.v1, &v2 = space.v2, &n = space.n;
  const ex through_normal = scalar.subs(lst{v1[2] == (s.v1n - v1[0] * n[0] - v1[1] * n[1]) / n[2],
                                            v2[2] == (s.v2n - v2[0] * n[0] - v2[1] * n[1]) / n[2]});
  const ex numerator_denominator = GiNaC::normal(through_normal).numer_denom();
  const ex numerator = reduce_modulo(numerator_denominator.op(0), space.unit_normal.relation);
  const ex denominator = reduce_modulo(numerator_denominator.op(1), space.unit_normal.relation);
  return GiNaC::normal(numerator / denominator).expand();
}

}  // namespace

Quadratic the_quadratic(Recorder& record, const Setting& setting) {
  const Symbols& s = symbols();
  const Definitions& d = setting.definitions;
  const Space& space = setting.space;
  record.section("quadratic", "The quadratic in x1·n",
                 "Solve momentum conservation along n for x2·n, substitute into energy conservation "
                 "and read the coefficients off with coeff().");
  // The paper's shorthand P·n and K∥, replaced by their definitions before any comparison.
  const GiNaC::exmap paper_shorthand = shorthand(d);
  const ex x2n_solved =
      GiNaC::lsolve(scalar_momentum(d, s.x1n, s.x2n) == scalar_momentum(d, s.v1n, s.v2n), s.x2n);
  record.add({
      .id = "quadratic.x2_from_momentum",
      .paper = "\"Solving for x2∥ in the momentum preservation equation\"",
      .statement = "x2·n = (P·n − m1 (x1·n)) / m2.",
      .method = "lsolve() of P(x1·n, x2·n) = P(v1·n, v2·n) for x2·n; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = ((s.Pn - s.m1 * s.x1n) / s.m2).subs(paper_shorthand),
      .derived_expression = x2n_solved,
      .paper_display = (s.Pn - s.m1 * s.x1n) / s.m2,
      .display_definitions = paper_shorthand,
      .note = "The paper states this step in words only; it is the vector equation "
              "x2∥ = (P∥ − m1 x1∥)/m2 along n.",
      .depends_on = {"along_n.momentum", "along_n.momentum_is_along_n"},
  });
  // The quadratic as the paper first writes it, in vectors: K(x1∥, x2∥) − K∥ with x2∥ from momentum;
  // then the same with every component written through x1·n, v1·n and v2·n: the scalar quadratic.
  ex quadratic;
  {
    const Vec v1_par = parallel_part(space.v1, space.n), v2_par = parallel_part(space.v2, space.n);
    const Vec x1_par = scale(s.x1n, space.n);
    const Vec P_par = momentum(d, v1_par, v2_par);
    // x2∥ lies along n, with the normal component momentum conservation gave.
    const Vec x2_par = scale(space.components_of(x2n_solved), space.n);
    const ex derived_vector_form = kinetic(d, x1_par, x2_par) - kinetic(d, v1_par, v2_par);
    const ex paper_vector_form = numeric(1, 2) * s.m1 * (1 + s.m1 / s.m2) * dot(x1_par, x1_par) -
                                 s.m1 / s.m2 * dot(P_par, x1_par) + dot(P_par, P_par) / (2 * s.m2) -
                                 kinetic(d, v1_par, v2_par);
    record.add({
        .id = "quadratic.vector_form",
        .paper = "the first quadratic (in x1∥)",
        .paper_tex =
            R"tex(0 = \frac{1}{2}m_1 \left(1 + \frac{m_1}{m_2}\right) (x_1^\parallel)^2 - \frac{m_1}{m_2} P^\parallel \cdot x_1^\parallel + \frac{(P^\parallel)^2}{2m_2} - K^\parallel)tex",
        .statement = "K(x1∥, x2∥) − K∥ = ½ m1 (1 + m1/m2)(x1∥)² − (m1/m2) P∥·x1∥ + (P∥)²/(2 m2) − K∥ "
                     "(3-D components).",
        .method = std::string("substitution of x2∥ into K; identity after normal()") + unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = paper_vector_form,
        .derived_expression = derived_vector_form,
        .constraints = {space.unit_normal},
        .paper_display = numeric(1, 2) * s.m1 * (1 + s.m1 / s.m2) * s.x1_parallel_squared -
                         s.m1 / s.m2 * s.P_parallel_dot_x1_parallel + s.P_parallel_squared / (2 * s.m2) -
                         s.K_parallel,
        .derived_label = s.K_of_x_parallel - s.K_parallel,
        .display_definitions = {{s.x1_parallel_squared, dot(x1_par, x1_par)},
                                {s.P_parallel_dot_x1_parallel, dot(P_par, x1_par)},
                                {s.P_parallel_squared, dot(P_par, P_par)},
                                {s.K_parallel, kinetic(d, v1_par, v2_par)}},
        .note = "(x1∥)² means x1∥·x1∥ and P∥ = P(v1∥, v2∥).",
        .depends_on = {"quadratic.x2_from_momentum", "along_n.kinetic_energy"},
    });
    quadratic = in_normal_components(derived_vector_form, space);
  }
  {
    const ex paper_scalar_form = numeric(1, 2) * s.m1 * (1 + s.m1 / s.m2) * GiNaC::pow(s.x1n, 2) -
                                 s.m1 / s.m2 * s.Pn * s.x1n + GiNaC::pow(s.Pn, 2) / (2 * s.m2) - s.K_parallel;
    record.add({
        .id = "quadratic.in_normal_component",
        .paper = "the second quadratic (\"a quadratic equation in the variable x1·n\")",
        .paper_tex =
            R"tex(0 = \frac{1}{2}m_1 \left(1 + \frac{m_1}{m_2}\right) (x_1 \cdot n)^2 - \frac{m_1}{m_2} (P \cdot n)(x_1 \cdot n) + \frac{(P \cdot n)^2}{2m_2} - K^\parallel)tex",
        .statement = "The quadratic is one in x1·n: ½ m1 (1 + m1/m2)(x1·n)² − (m1/m2)(P·n)(x1·n) + "
                     "(P·n)²/(2 m2) − K∥ (checked in 3-D components).",
        .method = std::string("the vector form with v1_z, v2_z written through v1·n, v2·n and reduced "
                              "modulo n_z² = 1 − n_x² − n_y²: a polynomial in x1·n, v1·n, v2·n and the "
                              "masses alone; identity after normal()"),
        .comparison = Comparison::identity,
        .paper_expression = paper_scalar_form.subs(paper_shorthand),
        .derived_expression = quadratic,
        .paper_display = paper_scalar_form,
        .derived_display = factored_form(quadratic),
        .display_definitions = paper_shorthand,
        .depends_on = {"quadratic.vector_form"},
    });
    struct Coefficient {
      const char* id;
      const char* name;
      int power;
      ex printed;
    };
    const Coefficient coefficients[] = {
        {"quadratic.coefficient_a", "A, of (x1·n)²", 2, numeric(1, 2) * s.m1 * (1 + s.m1 / s.m2)},
        {"quadratic.coefficient_b", "B, of x1·n", 1, -s.m1 / s.m2 * s.Pn},
        {"quadratic.coefficient_c", "C, the constant term", 0,
         GiNaC::pow(s.Pn, 2) / (2 * s.m2) - s.K_parallel},
    };
    for (const Coefficient& c : coefficients) {
      record.add({
          .id = c.id,
          .paper = "the quadratic in x1·n",
          .paper_tex =
              R"tex(0 = \frac{1}{2}m_1 \left(1 + \frac{m_1}{m_2}\right) (x_1 \cdot n)^2 - \frac{m_1}{m_2} (P \cdot n)(x_1 \cdot n) + \frac{(P \cdot n)^2}{2m_2} - K^\parallel)tex",
          .statement = std::string("The coefficient ") + c.name + " equals the paper's.",
          .method = "coeff() of the derived quadratic; identity after normal()",
          .comparison = Comparison::identity,
          .paper_expression = c.printed.subs(paper_shorthand),
          .derived_expression = quadratic.coeff(s.x1n, c.power),
          .paper_display = c.printed,
          .derived_display = factored_form(quadratic.coeff(s.x1n, c.power)),
          .display_definitions = paper_shorthand,
          .depends_on = {"quadratic.in_normal_component"},
      });
    }
  }
  return {
      paper_shorthand,          x2n_solved, quadratic, quadratic.coeff(s.x1n, 2), quadratic.coeff(s.x1n, 1),
      quadratic.coeff(s.x1n, 0)};
}

}  // namespace billiards::derive::parkin2023
