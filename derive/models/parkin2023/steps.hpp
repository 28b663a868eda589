// The paper's model: what every step shares — its symbols, the definitions P and K (perturbable for
// tests), the vectors in components — and the step functions, one per audit section, each taking what
// it reads and returning what later steps use. paper.cpp strings them together.
#pragma once

#include "core/algebra.hpp"
#include "core/record.hpp"
#include "emit/kernel.hpp"
#include "models/parkin2023/paper.hpp"
#include "print/printer.hpp"

#include <ginac/ginac.h>

#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

namespace billiards::derive::parkin2023 {

using GiNaC::ex;
using GiNaC::lst;
using GiNaC::numeric;

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

const Symbols& symbols();

/// P and K applied to vectors (a scalar is a one-component vector), with the definitions' coefficients.
Vec momentum(const Definitions& d, const Vec& a, const Vec& b);
ex kinetic(const Definitions& d, const Vec& a, const Vec& b);
ex scalar_momentum(const Definitions& d, const ex& a, const ex& b);
ex scalar_kinetic(const Definitions& d, const ex& a, const ex& b);

/// The vectors of one dimension, in components.
struct Space {
  std::size_t dimension;
  Vec v1, v2, n, x1, x2;
  Constraint unit_normal;  ///< n_d² == 1 − Σ n_i², "n·n = 1"
  std::string suffix;      ///< ".2d" or ".3d", for claim ids

  explicit Space(std::size_t d);
  /// A scalar of the derivation (in v1·n, v2·n) written in this space's components.
  ex components_of(const ex& scalar) const;
  /// The velocity v⊥ + κ n for a ball whose new normal component is `normal` (a scalar).
  Vec after_collision(const Vec& v, const ex& normal) const;
  /// For a claim's displays: v1·n and v2·n in this space's components.
  GiNaC::exmap normal_components() const;
  /// For a claim's vector displays: the vector symbols v1, v2, n, x1, x2 → component i, one map each.
  std::vector<GiNaC::exmap> vector_components() const;
};

/// For a claim's displays: the paper's shorthand P·n and K∥ by their definitions.
GiNaC::exmap shorthand(const Definitions& d);
/// The substitutions of several maps in one (a later map's entry wins).
GiNaC::exmap merged(std::initializer_list<GiNaC::exmap> maps);

/// What every step may read and none changes: the definitions and the two spaces.
struct Setting {
  Definitions definitions;
  Space plane{2};
  Space space{3};
};

lst concatenate(const Vec& a, const Vec& b);

/// Appended to a claim's method where n·n = 1 is imposed.
inline constexpr const char* unit_normal_method = "; n·n = 1 imposed by substituting n_last² → 1 − Σ n_i²";

// ---- The steps, in the paper's order -------------------------------------------------------------

void record_premises(Recorder& record, const Definitions& d);
void split_along_and_across(Recorder& record, const Setting& setting);
void frictionless_contact(Recorder& record);
void conservation_along_n(Recorder& record, const Setting& setting);

struct Quadratic {
  GiNaC::exmap paper_shorthand;  ///< P·n and K∥ by their definitions (shorthand())
  ex x2n_solved;                 ///< x2·n from momentum, in x1·n
  ex quadratic;                  ///< K(x1·n, x2·n) − K∥, a polynomial in x1·n
  ex A, B, C;                    ///< its coefficients, read off with coeff()
};
Quadratic the_quadratic(Recorder& record, const Setting& setting);

struct Discriminant {
  ex D;         ///< B² − 4AC from the coefficients
  ex relative;  ///< (v2 − v1)·n
};
Discriminant the_discriminant(Recorder& record, const Definitions& d, const Quadratic& quadratic);

struct Roots {
  ex plus_root, minus_root;  ///< x1·n for the "+" and "−" roots, |…| dropped
};
Roots the_roots(Recorder& record, const Quadratic& quadratic, const Discriminant& discriminant);

void putting_it_together(Recorder& record, const Setting& setting, const Quadratic& quadratic,
                         const Discriminant& discriminant, const Roots& roots);

struct Selection {
  ex x1n, x2n;  ///< the selected normal components: the "+" root and x2·n from momentum
};
Selection choosing_the_root(Recorder& record, const Quadratic& quadratic, const Discriminant& discriminant,
                            const Roots& roots);

void the_collision_formula(Recorder& record, const Setting& setting, const Discriminant& discriminant,
                           const Selection& selection);
void sanity_checks(Recorder& record, const Setting& setting, const Selection& selection);
void the_cushion(Recorder& record, const Setting& setting, const Selection& selection);
void end_to_end(Recorder& record, const Setting& setting, const Selection& selection);

struct KernelPieces {
  ex cushion_change;  ///< the cushion's change of v1·n, −2 v1·n
};
KernelPieces what_the_emitter_prints(Recorder& record, const Selection& selection);

// Beyond the paper.
struct Restitution {
  ex x1n, x2n;                               ///< the normal components for restitution e
  ex first_coefficient, second_coefficient;  ///< (x_i·n − v_i·n)/((v2 − v1)·n)
};
Restitution restitution(Recorder& record, const Definitions& d);

struct MassRatios {
  ex first_ratio_form, second_ratio_form;            ///< in ρ1 = m1/m2, ρ2 = m2/m1
  ex first_small_mass_form, second_small_mass_form;  ///< the changes with the speed multiplied in first
};
MassRatios immovable_bodies(Recorder& record, const Restitution& restitution);

struct PlainRange {
  ex first_mass_form, second_mass_form;  ///< (1 + e) m2/(m1 + m2) and (1 + e) m1/(m1 + m2), magnitudes
};
PlainRange plain_range(Recorder& record, const Restitution& restitution, const MassRatios& ratios);

struct Direction {
  Vec d;               ///< a direction, not necessarily unit (3-D components)
  ex dd;               ///< d·d
  Vec unit;            ///< d/√(d·d)
  lst from_unit_form;  ///< x1 with n = d/√(d·d)
};
Direction any_direction(Recorder& record, const Setting& setting, const Restitution& restitution);

struct Approaching {
  ex approach_speed;  ///< (s − |s|)/2 in the relative normal speed s
};
Approaching approaching_contacts(Recorder& record, const Definitions& d, const Selection& selection,
                                 const Restitution& restitution);

struct TimeOfImpact {
  Vec p, w;                 ///< relative position and velocity (3-D components)
  GiNaC::possymbol r;       ///< the contact distance r1 + r2
  ex a, b, c;               ///< the coefficients of a t² + 2 b t + c, read off
  ex quarter_discriminant;  ///< b² − a c in components
  Vec cross;                ///< p × w
  GiNaC::possymbol qa, root_of_d;
  GiNaC::realsymbol qb, qc, qd;  ///< a, b, c, D as symbols, and s = √D
  ex root_relation;              ///< s² = b² − a c
  ex earlier_root, later_root;   ///< (−b ∓ s)/a
  ex stable_root;                ///< c/(s − b)
};
TimeOfImpact time_of_impact_quadratic(Recorder& record);
void time_of_impact_cases(Recorder& record, const TimeOfImpact& toi);

void kernel_outputs(Recorder& record, const Setting& setting, const Selection& selection,
                    const Restitution& restitution, const Direction& direction,
                    const Approaching& approaching);

// ---- The kernels ----------------------------------------------------------------------------------

std::vector<Kernel> collision_kernels(const Setting& setting, const KernelPieces& pieces,
                                      const MassRatios& ratios, const PlainRange& plain,
                                      const Direction& direction);
Kernel time_of_impact_kernel(const TimeOfImpact& toi);
std::vector<Kernel> reference_kernels(const Quadratic& quadratic);

}  // namespace billiards::derive::parkin2023
