// The derivation of S. T. Parkin, "Billiard Ball Physics" (2023), step by step from the definitions.
// Each step computes its expressions from the previous steps' output and records claims; check()
// decides every verdict.
#pragma once

#include "claim.hpp"

#include <ginac/ginac.h>

#include <string>
#include <utility>
#include <vector>

namespace billiards::derive {

/// The paper's definitions, P(a, b) = m1 a + m2 b and K(a, b) = ½ m1 a² + ½ m2 b², written as the
/// coefficients of each term so that a test can perturb one and watch the claims downstream fail.
struct Definitions {
  GiNaC::ex momentum_coefficient_1 = 1;
  GiNaC::ex momentum_coefficient_2 = 1;
  GiNaC::ex kinetic_coefficient_1 = GiNaC::numeric(1, 2);
  GiNaC::ex kinetic_coefficient_2 = GiNaC::numeric(1, 2);
};

/// A definition or an input the derivation starts from, shown at the head of the audit.
struct Premise {
  std::string id;
  std::string statement;
  GiNaC::ex display;
};

struct Section {
  std::string id;
  std::string title;
  std::string text;  ///< what the step does, in the paper's terms
};

/// What the derivation selected, for the code emitter: scalar expressions in the normal components
/// v1·n, v2·n and the masses.
struct SelectedResult {
  GiNaC::ex x1_normal;  ///< x1·n, the selected root
  GiNaC::ex x2_normal;  ///< x2·n, from momentum conservation
};

/// An override of a kernel step: under `condition` (a relational such as `x > y`, `x <= y`), the step
/// takes `alternative` instead of its usual expression. Later guards of a step win.
struct Guard {
  enum class Kind {
    /// The same quantity in another form (an identity the audit checks), for inputs where the usual
    /// form would lose it to rounding: an exact evaluation may ignore the guard.
    same_value,
    /// A different value where the usual expression does not apply (no contact: +∞): part of the
    /// kernel's definition, which an exact evaluation must honour.
    piecewise,
  };
  GiNaC::ex condition;
  GiNaC::ex alternative;
  Kind kind = Kind::same_value;
};

/// A named quantity of an emitted kernel, `const Scalar name = expression;`, or with guards
/// `Scalar name = expression; if (condition) name = alternative; ...`.
struct KernelStep {
  GiNaC::symbol name;    ///< its C++ name, as a symbol later steps and outputs use
  GiNaC::ex expression;  ///< derived, in the kernel's parameters and earlier steps
  std::vector<Guard> guards = {};
};

/// A scalar kernel for the emitter: derived expressions in its parameters (masses and normal
/// components), and the audit claims that vouch for them.
struct Kernel {
  std::string name;                   ///< the C++ function name
  std::string brief;                  ///< one sentence for its comment
  std::vector<GiNaC::ex> parameters;  ///< symbols, in signature order; their names are the C++ names
  std::vector<KernelStep> steps;
  std::vector<GiNaC::ex> outputs;  ///< one: returns Scalar; two: NormalVelocityChange {first, second}
  std::vector<std::string> claims;
  /// Names for common subexpressions the emitter hoists, e.g. "total_mass" for m1 + m2.
  std::vector<std::pair<std::string, GiNaC::ex>> names;
};

struct Derivation {
  std::vector<Premise> premises;
  std::vector<Section> sections;
  std::vector<Claim> claims;  ///< in the paper's order, every verdict decided
  SelectedResult selected;
  std::vector<Kernel> kernels;  ///< what the emitter prints, each vouched for by claims above
  /// The raw derivation before simplification (the quadratic formula with √D), for the benchmark
  /// only: printed into billiards/reference_kernels.hpp, never part of the runtime.
  std::vector<Kernel> reference_kernels;
};

/// Runs every step with the given definitions (the paper's by default) and checks every claim.
Derivation derive_paper(const Definitions& definitions = {});

struct Summary {
  int verified = 0;
  int failed = 0;
  int assumption = 0;
};
Summary summarize(const std::vector<Claim>& claims);

/// The ids of `claims` that rest, directly or through other claims, on the premise or claim `id`.
std::vector<std::string> downstream_of(const std::vector<Claim>& claims, const std::string& id);

}  // namespace billiards::derive
