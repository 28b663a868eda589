#include "derivation.hpp"

#include "core/algebra.hpp"
#include "core/named_constants.hpp"
#include "print/printer.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace billiards::derive {

using GiNaC::ex;
using GiNaC::lst;
using GiNaC::numeric;

namespace {

// The scalar names of the derivation. Static: GiNaC tells symbols apart by identity, so every step
// (and every run in one process) must use the same ones.
struct Symbols {
  GiNaC::possymbol m1{"m1", "m_1"};
  GiNaC::possymbol m2{"m2", "m_2"};
  GiNaC::realsymbol v1n{"v1n", "(v_1 \\cdot n)"};
  GiNaC::realsymbol v2n{"v2n", "(v_2 \\cdot n)"};
  GiNaC::realsymbol x1n{"x1n", "(x_1 \\cdot n)"};
  GiNaC::realsymbol x2n{"x2n", "(x_2 \\cdot n)"};
  GiNaC::realsymbol relative_normal_speed{"relative_normal_speed", "((v_2 - v_1) \\cdot n)"};
  GiNaC::realsymbol head_on_speed{"c", "c"};
  GiNaC::possymbol inverse_m2{"epsilon", "\\varepsilon"};
  // The paper's shorthand, P·n and K∥, as printed; replaced by their definitions before comparing.
  GiNaC::symbol Pn{"Pn", "(P \\cdot n)"};
  GiNaC::symbol K_parallel{"Kpar", "K^{\\parallel}"};
  // Display-only names for vectors, so the audit shows vector equations as the paper writes them.
  GiNaC::symbol v1{"v1", "\\mathbf{v}_1"};
  GiNaC::symbol v2{"v2", "\\mathbf{v}_2"};
  GiNaC::symbol x1{"x1", "\\mathbf{x}_1"};
  GiNaC::symbol x2{"x2", "\\mathbf{x}_2"};
  GiNaC::symbol n{"n", "\\mathbf{n}"};
  GiNaC::symbol x1_perp{"x1perp", "x_1^{\\perp}"};
  GiNaC::symbol x2_perp{"x2perp", "x_2^{\\perp}"};
  GiNaC::symbol v1_perp{"v1perp", "v_1^{\\perp}"};
  GiNaC::symbol v2_perp{"v2perp", "v_2^{\\perp}"};
  GiNaC::symbol x1_parallel_squared{"x1par2", "(x_1^{\\parallel})^2"};
  GiNaC::symbol P_parallel_dot_x1_parallel{"Ppar_x1par", "P^{\\parallel} \\cdot x_1^{\\parallel}"};
  GiNaC::symbol P_parallel_squared{"Ppar2", "(P^{\\parallel})^2"};
  GiNaC::symbol P_of_x{"P_x", "P(x_1, x_2)"};
  GiNaC::symbol P_split{"P_split", "P(x_1^{\\parallel}, x_2^{\\parallel}) + P(x_1^{\\perp}, x_2^{\\perp})"};
  GiNaC::symbol K_of_x{"K_x", "K(x_1, x_2)"};
  GiNaC::symbol K_of_x_parallel{"K_xpar", "K(x_1^{\\parallel}, x_2^{\\parallel})"};
  GiNaC::symbol K_split{"K_split", "K(x_1^{\\parallel}, x_2^{\\parallel}) + K(x_1^{\\perp}, x_2^{\\perp})"};
  GiNaC::symbol P_v_par_minus_x_par{
      "dP_par", "P(v_1^{\\parallel}, v_2^{\\parallel}) - P(x_1^{\\parallel}, x_2^{\\parallel})"};
  GiNaC::symbol P_v_minus_x{"dP", "P(v_1, v_2) - P(x_1, x_2)"};
  GiNaC::symbol K_v_par_minus_x_par{
      "dK_par", "K(v_1^{\\parallel}, v_2^{\\parallel}) - K(x_1^{\\parallel}, x_2^{\\parallel})"};
  GiNaC::symbol K_v_minus_x{"dK", "K(v_1, v_2) - K(x_1, x_2)"};
  GiNaC::symbol P_of_v_parallel{"P_vpar", "P(v_1^{\\parallel}, v_2^{\\parallel})"};
  GiNaC::symbol K_of_v_parallel{"K_vpar", "K(v_1^{\\parallel}, v_2^{\\parallel})"};
  GiNaC::symbol P_of_v{"P_v", "P(v_1, v_2)"};
  GiNaC::symbol K_of_v{"K_v", "K(v_1, v_2)"};
  GiNaC::symbol sandwich{"nvn", "\\mathbf{n} \\mathbf{v}_1 \\mathbf{n}"};
  GiNaC::symbol results{"x1x2", "(\\mathbf{x}_1, \\mathbf{x}_2)"};
  GiNaC::symbol results_flipped{"x1x2_flipped",
                                "(\\mathbf{x}_1, \\mathbf{x}_2)\\big|_{\\mathbf{n} \\to -\\mathbf{n}}"};
  GiNaC::realsymbol restitution{"restitution", "e"};
  GiNaC::possymbol first_mass_ratio{"rho1", "\\rho_1"};
  GiNaC::possymbol second_mass_ratio{"rho2", "\\rho_2"};
  GiNaC::symbol c1{"c1", "c_1"};
  GiNaC::symbol direction{"d", "\\mathbf{d}"};
  GiNaC::symbol unit_direction{"dhat", "\\hat{\\mathbf{d}}"};
  GiNaC::symbol relative_direction_speed{"sd", "\\frac{(v_2 - v_1) \\cdot d}{d \\cdot d}"};
  GiNaC::symbol approach_direction_speed{"sigma", "\\sigma"};
  GiNaC::symbol relative_unit_speed{"sdhat", "((v_2 - v_1) \\cdot \\hat{d})"};
  GiNaC::symbol x1_scaled_direction{"x1_scaled",
                                    "\\mathbf{x}_1\\big|_{\\mathbf{d} \\to \\lambda \\mathbf{d}}"};
  GiNaC::symbol a_par_dot_b_perp{"apar_bperp", "a^{\\parallel} \\cdot b^{\\perp}"};
  GiNaC::symbol cross_product_squared{"pxw2", "|\\mathbf{p} \\times \\mathbf{w}|^2"};
};

const Symbols& symbols() {
  static const Symbols instance;
  return instance;
}

// P and K applied to vectors (a scalar is a one-component vector), with the definitions' coefficients.
Vec momentum(const Definitions& d, const Vec& a, const Vec& b) {
  const Symbols& s = symbols();
  return add(scale(d.momentum_coefficient_1 * s.m1, a), scale(d.momentum_coefficient_2 * s.m2, b));
}

ex kinetic(const Definitions& d, const Vec& a, const Vec& b) {
  const Symbols& s = symbols();
  return d.kinetic_coefficient_1 * s.m1 * dot(a, a) + d.kinetic_coefficient_2 * s.m2 * dot(b, b);
}

ex scalar_momentum(const Definitions& d, const ex& a, const ex& b) { return momentum(d, {a}, {b})[0]; }
ex scalar_kinetic(const Definitions& d, const ex& a, const ex& b) { return kinetic(d, {a}, {b}); }

// The vectors of one dimension, in components.
struct Space {
  std::size_t dimension;
  Vec v1, v2, n, x1, x2;
  Constraint unit_normal;  // n_d² == 1 − Σ n_i², "n·n = 1"
  std::string suffix;

  explicit Space(std::size_t d)
      : dimension(d),
        v1(component_symbols("v1", "v", "1", d)),
        v2(component_symbols("v2", "v", "2", d)),
        n(component_symbols("n", "n", "", d)),
        x1(component_symbols("x1", "x", "1", d)),
        x2(component_symbols("x2", "x", "2", d)),
        unit_normal{unit_normal_relation(n), "n·n = 1"},
        suffix(std::string(".").append(std::to_string(d)).append("d")) {}

  // A scalar of the derivation (in v1·n, v2·n) written in this space's components.
  ex components_of(const ex& scalar) const {
    const Symbols& s = symbols();
    return scalar.subs(lst{s.v1n == dot(v1, n), s.v2n == dot(v2, n)});
  }
  // The velocity v + κ n for a ball whose new normal component is `normal` (a scalar).
  Vec after_collision(const Vec& v, const ex& normal) const {
    return add(perpendicular_part(v, n), scale(components_of(normal), n));
  }
};

lst concatenate(const Vec& a, const Vec& b) {
  lst all = to_lst(a);
  for (const ex& component : b) all.append(component);
  return all;
}

ModelInfo paper_model() {
  ModelInfo model;
  model.name = "parkin2023";
  model.title = "Billiard Ball Physics";
  model.citation = "S. T. Parkin, \"Billiard Ball Physics\", 2023";
  model.scope = "frictionless, spinless balls in instantaneous contact (perfectly elastic)";
  model.notation =
      "Vectors in components are written $v_{1,x}$ as `v1_x`; $(v_1 \\cdot n)$ is the scalar $v_1 \\cdot n$; "
      "$\\mathbf{v}_1$ names the vector itself. Where $n \\cdot n = 1$ is needed it is imposed by substituting "
      "$n_\\text{last}^2 \\to 1 - \\sum n_i^2$, never by choosing a numeric normal, and the claim says so "
      "(\"Under: n·n = 1\").";
  model.remarks = {
      "Footnote 1 calls P and K \"bilinear\". P is linear and K is a quadratic form; K splits into parts "
      "along and across n because the cross terms a∥·b⊥ vanish for a unit n (`split.kinetic_cross_term.2d`, "
      "`split.kinetic_cross_term.3d`).",
      "\"A physics-based argument that we must have v1⊥ = x1⊥\" is an assumption (frictionless, spinless "
      "contact), not a consequence of conservation: `assumption.tangential_velocity_unchanged` is the only "
      "unchecked claim.",
      "P·n and (x1∥)² are shorthand for P(v1, v2)·n and x1∥·x1∥.",
      "The paper rejects the \"−\" root because it does not depend on v2. The stronger reason is that it is "
      "x1 = v1, x2 = v2: the state before the collision (`selection.minus_root_is_no_collision`); the \"+\" "
      "root reverses the relative normal velocity (`selection.plus_root_reverses_relative_normal_velocity`).",
      "The cushion limit needs v2 = 0 (or bounded): the limit of x1 for a wall moving with v2 is "
      "v1 + 2((v2 − v1)·n) n (`cushion.limit`). −n v1 n is a reflection only when n² = 1.",
  };
  model.reference_path = "billiards/reference_kernels.hpp";
  return model;
}

const char* const unit_normal_method = "; n·n = 1 imposed by substituting n_last² → 1 − Σ n_i²";

}  // namespace

Derivation derive_paper(const Definitions& definitions) {
  const Symbols& s = symbols();
  const Definitions& d = definitions;
  const Space plane(2);
  const Space space(3);
  Derivation result;
  result.model = paper_model();
  Recorder record(result);

  // ---- Premises ------------------------------------------------------------------------------
  {
    const ex a = GiNaC::symbol("a"), b = GiNaC::symbol("b");
    result.premises = {
        {"definition.momentum", "P(a, b) = m1 a + m2 b: the total momentum of the two balls.",
         scalar_momentum(d, a, b)},
        {"definition.kinetic_energy", "K(a, b) = ½ m1 a² + ½ m2 b²: their total kinetic energy (a² = a·a).",
         scalar_kinetic(d, a, b)},
        {"definition.split",
         "a∥ = (a·n) n and a⊥ = a − a∥ for a unit contact normal n (n·n = 1); vectors are kept in "
         "symbolic components in 2-D and 3-D, never a chosen numeric n.",
         ex(0)},
        {"definition.restitution",
         "Newton's law of restitution (beyond the paper): (x2 − x1)·n = −e (v2 − v1)·n with 0 ≤ e ≤ 1; "
         "e = 1 is the paper's perfectly elastic collision.",
         ex(0)},
        {"definition.time_of_impact",
         "Balls move in straight lines between collisions (beyond the paper): centres p1 + t v1 and "
         "p2 + t v2; spheres of radii r1, r2 touch when |(p2 − p1) + t (v2 − v1)| = r1 + r2.",
         ex(0)},
        {"definition.conservation",
         "Momentum is conserved, P(v1, v2) = P(x1, x2); for a perfectly elastic collision so is the "
         "kinetic energy, K(v1, v2) = K(x1, x2).",
         ex(0)},
    };
  }

  // ---- The split along and across n ----------------------------------------------------------
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
        .paper_display = s.P_of_x,
        .derived_display = s.P_split,
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
        .derived_display = s.a_par_dot_b_perp,
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
        .paper_display = s.K_of_x,
        .derived_display = s.K_split,
        .note = "Holds only because n is a unit vector: without n·n = 1 the parallel part carries a "
                "factor (n·n)² and the cross terms do not cancel.",
        .depends_on = {"definition.kinetic_energy", "definition.split",
                       "split.kinetic_cross_term" + sp->suffix},
    });
  }

  // ---- Frictionless contact ------------------------------------------------------------------
  record.section("tangential", "Frictionless contact: the tangential parts are unchanged",
                 "The paper makes \"a physics-based argument that we must have v1⊥ = x1⊥ and "
                 "v2⊥ = x2⊥\". This is a modelling assumption, not a consequence of the "
                 "conservation laws.");
  record.add({
      .id = "assumption.tangential_velocity_unchanged",
      .paper = "\"after making a physics-based argument\"",
      .paper_tex = R"tex(v_1^\perp = x_1^\perp, \quad v_2^\perp = x_2^\perp)tex",
      .statement = "x1⊥ = v1⊥ and x2⊥ = v2⊥: the contact exerts no force across n.",
      .method = "assumption",
      .comparison = Comparison::assumption,
      .paper_expression = lst{s.x1_perp == s.v1_perp, s.x2_perp == s.v2_perp},
      .derived_expression = lst{s.x1_perp == s.v1_perp, s.x2_perp == s.v2_perp},
      .paper_display = lst{s.x1_perp == s.v1_perp, s.x2_perp == s.v2_perp},
      .derived_display = lst{s.x1_perp == s.v1_perp, s.x2_perp == s.v2_perp},
      .note = "Physical reason: smooth (frictionless), spinless balls in instantaneous contact push "
              "on each other only along the contact normal, so no impulse acts across n. Momentum "
              "and energy conservation alone do not force it: they are four scalar equations in 3-D "
              "for six unknown components. With friction or spin the tangential parts change.",
      .depends_on = {},
  });

  // ---- Conservation along n ------------------------------------------------------------------
  record.section("along_n", "Conservation reduces to the parts along n",
                 "With the tangential parts unchanged, x_i = v_i⊥ + (x_i·n) n, and the conservation "
                 "laws become P(v1∥, v2∥) = P(x1∥, x2∥) and K(v1∥, v2∥) = K(x1∥, x2∥).");
  {
    const Vec x1 = space.after_collision(space.v1, s.x1n), x2 = space.after_collision(space.v2, s.x2n);
    const Vec v1_par = parallel_part(space.v1, space.n), v2_par = parallel_part(space.v2, space.n);
    const Vec x1_par = parallel_part(x1, space.n), x2_par = parallel_part(x2, space.n);
    record.add({
        .id = "along_n.momentum",
        .paper = "\"our preservation equations become\" (momentum)",
        .paper_tex = R"tex(P(v_1^\parallel, v_2^\parallel) = P(x_1^\parallel, x_2^\parallel))tex",
        .statement = "P(v1, v2) − P(x1, x2) = P(v1∥, v2∥) − P(x1∥, x2∥) when x_i⊥ = v_i⊥ (3-D).",
        .method = std::string("identity after expand(), componentwise") + unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = to_lst(subtract(momentum(d, v1_par, v2_par), momentum(d, x1_par, x2_par))),
        .derived_expression = to_lst(subtract(momentum(d, space.v1, space.v2), momentum(d, x1, x2))),
        .constraints = {space.unit_normal},
        .paper_display = s.P_v_par_minus_x_par,
        .derived_display = s.P_v_minus_x,
        .depends_on = {"definition.conservation", "split.momentum.3d",
                       "assumption.tangential_velocity_unchanged"},
    });
    record.add({
        .id = "along_n.kinetic_energy",
        .paper = "\"our preservation equations become\" (kinetic energy)",
        .paper_tex = R"tex(K(v_1^\parallel, v_2^\parallel) = K(x_1^\parallel, x_2^\parallel))tex",
        .statement = "K(v1, v2) − K(x1, x2) = K(v1∥, v2∥) − K(x1∥, x2∥) when x_i⊥ = v_i⊥ (3-D).",
        .method = std::string("identity after expand()") + unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = kinetic(d, v1_par, v2_par) - kinetic(d, x1_par, x2_par),
        .derived_expression = kinetic(d, space.v1, space.v2) - kinetic(d, x1, x2),
        .constraints = {space.unit_normal},
        .paper_display = s.K_v_par_minus_x_par,
        .derived_display = s.K_v_minus_x,
        .depends_on = {"definition.conservation", "split.kinetic.3d",
                       "assumption.tangential_velocity_unchanged"},
    });
    record.add({
        .id = "along_n.momentum_is_along_n",
        .paper = "the notation P·n",
        .paper_tex = R"tex(P^\parallel = P(v_1^\parallel, v_2^\parallel))tex",
        .statement = "P∥ = P(v1∥, v2∥) = (P·n) n with P·n = m1 (v1·n) + m2 (v2·n): momentum along n "
                     "is one scalar equation.",
        .method = "identity after expand(), componentwise",
        .comparison = Comparison::identity,
        .paper_expression = to_lst(scale(dot(momentum(d, space.v1, space.v2), space.n), space.n)),
        .derived_expression = to_lst(momentum(d, v1_par, v2_par)),
        .paper_display = s.Pn * s.n,
        .derived_display = s.P_of_v_parallel,
        .note = "The paper writes P·n for P(v1, v2)·n, the total momentum along n.",
        .depends_on = {"definition.momentum", "definition.split"},
    });
    record.add({
        .id = "along_n.kinetic_energy_in_normal_components",
        .paper = "K∥ = K(v1∥, v2∥)",
        .paper_tex = R"tex(K^\parallel = K(v_1^\parallel, v_2^\parallel))tex",
        .statement = "K∥ = K(v1∥, v2∥) = ½ m1 (v1·n)² + ½ m2 (v2·n)² given n·n = 1.",
        .method = std::string("identity after expand()") + unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = space.components_of(scalar_kinetic(d, s.v1n, s.v2n)),
        .derived_expression = kinetic(d, v1_par, v2_par),
        .constraints = {space.unit_normal},
        .paper_display = scalar_kinetic(d, s.v1n, s.v2n),
        .derived_display = s.K_of_v_parallel,
        .depends_on = {"definition.kinetic_energy", "definition.split"},
    });
  }

  // ---- The quadratic in x1·n -----------------------------------------------------------------
  record.section("quadratic", "The quadratic in x1·n",
                 "Solve momentum conservation along n for x2·n, substitute into energy conservation "
                 "and read the coefficients off with coeff().");
  // The paper's shorthand P·n and K∥, replaced by their definitions before any comparison.
  const ex paper_shorthand =
      lst{s.Pn == scalar_momentum(d, s.v1n, s.v2n), s.K_parallel == scalar_kinetic(d, s.v1n, s.v2n)};
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
      .note = "The paper states this step in words only; it is the vector equation "
              "x2∥ = (P∥ − m1 x1∥)/m2 along n.",
      .depends_on = {"along_n.momentum", "along_n.momentum_is_along_n"},
  });
  // The quadratic as the paper first writes it, in vectors: K(x1∥, x2∥) − K∥ with x2∥ from momentum.
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
        .derived_display = s.K_of_x_parallel - s.K_parallel,
        .note = "(x1∥)² means x1∥·x1∥ and P∥ = P(v1∥, v2∥).",
        .depends_on = {"quadratic.x2_from_momentum", "along_n.kinetic_energy"},
    });
  }
  const ex quadratic = (scalar_kinetic(d, s.x1n, x2n_solved) - scalar_kinetic(d, s.v1n, s.v2n)).expand();
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
        .method = std::string("the scalar quadratic, written in components, against the paper's; "
                              "identity after normal()") +
                  unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = space.components_of(paper_scalar_form.subs(paper_shorthand)),
        .derived_expression = space.components_of(quadratic),
        .constraints = {space.unit_normal},
        .paper_display = paper_scalar_form,
        .derived_display = factored_form(quadratic),
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
          .depends_on = {"quadratic.in_normal_component"},
      });
    }
  }
  const ex A = quadratic.coeff(s.x1n, 2), B = quadratic.coeff(s.x1n, 1), C = quadratic.coeff(s.x1n, 0);

  // ---- The discriminant ----------------------------------------------------------------------
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
        .depends_on = {"discriminant.factored"},
    });
  }

  // ---- The roots -----------------------------------------------------------------------------
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
        .paper_display = paper_roots,
        .derived_display = factored_form(roots),
        .depends_on = {"discriminant.factored", "discriminant.nonnegative"},
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
        .paper_display = paper_roots_no_abs,
        .derived_display = factored_form(roots),
        .note = c.sign > 0 ? "Here the pairing is sign for sign." : "Here ± pair crosswise.",
        .depends_on = {std::string("roots.quadratic_formula.") + c.suffix},
    });
  }
  // The roots with |…| dropped, as derived: the s ≥ 0 case, written back in v2·n.
  const auto without_abs = [&](const ex& root) {
    return GiNaC::normal(in_case(root, +1).subs(s.relative_normal_speed == relative));
  };
  const ex plus_root = without_abs(roots.op(0)), minus_root = without_abs(roots.op(1));

  // ---- The general solution ------------------------------------------------------------------
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
        .depends_on = {"roots.absolute_value_dropped.relative_speed_nonnegative",
                       "roots.absolute_value_dropped.relative_speed_negative",
                       "assumption.tangential_velocity_unchanged"},
    });
  }

  // ---- Root selection ------------------------------------------------------------------------
  record.section("selection", "Choosing the root",
                 "The paper rejects the \"−\" root because x1 would not depend on v2. A stronger "
                 "criterion: the \"−\" root is the state before the collision.");
  const ex x2_of = [&](const ex& x1n) { return GiNaC::normal(x2n_solved.subs(s.x1n == x1n)); }(minus_root);
  record.add({
      .id = "selection.minus_root_independent_of_v2",
      .paper = "\"x1 no longer becomes dependent upon v2\"",
      .statement = "The \"−\" root does not depend on v2·n (the paper's argument).",
      .method = "diff() of the \"−\" root by v2·n; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = 0,
      .derived_expression = GiNaC::diff(minus_root, s.v2n),
      .derived_display = factored_form(GiNaC::diff(minus_root, s.v2n)),
      .depends_on = {"general.x1_both_roots"},
  });
  record.add({
      .id = "selection.minus_root_is_no_collision",
      .paper = "the negative case",
      .statement = "The \"−\" root gives x1·n = v1·n and x2·n = v2·n: x1 = v1 and x2 = v2, no momentum "
                   "exchanged — the state before the collision, which trivially conserves everything.",
      .method = "the \"−\" root and x2·n from momentum; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = lst{s.v1n, s.v2n},
      .derived_expression = lst{minus_root, x2_of},
      .paper_display = lst{s.v1n, s.v2n},
      .derived_display = factored_form(lst{minus_root, x2_of}),
      .note = "Stronger than the paper's intuition: the \"−\" root is not merely implausible, it is "
              "the trivial solution that every pair of conservation laws admits.",
      .depends_on = {"general.x1_both_roots", "quadratic.x2_from_momentum"},
  });
  const ex x2n_selected = GiNaC::normal(x2n_solved.subs(s.x1n == plus_root));
  record.add({
      .id = "selection.plus_root_reverses_relative_normal_velocity",
      .paper = "\"the case we care about must be the positive case\"",
      .statement = "The \"+\" root reverses the relative normal velocity: (x2 − x1)·n = −(v2 − v1)·n.",
      .method = "the \"+\" root and x2·n from momentum; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = -relative,
      .derived_expression = x2n_selected - plus_root,
      .derived_display = factored_form(x2n_selected - plus_root),
      .note = "A perfectly elastic collision in Newton's sense (restitution 1): the balls separate as "
              "fast as they approached.",
      .depends_on = {"general.x1_both_roots", "quadratic.x2_from_momentum"},
  });

  // ---- The collision formula -----------------------------------------------------------------
  record.section("result", "The collision formula",
                 "The selected root in the paper's expanded and simplified forms, x2 by symmetry, "
                 "and independence of the sign of n (3-D components).");
  const Vec x1_selected = space.after_collision(space.v1, plus_root);
  const Vec x2_selected = space.after_collision(space.v2, x2n_selected);
  const ex simplified_coefficient = 2 * s.m2 / (s.m1 + s.m2) * relative;
  const auto paper_simplified = [&](const Space& sp) {
    return add(sp.v1, scale(sp.components_of(simplified_coefficient), sp.n));
  };
  {
    const ex expanded_coefficient =
        2 * s.m2 / (s.m1 + s.m2) * s.v2n + ((s.m1 - s.m2) / (s.m1 + s.m2) - 1) * s.v1n;
    record.add({
        .id = "result.x1_expanded_form",
        .paper = "\"In that case, we get\"",
        .paper_tex =
            R"tex(x_1 = v_1 + \left(\frac{2m_2}{m_1 + m_2} (v_2 \cdot n) + \left(\frac{m_1 - m_2}{m_1 + m_2} - 1 \right) (v_1 \cdot n) \right) n)tex",
        .statement = "x1 = v1 + (2m2/(m1 + m2) (v2·n) + ((m1 − m2)/(m1 + m2) − 1)(v1·n)) n.",
        .method = "x1 = v1⊥ + (x1·n) n with the \"+\" root; identity after normal(), componentwise",
        .comparison = Comparison::identity,
        .paper_expression = to_lst(add(space.v1, scale(space.components_of(expanded_coefficient), space.n))),
        .derived_expression = to_lst(x1_selected),
        .constraints = {space.unit_normal},
        .paper_display = s.v1 + expanded_coefficient * s.n,
        .derived_display = s.v1 + factored_form(plus_root - s.v1n) * s.n,
        .depends_on = {"selection.plus_root_reverses_relative_normal_velocity",
                       "selection.minus_root_is_no_collision"},
    });
    record.add({
        .id = "result.x1_simplified_form",
        .paper = "\"The equation simplifies further as\"",
        .paper_tex = R"tex(x_1 = v_1 + \left(\frac{2m_2}{m_1 + m_2} (v_2 - v_1) \cdot n \right) n)tex",
        .statement = "x1 = v1 + (2 m2/(m1 + m2)) ((v2 − v1)·n) n.",
        .method = "identity after normal(), componentwise",
        .comparison = Comparison::identity,
        .paper_expression = to_lst(paper_simplified(space)),
        .derived_expression = to_lst(x1_selected),
        .constraints = {space.unit_normal},
        .paper_display = s.v1 + simplified_coefficient * s.n,
        .derived_display = s.v1 + factored_form(plus_root - s.v1n) * s.n,
        .depends_on = {"result.x1_expanded_form"},
    });
  }
  // The paper: "By symmetry ... Just replace subscript 1 with 2 and vice-versa."
  const auto swap_balls = [&](const Space& sp) {
    GiNaC::exmap swap{{s.m1, s.m2}, {s.m2, s.m1}};
    for (std::size_t i = 0; i < sp.dimension; ++i) {
      swap[sp.v1[i]] = sp.v2[i];
      swap[sp.v2[i]] = sp.v1[i];
    }
    return swap;
  };
  record.add({
      .id = "result.x2_by_symmetry",
      .paper = "\"By symmetry of the preservation equations\"",
      .statement = "x2 from momentum conservation equals the paper's x1 with subscripts 1 and 2 "
                   "swapped: x2 = v2 + (2 m1/(m1 + m2)) ((v1 − v2)·n) n.",
      .method = "x2 = v2⊥ + (x2·n) n with x2·n from momentum; the paper's x1 with 1 ↔ 2 by "
                "simultaneous subs(); identity after normal(), componentwise",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(paper_simplified(space)).subs(swap_balls(space)),
      .derived_expression = to_lst(x2_selected),
      .constraints = {space.unit_normal},
      .paper_display = s.v2 + 2 * s.m1 / (s.m1 + s.m2) * (s.v1n - s.v2n) * s.n,
      .derived_display = s.v2 + factored_form(x2n_selected - s.v2n) * s.n,
      .depends_on = {"result.x1_simplified_form", "quadratic.x2_from_momentum"},
  });
  {
    GiNaC::exmap flip;
    for (const ex& component : space.n) flip[component] = -component;
    record.add({
        .id = "result.independent_of_normal_sign",
        .paper = "\"it didn't matter which direction n pointed\"",
        .statement = "Replacing n by −n leaves x1 and x2 unchanged.",
        .method = "subs() n → −n in the derived x1, x2; identity after normal(), componentwise",
        .comparison = Comparison::identity,
        .paper_expression = concatenate(x1_selected, x2_selected),
        .derived_expression = concatenate(x1_selected, x2_selected).subs(flip),
        .paper_display = s.results,
        .derived_display = s.results_flipped,
        .depends_on = {"result.x1_simplified_form", "result.x2_by_symmetry"},
    });
  }

  // ---- The paper's sanity checks -------------------------------------------------------------
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
        .depends_on = {"sanity.equal_masses_at_rest.x2"},
    });
  }

  // ---- The cushion ---------------------------------------------------------------------------
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
          .derived_display = -s.sandwich,
          .note = "In geometric algebra n v n = 2 (n·v) n − (n·n) v, so −n v n is the reflection in "
                  "the plane normal to n only when n² = n·n = 1.",
          .depends_on = {"definition.split"},
      });
    }
  }

  // ---- End to end ----------------------------------------------------------------------------
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
        .paper_display = s.P_of_v,
        .derived_display = s.P_of_x,
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
        .paper_display = s.K_of_v,
        .derived_display = s.K_of_x,
        .depends_on = {"result.x1_simplified_form", "result.x2_by_symmetry", "definition.conservation"},
    });
  }
  // ---- The kernels the emitter prints --------------------------------------------------------
  ex cushion_change;  // the cushion's change of v1·n, for its kernel below
  record.section("kernels", "What the code emitter prints",
                 "The emitted kernels are scalar functions of the masses and the normal components "
                 "v1·n, v2·n, so they serve vectors of any dimension. Their expressions are read off "
                 "the selected root, never typed again; these claims vouch for each piece.");
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

  // ---- Beyond the paper ----------------------------------------------------------------------
  record.section("beyond", "Beyond the paper",
                 "What engines need and the paper does not cover: a coefficient of restitution, "
                 "immovable bodies, directions that are not unit vectors, contacts that are "
                 "already separating, and the time at which two moving balls first touch. Derived "
                 "and checked like the paper's claims; the paper states none of them.");
  const ex e = s.restitution;
  const ex speed = s.relative_normal_speed;
  const auto through_speed = [&](const ex& x) { return GiNaC::normal(x.subs(s.v2n == s.v1n + speed)); };
  // Momentum conservation and Newton's law of restitution, solved for the normal components.
  const ex restitution_solution =
      GiNaC::lsolve(lst{scalar_momentum(d, s.x1n, s.x2n) == scalar_momentum(d, s.v1n, s.v2n),
                        s.x2n - s.x1n == -e * (s.v2n - s.v1n)},
                    lst{s.x1n, s.x2n});
  const ex x1n_e = GiNaC::normal(ex(s.x1n).subs(restitution_solution));
  const ex x2n_e = GiNaC::normal(ex(s.x2n).subs(restitution_solution));
  const ex paper_x1n = s.v1n + 2 * s.m2 / (s.m1 + s.m2) * (s.v2n - s.v1n);
  const ex paper_x2n = s.v2n + 2 * s.m1 / (s.m1 + s.m2) * (s.v1n - s.v2n);
  const std::vector<std::string> restitution_premises = {"definition.momentum", "definition.restitution"};
  record.add({
      .id = "beyond.restitution.elastic_is_the_paper",
      .statement = "With restitution e = 1, momentum conservation and Newton's law give exactly the "
                   "paper's selected result.",
      .method = "lsolve() of m1 x1·n + m2 x2·n = P·n and (x2 − x1)·n = −e (v2 − v1)·n; e = 1 "
                "substituted; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = lst{paper_x1n, paper_x2n},
      .derived_expression = lst{x1n_e.subs(e == 1), x2n_e.subs(e == 1)},
      .paper_display = lst{paper_x1n, paper_x2n},
      .derived_display = factored_form(lst{x1n_e, x2n_e}),
      .note = "The derived display is the general solution for any e.",
      .depends_on = restitution_premises,
  });
  record.add({
      .id = "beyond.restitution.elastic_conserves_energy",
      .statement = "With e = 1 the kinetic energy is conserved.",
      .method = "K of the solved normal components at e = 1; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = scalar_kinetic(d, s.v1n, s.v2n),
      .derived_expression = scalar_kinetic(d, x1n_e, x2n_e).subs(e == 1),
      .paper_display = s.K_parallel,
      .derived_display = s.K_of_x_parallel,
      .depends_on = {"beyond.restitution.elastic_is_the_paper", "definition.kinetic_energy"},
  });
  const ex reduced_mass = s.m1 * s.m2 / (s.m1 + s.m2);
  const ex energy_loss = GiNaC::normal(scalar_kinetic(d, s.v1n, s.v2n) - scalar_kinetic(d, x1n_e, x2n_e));
  const ex printed_loss = numeric(1, 2) * reduced_mass * (1 - e * e) * GiNaC::pow(s.v2n - s.v1n, 2);
  record.add({
      .id = "beyond.restitution.energy_loss",
      .statement = "The kinetic energy lost is ½ μ (1 − e²) ((v2 − v1)·n)², μ = m1 m2/(m1 + m2).",
      .method = "K before minus K after, the solved normal components; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = printed_loss,
      .derived_expression = energy_loss,
      .paper_display = printed_loss,
      .derived_display = factored_form(energy_loss),
      .depends_on = {"beyond.restitution.elastic_is_the_paper", "definition.kinetic_energy"},
  });
  const GiNaC::possymbol t("t");
  record.add({
      .id = "beyond.restitution.energy_loss_nonnegative",
      .statement = "For 0 ≤ e ≤ 1 no energy is created: the loss is ≥ 0 (zero at e = 1).",
      .method = "sign: e = t/(1 + t) with t ≥ 0 covers [0, 1); factor() of the loss is then a product "
                "of positive factors and even powers; e = 1 is beyond.restitution.elastic_conserves_energy",
      .comparison = Comparison::nonnegative,
      .paper_expression = 0,
      .derived_expression = GiNaC::normal(energy_loss.subs(e == t / (1 + t))),
      .paper_display = 0,
      .derived_display = factored_form(energy_loss.subs(e == t / (1 + t))),
      .depends_on = {"beyond.restitution.energy_loss"},
  });
  record.add({
      .id = "beyond.restitution.perfectly_inelastic",
      .statement = "With e = 0 the balls leave with equal normal velocities: x1·n = x2·n.",
      .method = "e = 0 substituted; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = 0,
      .derived_expression = (x2n_e - x1n_e).subs(e == 0),
      .paper_display = 0,
      .derived_display = factored_form((x2n_e - x1n_e).subs(e == 0)),
      .depends_on = {"beyond.restitution.elastic_is_the_paper"},
  });
  const ex first_coefficient_e = GiNaC::normal(through_speed(x1n_e - s.v1n) / speed);
  const ex second_coefficient_e = GiNaC::normal(through_speed(x2n_e - s.v2n) / speed);
  const lst printed_coefficients{(1 + e) * s.m2 / (s.m1 + s.m2), -(1 + e) * s.m1 / (s.m1 + s.m2)};
  record.add({
      .id = "beyond.restitution.impulse_coefficients",
      .statement = "x1·n − v1·n = (1 + e) m2/(m1 + m2) (v2 − v1)·n and x2·n − v2·n = −(1 + e) m1/(m1 + "
                   "m2) (v2 − v1)·n: the change depends on the velocities only through (v2 − v1)·n.",
      .method = "v2·n = v1·n + (v2 − v1)·n substituted, divided by (v2 − v1)·n; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = printed_coefficients,
      .derived_expression = lst{first_coefficient_e, second_coefficient_e},
      .paper_display = printed_coefficients,
      .derived_display = factored_form(lst{first_coefficient_e, second_coefficient_e}),
      .depends_on = {"beyond.restitution.elastic_is_the_paper"},
  });
  // Immovable bodies: the coefficients in the mass ratios ρ1 = m1/m2 and ρ2 = m2/m1.
  const ex rho1 = s.first_mass_ratio, rho2 = s.second_mass_ratio;
  const ex first_ratio_form = GiNaC::normal(first_coefficient_e.subs(s.m1 == rho1 * s.m2));
  const ex second_ratio_form = GiNaC::normal(second_coefficient_e.subs(s.m2 == rho2 * s.m1));
  const lst printed_ratio_forms{(1 + e) / (1 + rho1), -(1 + e) / (1 + rho2)};
  record.add({
      .id = "beyond.immovable.mass_ratio_form",
      .statement = "In the mass ratios ρ1 = m1/m2 and ρ2 = m2/m1 the coefficients are (1 + e)/(1 + ρ1) "
                   "and −(1 + e)/(1 + ρ2): no mass appears alone.",
      .method = "m1 = ρ1 m2 (resp. m2 = ρ2 m1) substituted; normal() cancels the other mass; identity",
      .comparison = Comparison::identity,
      .paper_expression = printed_ratio_forms,
      .derived_expression = lst{first_ratio_form, second_ratio_form},
      .paper_display = printed_ratio_forms,
      .derived_display = factored_form(lst{first_ratio_form, second_ratio_form}),
      .note = "Chosen for floating point: a ratio of two positive masses is finite or +∞ and never "
              "NaN unless both are infinite; 1 + ρ cannot overflow where m1 + m2 can (1e308 + 1e308), "
              "and no inverse mass overflows for a subnormal mass. An infinite m2 gives ρ1 = 0 and "
              "ρ2 = ∞, so the coefficients are exactly 1 + e and 0. Equal masses give ρ = 1 and a "
              "coefficient of exactly (1 + e)/2.",
      .depends_on = {"beyond.restitution.impulse_coefficients"},
  });
  record.add({
      .id = "beyond.immovable.equals_mass_form",
      .statement = "For finite masses the ratio form equals the mass form.",
      .method = "ρ1 = m1/m2, ρ2 = m2/m1 substituted back; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = lst{first_coefficient_e, second_coefficient_e},
      .derived_expression =
          lst{first_ratio_form.subs(rho1 == s.m1 / s.m2), second_ratio_form.subs(rho2 == s.m2 / s.m1)},
      .paper_display = factored_form(lst{first_coefficient_e, second_coefficient_e}),
      .derived_display = printed_ratio_forms,
      .depends_on = {"beyond.immovable.mass_ratio_form"},
  });
  const ex first_small_mass_form = (1 + e) * (speed * s.m2) / (s.m1 + s.m2);
  const ex second_small_mass_form = -(1 + e) * (speed * s.m1) / (s.m1 + s.m2);
  record.add({
      .id = "beyond.immovable.small_mass_form",
      .statement = "x1·n − v1·n = (1 + e)((v2 − v1)·n m2)/(m1 + m2), and likewise for ball 2: the mass form "
                   "with the speed multiplied in first.",
      .method = "the coefficients times (v2 − v1)·n; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = lst{first_small_mass_form, second_small_mass_form},
      .derived_expression = lst{first_coefficient_e * speed, second_coefficient_e * speed},
      .paper_display = lst{first_small_mass_form, second_small_mass_form},
      .derived_display = factored_form(lst{first_coefficient_e * speed, second_coefficient_e * speed}),
      .note = "The kernels use it where the ratio form would lose the answer: where the coefficient "
              "(1 + e)/(1 + ρ1) falls below the smallest normal number (ρ1 = m1/m2 beyond about 2^1022 "
              "in double, or infinite) it has rounded into the subnormal range or to 0, although the "
              "change itself may be a normal number (m1 = 1e308, m2 = 0.07). There m2 ≤ 4, so "
              "(v2 − v1)·n m2 cannot overflow, and m1 + m2 rounds to m1 without overflowing.",
      .depends_on = {"beyond.restitution.impulse_coefficients"},
  });
  {
    // m2 = ∞ is ρ1 = 0 and 1/ρ2 = 0: substituted, not a limit.
    const GiNaC::possymbol inverse_rho2("inverse_rho2");
    const ex first_at_wall = first_ratio_form.subs(rho1 == 0);
    const ex second_at_wall =
        GiNaC::normal(second_ratio_form.subs(rho2 == 1 / inverse_rho2)).subs(inverse_rho2 == 0);
    const lst changes{(first_at_wall * speed).subs(lst{e == 1, speed == -s.v1n}), second_at_wall};
    record.add({
        .id = "beyond.immovable.cushion_without_limit",
        .statement = "An infinite mass m2 (ρ1 = 0, 1/ρ2 = 0 substituted, no limit taken) with e = 1 and "
                     "v2 = 0 gives the paper's cushion x1 = v1 − 2 (v1·n) n and leaves ball 2 unmoved.",
        .method = "substitution into the ratio form; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = lst{-2 * s.v1n, 0},
        .derived_expression = changes,
        .paper_display = lst{-2 * s.v1n, 0},
        .derived_display = factored_form(changes),
        .note = "Both masses infinite is not a collision: ρ1 = ∞/∞ is undefined (NaN in floating point).",
        .depends_on = {"beyond.immovable.mass_ratio_form"},
    });
  }
  // Any direction: d not necessarily unit, n = d/√(d·d) substituted into the unit form (3-D).
  const Vec direction = component_symbols("d", "d", "", 3);
  const ex dd = dot(direction, direction);
  const Vec n_of_d = scale(1 / GiNaC::sqrt(dd), direction);
  const ex c1 = first_coefficient_e;
  const auto unit_form = [&](const Vec& n) {
    return add(space.v1, scale(c1 * dot(subtract(space.v2, space.v1), n), n));
  };
  lst from_unit_form;
  for (const ex& component : unit_form(n_of_d)) from_unit_form.append(GiNaC::normal(component));
  const auto direction_form = [&](const Vec& dir) {
    return add(space.v1, scale(c1 * dot(subtract(space.v2, space.v1), dir) / dot(dir, dir), dir));
  };
  record.add({
      .id = "beyond.any_normal.direction_form",
      .statement = "For a non-zero direction d (not necessarily unit), x1 = v1 + c1 ((v2 − v1)·d)/(d·d) d: "
                   "no square root is needed.",
      .method = "n = d/√(d·d) substituted into the unit form, componentwise (3-D); identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(direction_form(direction)),
      .derived_expression = from_unit_form,
      .paper_display = s.v1 + s.c1 * s.relative_direction_speed * s.direction,
      .derived_display = s.v1 + s.c1 * s.relative_unit_speed * s.unit_direction,
      .depends_on = {"beyond.restitution.impulse_coefficients"},
  });
  const GiNaC::realsymbol lambda("lambda", "\\lambda");
  record.add({
      .id = "beyond.any_normal.scale_invariant",
      .statement = "Scaling d by any λ ≠ 0 leaves the result unchanged.",
      .method = "d → λ d substituted; identity after normal(), componentwise (3-D)",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(direction_form(direction)),
      .derived_expression = to_lst(direction_form(scale(lambda, direction))),
      .paper_display = s.x1,
      .derived_display = s.x1_scaled_direction,
      .depends_on = {"beyond.any_normal.direction_form"},
  });
  record.add({
      .id = "beyond.any_normal.unit_direction",
      .statement = "For |d| = 1 the direction form is the unit form x1 = v1 + c1 ((v2 − v1)·d) d.",
      .method = std::string("identity after normal()") +
                " ; d·d = 1 imposed by substituting d_z² → 1 − d_x² − d_y²",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(unit_form(direction)),
      .derived_expression = to_lst(direction_form(direction)),
      .constraints = {{unit_normal_relation(direction), "d·d = 1"}},
      .paper_display = s.v1 + s.c1 * s.relative_unit_speed * s.unit_direction,
      .derived_display = s.v1 + s.c1 * s.relative_direction_speed * s.direction,
      .depends_on = {"beyond.any_normal.direction_form"},
  });
  // Approaching contacts.
  record.add({
      .id = "beyond.approaching.collision_root_separates",
      .statement = "With n pointing from ball 1 to ball 2 the gap closes iff (v2 − v1)·n < 0. After the "
                   "collision (x2 − x1)·n = −e (v2 − v1)·n, which is ≥ 0 then: the non-trivial root "
                   "separates the balls (e > 0) exactly when they approach.",
      .method = "the solved normal components; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = -e * (s.v2n - s.v1n),
      .derived_expression = x2n_e - x1n_e,
      .paper_display = -e * (s.v2n - s.v1n),
      .derived_display = factored_form(x2n_e - x1n_e),
      .depends_on = {"beyond.restitution.elastic_is_the_paper"},
  });
  // The kernel form for any e: c1 (s − |s|)/2, which is c1 s when s < 0 and 0 when s ≥ 0.
  const ex approach_speed = (speed - GiNaC::abs(speed)) / 2;
  {
    // x1·n = (P·n − m2 |(v2 − v1)·n|)/(m1 + m2): the collision root when approaching, else v1·n.
    const ex minus_abs_root =
        (scalar_momentum(d, s.v1n, s.v2n) - s.m2 * GiNaC::abs(s.v2n - s.v1n)) / (s.m1 + s.m2);
    const auto in_sign = [&](const ex& x, int sign) {
      return GiNaC::normal(resolve_absolute_values(through_speed(x), speed, sign));
    };
    const lst cases{in_sign(minus_abs_root, -1), in_sign(minus_abs_root, +1)};
    const lst expected{through_speed(plus_root), s.v1n};
    record.add({
        .id = "beyond.approaching.resolve_only_approaching",
        .statement = "Resolving only approaching contacts is always taking x1·n = (P·n − m2 |(v2 − v1)·n|)/"
                     "(m1 + m2): the paper's collision root when (v2 − v1)·n < 0, and x1·n = v1·n (nothing "
                     "happens) when (v2 − v1)·n ≥ 0.",
        .method = "v2·n = v1·n + s, |s| resolved for s < 0 and s ≥ 0; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = expected,
        .derived_expression = cases,
        .paper_display = lst{plus_root, s.v1n},
        .derived_display = minus_abs_root,
        .depends_on = {"beyond.approaching.collision_root_separates", "result.x1_simplified_form"},
    });
    const lst kernel_cases{GiNaC::normal(resolve_absolute_values(c1 * approach_speed, speed, -1)),
                           GiNaC::normal(resolve_absolute_values(c1 * approach_speed, speed, +1))};
    const lst kernel_expected{through_speed(x1n_e - s.v1n), 0};
    record.add({
        .id = "beyond.approaching.kernel_form",
        .statement = "For any e, x1·n − v1·n = c1 ((v2 − v1)·n − |(v2 − v1)·n|)/2: the collision when the "
                     "balls approach, zero when they separate (likewise for ball 2).",
        .method = "|s| resolved for s < 0 and s ≥ 0; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = kernel_expected,
        .derived_expression = kernel_cases,
        .paper_display = lst{s.c1 * s.relative_normal_speed, 0},
        .derived_display = s.c1 * approach_speed,
        .depends_on = {"beyond.approaching.collision_root_separates",
                       "beyond.restitution.impulse_coefficients"},
    });
  }

  // ---- Time of impact ------------------------------------------------------------------------
  // Two spheres with centres p1 + t v1 and p2 + t v2 and radii r1, r2 touch when |p + t w| = r, with
  // p = p2 − p1, w = v2 − v1 and r = r1 + r2 (3-D components): another quadratic, in t.
  const Vec p = component_symbols("p", "p", "", 3);  // the relative position p2 − p1
  const Vec w = component_symbols("w", "w", "", 3);  // the relative velocity v2 − v1
  const GiNaC::possymbol contact_distance("contact_distance", "r");
  const GiNaC::realsymbol time("t", "t");
  const Vec separation_at_time = add(p, scale(time, w));
  const ex touching =
      (dot(separation_at_time, separation_at_time) - contact_distance * contact_distance).expand();
  // Read off as a t² + 2 b t + c.
  const ex coefficient_a = touching.coeff(time, 2), coefficient_b = touching.coeff(time, 1) / 2,
           coefficient_c = touching.coeff(time, 0);
  const GiNaC::possymbol qa("a", "a"), root_of_d("s", "\\sqrt{D}");
  const GiNaC::realsymbol qb("b", "b"), qc("c", "c"), qd("D", "D");
  const std::vector<std::string> time_premises = {"definition.time_of_impact"};
  record.add({
      .id = "beyond.time_of_impact.quadratic",
      .statement = "|p + t w|² − r² = a t² + 2 b t + c with a = w·w, b = p·w, c = p·p − r²: the spheres "
                   "touch at the roots t of a quadratic.",
      .method = "|p + t w|² − r² expanded in 3-D components; coeff() in t; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{dot(w, w), dot(p, w), dot(p, p) - contact_distance * contact_distance},
      .derived_expression = lst{coefficient_a, coefficient_b, coefficient_c},
      .paper_display = qa * GiNaC::pow(time, 2) + 2 * qb * time + qc,
      .derived_display = touching,
      .depends_on = time_premises,
  });
  // D/4 = b² − a c from the coefficients read off; in 3-D it is a r² − |p × w|² (Lagrange's identity).
  const ex quarter_discriminant = (coefficient_b * coefficient_b - coefficient_a * coefficient_c).expand();
  const Vec cross = {p[1] * w[2] - p[2] * w[1], p[2] * w[0] - p[0] * w[2], p[0] * w[1] - p[1] * w[0]};
  const ex lagrange = dot(w, w) * contact_distance * contact_distance - dot(cross, cross);
  record.add({
      .id = "beyond.time_of_impact.discriminant",
      .statement = "D = b² − a c = (w·w) r² − |p × w|²: real roots exist iff the line of relative motion "
                   "passes within r, |p × w|/|w| ≤ r. D < 0 is a miss, D = 0 a graze.",
      .method = "b² − a c of the coefficients read off, 3-D components; identity after expand()",
      .comparison = Comparison::identity,
      .paper_expression = lagrange,
      .derived_expression = quarter_discriminant,
      .paper_display = qa * contact_distance * contact_distance - s.cross_product_squared,
      .derived_display = qb * qb - qa * qc,
      .note = "D here is a quarter of the usual B² − 4AC with B = 2b.",
      .depends_on = {"beyond.time_of_impact.quadratic"},
  });
  // The roots by the quadratic formula, A = a, B = 2b, C = c, with √(B² − 4AC) = 2√D = 2 s.
  const ex quadratic_in_t = qa * GiNaC::pow(time, 2) + 2 * qb * time + qc;
  const ex big_a = quadratic_in_t.coeff(time, 2), big_b = quadratic_in_t.coeff(time, 1),
           big_c = quadratic_in_t.coeff(time, 0);
  const ex d_of_coefficients = ((big_b * big_b - 4 * big_a * big_c) / 4).expand();
  const ex root_relation = GiNaC::pow(root_of_d, 2) == d_of_coefficients;
  const ex earlier_root = GiNaC::normal((-big_b - 2 * root_of_d) / (2 * big_a));
  const ex later_root = GiNaC::normal((-big_b + 2 * root_of_d) / (2 * big_a));
  const lst printed_roots{(-qb - root_of_d) / qa, (-qb + root_of_d) / qa};
  record.add({
      .id = "beyond.time_of_impact.roots",
      .statement = "t∓ = (−b ∓ √D)/a, D = b² − a c, and both solve a t² + 2 b t + c = 0.",
      .method = "quadratic formula with A, B, C read off by coeff(); each root substituted back, the "
                "numerator reduced modulo s² = b² − a c (s = √D); identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{printed_roots.op(0), printed_roots.op(1), 0, 0},
      .derived_expression = lst{earlier_root, later_root, quadratic_in_t.subs(time == earlier_root),
                                quadratic_in_t.subs(time == later_root)},
      .constraints = {{root_relation, "s² = b² − a c (s = √D)"}},
      .paper_display = printed_roots,
      .derived_display = lst{earlier_root, later_root},
      .depends_on = {"beyond.time_of_impact.discriminant"},
  });
  // (p + t w)·w is the rate of change of |p + t w|²/2: negative while the gap closes.
  const ex closing_rate = dot(separation_at_time, w);
  record.add({
      .id = "beyond.time_of_impact.first_contact_approaches",
      .statement = "At t− the spheres approach, (p + t w)·w = −√D ≤ 0, and at t+ they separate (+√D): t− "
                   "is the physical contact, t+ the moment they would part after passing through "
                   "each other.",
      .method = "(p + t w)·w − (b + a t) in 3-D components (zero), then b + a t at t∓; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{0, -root_of_d, root_of_d},
      .derived_expression = lst{(closing_rate - (coefficient_b + coefficient_a * time)).expand(),
                                qb + qa * earlier_root, qb + qa * later_root},
      .paper_display = lst{-root_of_d, root_of_d},
      .derived_display = lst{qb + qa * time},
      .depends_on = {"beyond.time_of_impact.roots"},
  });
  // The earlier root without cancellation: multiply by (s − b)/(s − b) and reduce s² = b² − a c.
  const ex rationalized_numerator =
      reduce_modulo(((-qb - root_of_d) * (root_of_d - qb)).expand(), root_relation);
  const ex stable_root = GiNaC::normal(rationalized_numerator / (qa * (root_of_d - qb)));
  record.add({
      .id = "beyond.time_of_impact.stable_form",
      .statement = "t− = c/(√D − b): for approaching spheres (b < 0) no cancellation (√D ≥ 0 and −b > 0 are "
                   "added) and no division by a, so no division by zero.",
      .method = "t− multiplied by (s − b)/(s − b), the numerator reduced modulo s² = b² − a c; identity",
      .comparison = Comparison::identity,
      .paper_expression = qc / (root_of_d - qb),
      .derived_expression = stable_root,
      .constraints = {{root_relation, "s² = b² − a c (s = √D)"}},
      .paper_display = qc / (root_of_d - qb),
      .derived_display = printed_roots.op(0),
      .note = "(−b − √D)/a loses every digit when a c is small beside b² (spheres nearly touching); "
              "c/(√D − b) does not.",
      .depends_on = {"beyond.time_of_impact.roots"},
  });
  record.add({
      .id = "beyond.time_of_impact.no_contact",
      .statement = "t− t+ = c/a and t− + t+ = −2b/a: spheres apart (c > 0) that are not approaching (b ≥ 0) "
                   "have no root t > 0, and neither have spheres that miss (D < 0). There is no contact: "
                   "the kernel returns +∞.",
      .method = "product and sum of the roots, reduced modulo s² = b² − a c; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{qc / qa, -2 * qb / qa},
      .derived_expression = lst{earlier_root * later_root, earlier_root + later_root},
      .constraints = {{root_relation, "s² = b² − a c (s = √D)"}},
      .paper_display = lst{qc / qa, -2 * qb / qa},
      .derived_display = lst{earlier_root * later_root, earlier_root + later_root},
      .depends_on = {"beyond.time_of_impact.roots"},
        .cases = {{lst{qb >= 0}, infinity()}},
  });
  record.add({
      .id = "beyond.time_of_impact.grazing",
      .statement =
          "D = 0 (a graze): the roots coincide and at the contact (p + t w)·w = 0, no closing speed, "
          "so resolving only approaching contacts changes nothing. The kernel treats D ≤ 0 as no "
          "contact (+∞).",
      .method = "√D = 0 substituted; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{0, 0},
      .derived_expression = lst{(earlier_root - later_root).subs(root_of_d == 0),
                                GiNaC::normal(qb + qa * earlier_root).subs(root_of_d == 0)},
      .paper_display = lst{0, 0},
      .derived_display = lst{earlier_root - later_root, qb + qa * earlier_root},
      .depends_on = {"beyond.time_of_impact.first_contact_approaches", "beyond.approaching.kernel_form"},
        .cases = {{lst{qd <= 0, qb < 0}, infinity()}},
  });
  {
    const GiNaC::possymbol overlap("gamma", "\\gamma"), approach("beta", "\\beta");
    const ex negated_time = GiNaC::normal(-stable_root.subs(lst{qc == -overlap, qb == -approach}));
    record.add({
        .id = "beyond.time_of_impact.touching_now",
        .statement = "Spheres already touching or overlapping by rounding (c ≤ 0) and approaching (b < 0) "
                     "give t− ≤ 0: the contact is now, and the kernel returns 0.",
        .method = "sign: c = −γ, b = −β (γ, β > 0) in the stable form; −t− factors into positive "
                  "symbols (√D ≥ 0)",
        .comparison = Comparison::nonnegative,
        .paper_expression = 0,
        .derived_expression = negated_time,
        .paper_display = 0,
        .derived_display = negated_time,
        .depends_on = {"beyond.time_of_impact.stable_form"},
        .cases = {{lst{qc < 0, qd > 0, qb < 0}, 0}},
    });
  }

  // ---- What each emitted kernel computes -----------------------------------------------------
  record.section("kernel_outputs", "What each emitted kernel computes",
                 "One claim per emitted quantity: what the kernel returns, derived from the steps above and "
                 "compared with the formula the source prints. Every kernel is proven equal to the derived "
                 "side of its claim before it is printed (see \"The emitted kernels\" below).");
  const ex direction_speed_in_components =
      (dot(space.v2, direction) - dot(space.v1, direction)) / dd;  // ((v2 − v1)·d)/(d·d)
  {
    const lst changes{GiNaC::normal(plus_root - s.v1n), GiNaC::normal(x2n_selected - s.v2n)};
    const lst printed{2 * s.m2 / (s.m1 + s.m2) * relative, -2 * s.m1 / (s.m1 + s.m2) * relative};
    record.add({
        .id = "kernel.elastic_normal_velocity_change",
        .paper = "\"This form makes it easier to see the impulse magnitude\"",
        .statement = "x1·n − v1·n = (2 m2/(m1 + m2)) (v2 − v1)·n and x2·n − v2·n = −(2 m1/(m1 + m2)) (v2 − v1)·n: "
                     "the selected root, and x2·n from momentum, along n.",
        .method = "the \"+\" root minus v1·n, x2·n from momentum minus v2·n; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = printed,
        .derived_expression = changes,
        .paper_display = printed,
        .derived_display = factored_form(changes),
        .depends_on = {"selection.plus_root_reverses_relative_normal_velocity", "result.x1_simplified_form",
                       "result.x2_by_symmetry"},
    });
    const lst changes_e{GiNaC::normal(x1n_e - s.v1n), GiNaC::normal(x2n_e - s.v2n)};
    const lst printed_e{(1 + e) * s.m2 / (s.m1 + s.m2) * relative, -(1 + e) * s.m1 / (s.m1 + s.m2) * relative};
    record.add({
        .id = "kernel.normal_velocity_change",
        .statement = "With restitution e: x1·n − v1·n = (1 + e) m2/(m1 + m2) (v2 − v1)·n and x2·n − v2·n = "
                     "−(1 + e) m1/(m1 + m2) (v2 − v1)·n.",
        .method = "the normal components solved with lsolve() minus v1·n, v2·n; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = printed_e,
        .derived_expression = changes_e,
        .paper_display = printed_e,
        .derived_display = factored_form(changes_e),
        .depends_on = {"beyond.restitution.impulse_coefficients"},
    });
    // The multiples of d: (x1 − v1) = λ1 d in the direction form derived from the unit form, λ1 read off
    // the first component (beyond.any_normal.direction_form checks every component).
    const Vec x2_unit = add(space.v2, scale(second_coefficient_e * dot(subtract(space.v2, space.v1), n_of_d), n_of_d));
    const lst multiples{GiNaC::normal((from_unit_form.op(0) - space.v1[0]) / direction[0]),
                        GiNaC::normal((x2_unit[0] - space.v2[0]) / direction[0])};
    const lst printed_multiples{(1 + e) * s.m2 / (s.m1 + s.m2) * direction_speed_in_components,
                                -(1 + e) * s.m1 / (s.m1 + s.m2) * direction_speed_in_components};
    record.add({
        .id = "kernel.direction_velocity_change",
        .statement = "Along a direction d (not necessarily unit) the velocities change by λ1 d and λ2 d with "
                     "λ1 = (1 + e) m2/(m1 + m2) ((v2 − v1)·d)/(d·d) and λ2 = −(1 + e) m1/(m1 + m2) ((v2 − v1)·d)/(d·d).",
        .method = "n = d/√(d·d) substituted into the unit form (3-D components); (x_i − v_i)/d read off the first "
                  "component; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = printed_multiples,
        .derived_expression = multiples,
        .paper_display = lst{(1 + e) * s.m2 / (s.m1 + s.m2) * s.relative_direction_speed,
                             -(1 + e) * s.m1 / (s.m1 + s.m2) * s.relative_direction_speed},
        .depends_on = {"beyond.any_normal.direction_form", "beyond.restitution.impulse_coefficients"},
    });
    // Only approaching balls: the relative speed along d clamped as beyond.approaching.kernel_form proves.
    const ex clamped = approach_speed.subs(speed == direction_speed_in_components);
    const lst approaching{GiNaC::normal(multiples.op(0) / direction_speed_in_components) * clamped,
                          GiNaC::normal(multiples.op(1) / direction_speed_in_components) * clamped};
    const ex printed_clamp = (direction_speed_in_components - GiNaC::abs(direction_speed_in_components)) / 2;
    const lst printed_approaching{(1 + e) * s.m2 / (s.m1 + s.m2) * printed_clamp,
                                  -(1 + e) * s.m1 / (s.m1 + s.m2) * printed_clamp};
    record.add({
        .id = "kernel.approaching_direction_velocity_change",
        .statement = "Resolving only approaching balls along d: λ1 and λ2 with ((v2 − v1)·d)/(d·d) replaced by "
                     "σ = (s − |s|)/2 of it, which is the collision when (v2 − v1)·d < 0 and no change otherwise.",
        .method = "the multiples of kernel.direction_velocity_change divided by their speed, times the clamped "
                  "speed of beyond.approaching.kernel_form; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = printed_approaching,
        .derived_expression = approaching,
        .paper_display = lst{(1 + e) * s.m2 / (s.m1 + s.m2) * s.approach_direction_speed,
                             -(1 + e) * s.m1 / (s.m1 + s.m2) * s.approach_direction_speed},
        .depends_on = {"kernel.direction_velocity_change", "beyond.approaching.kernel_form"},
    });
  }

  // ---- The emitted kernels -------------------------------------------------------------------
  // Every kernel uses the mass-ratio form (beyond.immovable.mass_ratio_form); the paper's elastic one
  // is the same with e = 1. Coefficients are emitted as magnitudes with the sign on the product, so
  // swapping the balls swaps the results bit for bit, and equal masses give exactly (1 + e)/2. Each
  // kernel is validated against the claim it `equals` before it is printed.
  {
    const GiNaC::symbol first_ratio("first_mass_ratio"), second_ratio("second_mass_ratio");
    const GiNaC::symbol first_name("first_impulse_coefficient"), second_name("second_impulse_coefficient");
    const GiNaC::symbol speed_name("relative_normal_speed"), direction_speed("direction_speed");
    const GiNaC::symbol approach_name("approach_speed");
    const GiNaC::realsymbol v1d("v1d"), v2d("v2d");
    const GiNaC::possymbol ddot("dd");
    const auto magnitude = [](const ex& coefficient) {
      return prints_negative(coefficient) ? ex(-coefficient) : coefficient;
    };
    const auto with_sign = [](const ex& coefficient, const ex& product) {
      return prints_negative(coefficient) ? ex(-product) : product;
    };
    // The two changes for restitution `restitution` (e, or 1) and speed `by`: the ratio form c1 · by, or
    // the small-mass form where c1 = (1 + e)/(1 + m1/m2) has dropped below the smallest normal number
    // and so lost digits (beyond.immovable.small_mass_form), likewise for ball 2. Each change is a
    // product whose two factors are chosen, never computed, under the condition: so no operation
    // depends on it, and compilers vectorise a loop of kernels with plain selects (GCC would not
    // if-convert a division or product made conditional, short of AVX-512 masks).
    const GiNaC::symbol first_change("first_change"), second_change("second_change");
    const GiNaC::symbol first_factor("first_factor"), second_factor("second_factor");
    const GiNaC::symbol first_multiplier("first_multiplier"), second_multiplier("second_multiplier");
    const GiNaC::symbol speed_per_mass("impulse_per_total_mass");
    const std::string small_mass = "beyond.immovable.small_mass_form";
    const auto change_steps = [&](const ex& restitution, const ex& by) {
      const ex first = first_ratio_form.subs(lst{e == restitution, rho1 == first_ratio});
      const ex second = second_ratio_form.subs(lst{e == restitution, rho2 == second_ratio});
      // In the small-mass form (1 + e) s/(m1 + m2) is computed first and the light mass multiplies it
      // last: the product then rounds once, even into the subnormal range, where m2 (1 + e) s would
      // round at every step; and (1 + e) s/(m1 + m2) cannot overflow there (c1 below the smallest
      // normal means m1/m2 > 2^1022 (double), so m1 + m2 ≥ 2 ε).
      const ex per_mass = (1 + restitution) * by / (s.m1 + s.m2);
      const ex in_per_mass = speed == speed_per_mass * (s.m1 + s.m2) / (1 + restitution);
      const ex first_small = magnitude(first_small_mass_form.subs(e == restitution).subs(in_per_mass));
      const ex second_small = magnitude(second_small_mass_form.subs(e == restitution).subs(in_per_mass));
      const auto tiny = [&](const GiNaC::symbol& coefficient, const ex& alternative) {
        return Guard{coefficient < smallest_normal(), alternative, Guard::Kind::same_value, small_mass};
      };
      return std::vector<KernelStep>{
          {first_ratio, s.m1 / s.m2},
          {second_ratio, s.m2 / s.m1},
          {first_name, magnitude(first)},
          {second_name, magnitude(second)},
          {speed_per_mass, per_mass},
          // The small-mass form's factors, read off the derived form: per_mass times the light mass.
          {first_factor, first_name, {tiny(first_name, speed_per_mass)}},
          {first_multiplier, by, {tiny(first_name, GiNaC::normal(first_small / speed_per_mass))}},
          {first_change, first_factor * first_multiplier},
          {second_factor, second_name, {tiny(second_name, speed_per_mass)}},
          {second_multiplier, by, {tiny(second_name, GiNaC::normal(second_small / speed_per_mass))}},
          {second_change, second_factor * second_multiplier}};
    };
    const auto outputs = [&] {
      return std::vector<ex>{with_sign(first_ratio_form, first_change),
                             with_sign(second_ratio_form, second_change)};
    };
    const auto steps_then = [](std::vector<KernelStep> first, std::vector<KernelStep> then) {
      first.insert(first.end(), then.begin(), then.end());
      return first;
    };
    // The direction kernels' parameters in the claims' terms: dot products in 3-D components.
    const GiNaC::exmap direction_terms{{v1d, dot(space.v1, direction)}, {v2d, dot(space.v2, direction)}, {ddot, dd}};
    result.kernels.push_back({
        .name = "elastic_normal_velocity_change",
        .brief = "The paper's perfectly elastic collision in normal components: the changes x1·n − v1·n and "
                 "x2·n − v2·n of the two balls' velocities along the unit contact normal n, from the masses "
                 "and v1·n, v2·n. A mass may be +∞ (an immovable body), not both.",
        .parameters = {s.m1, s.m2, s.v1n, s.v2n},
        .steps = steps_then({{speed_name, s.v2n - s.v1n}}, change_steps(1, speed_name)),
        .outputs = outputs(),
        .equals = "kernel.elastic_normal_velocity_change",
        .claims = {"result.x1_simplified_form", "result.x2_by_symmetry", "kernel.impulse_coefficient_first",
                   "kernel.impulse_coefficient_second", "beyond.immovable.mass_ratio_form"},
    });
    result.kernels.push_back({
        .name = "normal_velocity_change",
        .brief = "A collision with coefficient of restitution e (0 ≤ e ≤ 1; e = 1 is the paper's): the "
                 "changes x1·n − v1·n and x2·n − v2·n along the unit contact normal n. A mass may be +∞.",
        .parameters = {s.m1, s.m2, s.v1n, s.v2n, e},
        .steps = steps_then({{speed_name, s.v2n - s.v1n}}, change_steps(e, speed_name)),
        .outputs = outputs(),
        .equals = "kernel.normal_velocity_change",
        .claims = {"beyond.restitution.impulse_coefficients", "beyond.immovable.mass_ratio_form",
                   "beyond.restitution.energy_loss"},
        .names = {{"restitution_factor", 1 + e}},
    });
    result.kernels.push_back({
        .name = "direction_velocity_change",
        .brief = "The same along a direction d that need not be a unit vector: the multiples of d to add to "
                 "v1 and v2, from the masses, v1·d, v2·d, d·d and e. d must not be zero.",
        .parameters = {s.m1, s.m2, v1d, v2d, ddot, e},
        .steps = steps_then({{direction_speed, (v2d - v1d) / ddot}}, change_steps(e, direction_speed)),
        .outputs = outputs(),
        .equals = "kernel.direction_velocity_change",
        .in_claim_terms = direction_terms,
        .claims = {"beyond.any_normal.direction_form", "beyond.any_normal.scale_invariant",
                   "beyond.immovable.mass_ratio_form"},
        .names = {{"restitution_factor", 1 + e}},
    });
    result.kernels.push_back({
        .name = "approaching_direction_velocity_change",
        .brief = "Like direction_velocity_change with d pointing from ball 1 to ball 2, but only for "
                 "approaching balls ((v2 − v1)·d < 0); separating or resting contacts are left unchanged "
                 "(zero change), so rounding can never make a separating pair collide again.",
        .parameters = {s.m1, s.m2, v1d, v2d, ddot, e},
        .steps = steps_then({{direction_speed, (v2d - v1d) / ddot},
                             {approach_name, (direction_speed - GiNaC::abs(direction_speed)) / 2}},
                            change_steps(e, approach_name)),
        .outputs = outputs(),
        .equals = "kernel.approaching_direction_velocity_change",
        .in_claim_terms = direction_terms,
        .claims = {"beyond.approaching.kernel_form", "beyond.approaching.resolve_only_approaching",
                   "beyond.any_normal.direction_form", "beyond.immovable.mass_ratio_form"},
        .names = {{"restitution_factor", 1 + e}},
    });
    const GiNaC::realsymbol vn("vn");
    result.kernels.push_back({
        .name = "cushion_normal_velocity_change",
        .brief = "A ball meeting an immovable cushion (the paper's limit m2 → ∞ with v2 = 0): the change "
                 "x·n − v·n of its velocity along the unit contact normal n, from v·n.",
        .parameters = {vn},
        .steps = {},
        .outputs = {cushion_change.subs(s.v1n == vn)},
        .equals = "kernel.cushion_velocity_change",
        .in_claim_terms = {{vn, s.v1n}},
        .claims = {"cushion.limit"},
    });
    // The raw derivation, for the benchmark: the coefficients A, B, C as read off, D = B² − 4AC, and the
    // root (−B ± √D)/(2A) with the sign of (v2 − v1)·n, the collision root whichever the sign
    // (roots.quadratic_formula.*: for s ≥ 0 the "+" root is (P·n + m2 s)/(m1 + m2), for s < 0 the "−"
    // one); x2·n from momentum.
    {
      const GiNaC::symbol a_name("quadratic_a"), b_name("quadratic_b"), c_name("quadratic_c");
      const GiNaC::symbol d_name("discriminant"), root_name("signed_root"), x1_name("x1n"), x2_name("x2n");
      result.reference_kernels.push_back({
          .name = "raw_normal_velocity_change",
          .brief = "For the benchmark only: the paper's derivation before simplification. The quadratic in "
                   "x1·n with its coefficients as read off, D = B² − 4AC, the root (−B ± √D)/(2A) with the "
                   "sign of (v2 − v1)·n (the collision root), x2·n from momentum; returns the changes x1·n − "
                   "v1·n and x2·n − v2·n. Finite masses only.",
          .parameters = {s.m1, s.m2, s.v1n, s.v2n},
          .steps = {{a_name, A},
                    {b_name, B},
                    {c_name, C},
                    // D ≥ 0 exactly (discriminant.nonnegative); rounding can make it negative when the
                    // contact is nearly tangent, and √ of that would be NaN.
                    {d_name,
                     b_name * b_name - 4 * a_name * c_name,
                     {{d_name < 0, 0, Guard::Kind::unreachable, "discriminant.nonnegative"}}},
                    {root_name,
                     GiNaC::sqrt(d_name),
                     {{s.v2n - s.v1n < 0, -GiNaC::sqrt(d_name), Guard::Kind::piecewise,
                       "roots.quadratic_formula.relative_speed_negative"}}},
                    {x1_name, (-b_name + root_name) / (2 * a_name)},
                    {x2_name, x2n_solved.subs(s.x1n == x1_name)}},
          .outputs = {x1_name - s.v1n, x2_name - s.v2n},
          .equals = "kernel.elastic_normal_velocity_change",
          .claims = {"quadratic.coefficient_a", "quadratic.coefficient_b", "quadratic.coefficient_c",
                     "discriminant.paper_form", "roots.quadratic_formula.relative_speed_nonnegative",
                     "quadratic.x2_from_momentum"},
      });
    }
    // The time of impact in the dot products pp = p·p, pv = p·w, vv = w·w: the coefficients read off
    // in components, the last component eliminated through each dot product.
    const GiNaC::realsymbol pp("pp"), pv("pv"), vv("vv");
    const ex b_in_dots = GiNaC::normal(coefficient_b.subs(p[2] == (pv - p[0] * w[0] - p[1] * w[1]) / w[2]));
    const ex c_in_dots = reduce_modulo(coefficient_c, GiNaC::pow(p[2], 2) == pp - p[0] * p[0] - p[1] * p[1]);
    const ex a_in_dots = reduce_modulo(coefficient_a, GiNaC::pow(w[2], 2) == vv - w[0] * w[0] - w[1] * w[1]);
    // D in Lagrange's form, (w·w) r² − |p × w|² (beyond.time_of_impact.discriminant): D + |p × w|²
    // expanded in components is (w·w) r², written in vv. Unlike b² − a c it does not cancel when the
    // spheres are far apart (r ≪ |p|), where b² and a c agree in all but their last digits.
    const GiNaC::realsymbol cross_squared("cross_squared");
    const ex lagrange_in_dots = reduce_modulo((quarter_discriminant + dot(cross, cross)).expand(),
                                              GiNaC::pow(w[2], 2) == vv - w[0] * w[0] - w[1] * w[1]) -
                                cross_squared;
    const GiNaC::symbol gap("gap"), discriminant("discriminant"), contact_time("contact_time");
    const lst in_kernel{qb == b_in_dots, qc == gap};  // the stable form c/(√D − b) has no a
    // The dot products in the claims' terms, inverting what was read off: b = pv, c = pp − r², a = vv,
    // D = a r² − |p × w|², and √D for the claims' s.
    const GiNaC::exmap time_terms{{pv, qb},
                                  {pp, GiNaC::lsolve(c_in_dots == qc, pp)},
                                  {vv, GiNaC::lsolve(a_in_dots == qa, vv)},
                                  {cross_squared, GiNaC::lsolve(lagrange_in_dots.subs(vv == qa) == qd, cross_squared)},
                                  {root_of_d, GiNaC::sqrt(qd)}};
    using Kind = Guard::Kind;
    result.kernels.push_back({
        .name = "time_of_impact",
        .brief =
            "The time until two spheres moving in straight lines first touch: from pp = p·p, pv = p·w, "
            "vv = w·w and cross_squared = |p × w|² (in any dimension the sum over i < j of (p_i w_j − "
            "p_j w_i)²), with p = p2 − p1 and w = v2 − v1 (relative position and velocity), and the "
            "contact distance r1 + r2. Returns the earliest t ≥ 0 at which they touch while approaching; "
            "0 when they already touch (or overlap by rounding) and approach; +∞ when they never touch "
            "(separating, no relative motion, a miss or a graze).",
        .parameters = {pp, pv, vv, cross_squared, contact_distance},
        .steps = {{gap, c_in_dots},
                  {discriminant, lagrange_in_dots},
                  {contact_time,
                   stable_root.subs(in_kernel).subs(root_of_d == GiNaC::sqrt(discriminant)),
                   {{gap < 0, 0, Kind::piecewise, "beyond.time_of_impact.touching_now"},
                    {discriminant <= 0, infinity(), Kind::piecewise, "beyond.time_of_impact.grazing"},
                    {pv >= 0, infinity(), Kind::piecewise, "beyond.time_of_impact.no_contact"}}}},
        .outputs = {contact_time},
        .equals = "beyond.time_of_impact.stable_form",
        .in_claim_terms = time_terms,
        .claims = {"beyond.time_of_impact.quadratic", "beyond.time_of_impact.discriminant"},
    });
  }

  return result;
}

}  // namespace billiards::derive
