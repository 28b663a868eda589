// The kernel form: what a model hands the emitter. A kernel is a sequence of named steps in its
// parameters and the steps before; its outputs are proven equal to the derived expression of one
// verified claim (validate.hpp) before anything is printed.
#pragma once

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace billiards::derive {

/// An override of a kernel step: under `condition` (a relational such as `x > y`, `x <= y`), the step
/// takes `alternative` instead of its usual expression. Later guards of a step win.
struct Guard {
  enum class Kind {
    /// The same quantity in another form, for inputs where the usual form would lose it to rounding.
    /// Validated: with every guard of the same condition taken, the outputs still equal the kernel's
    /// claim. An exact evaluation may ignore it.
    same_value,
    /// A different expression where the condition holds. Validated: either the outputs still equal
    /// the kernel's claim given the condition (e.g. the sign of a square root chosen by a sign), or
    /// the condition and the value are a case stated by `claim` (no contact: +∞). An exact
    /// evaluation must honour it.
    piecewise,
    /// A condition that never holds in exact arithmetic, only after rounding: `x < 0` where `claim` is
    /// a verified sign claim that x ≥ 0. Validated against that claim.
    unreachable,
    /// A value no output sees: where the condition holds, piecewise guards of the same condition
    /// override every output that would read the step. For a step whose usual form would fault there
    /// and cost time doing so, e.g. the argument of a square root that is negative where the kernel
    /// returns +∞ anyway (√ of a negative number raises the invalid flag and, under errno, calls into
    /// libm). Validated: with it taken or not, beside those piecewise guards and any combination of the
    /// others, every output is the same. An exact evaluation honours it, as the code does.
    overridden,
  };
  GiNaC::ex condition;
  GiNaC::ex alternative;
  Kind kind = Kind::same_value;
  std::string claim = {};  ///< the audit claim that vouches for this guard
};

/// A named quantity of an emitted kernel, `const Scalar name = expression;`, or with guards
/// `Scalar name = expression; if (condition) name = alternative; ...`.
struct KernelStep {
  GiNaC::symbol name;    ///< its C++ name, as a symbol later steps and outputs use
  GiNaC::ex expression;  ///< in the kernel's parameters, earlier steps and named constants
  std::vector<Guard> guards = {};
};

/// A faster form for part of the inputs: where every condition holds, the kernel returns the outputs of
/// kernel `kernel` (printed before it, with the same parameters, proven equal to the same claim)
/// before computing its own steps. Printed as a call of the predicate `predicate` (its parameters: the
/// kernel's parameters the conditions read, in order), itself printed once from the conditions.
struct FastPath {
  std::string predicate;              ///< the C++ name of the range test, e.g. within_plain_mass_range
  std::string brief;                  ///< one sentence for the predicate's comment
  std::vector<GiNaC::ex> conditions;  ///< relationals in parameters and named constants, all must hold
  std::string kernel;                 ///< the kernel taken where they hold
  std::string claim;                  ///< the audit claim that vouches for that kernel's form there
};

/// The struct a kernel with two outputs returns: its name and what it and its members hold.
struct PairResult {
  std::string name = "NormalVelocityChange";
  std::string brief;
  std::string first = "the first output";
  std::string second = "the second output";
};

/// A scalar kernel for the emitter.
struct Kernel {
  std::string name;                   ///< the C++ function name
  std::string brief;                  ///< one sentence for its comment
  std::vector<GiNaC::ex> parameters;  ///< symbols, in signature order; their names are the C++ names
  std::vector<KernelStep> steps;
  std::vector<GiNaC::ex> outputs;  ///< one: returns Scalar; two: a PairResult {first, second}
  /// The struct it returns when it has two outputs; unset, the model's (ModelInfo::pair_result).
  std::optional<PairResult> pair = {};
  /// The verified claim whose derived expression (a list, one element per output) the outputs equal.
  std::string equals = {};
  /// The kernel's parameters in the claims' terms (e.g. v1d → v1·d in components), applied to both
  /// sides before comparing; empty when the kernel's parameters are the claim's own symbols.
  GiNaC::exmap in_claim_terms = {};
  /// Further audit claims it implements, named in its comment beside `equals` and the guards' claims.
  std::vector<std::string> claims = {};
  /// Names for common subexpressions the emitter hoists, e.g. "restitution_factor" for 1 + e.
  std::vector<std::pair<std::string, GiNaC::ex>> names = {};
  /// Taken first, where its conditions hold: a faster form of the same claim.
  std::optional<FastPath> fast_path = {};
  /// Where this kernel keeps its accuracy when that is less than every valid input: relationals (a fast
  /// path's conditions) that its inputs must meet. The accuracy tool draws its inputs inside them.
  std::vector<GiNaC::ex> domain = {};
  /// The rounding proof's cases (prove/rounding.hpp). Every kernel that is not a reference kernel needs a
  /// domain or at least one case, or billiards-derive fails: its error bound is proven over them. In
  /// each, relationals `a <= x`, `x <= b`, `x < 2^k` or `-2^k < x` (the bounds numbers or named constants'
  /// expressions) bounding the quantities the domain leaves free — restitution in [0, 1], a speed such as
  /// v2n − v1n in one binade, [1, 2] (its outputs scale exactly with it, and its sign only turns them, so
  /// one binade stands for every magnitude at which they are normal numbers), a mass beyond the plain
  /// range. Each case is proven on its own; none means the domain alone.
  std::vector<std::vector<GiNaC::ex>> rounding_cases = {};
  /// Rewritings Gappa is given beside each of its proofs (`a -> b;`, in the script's names: p_<parameter>
  /// for a parameter, c_<step> computed and e_<step> exact): how errors the steps keep cancel, e.g. that a
  /// product's rounding error taken by std::fma makes the product exact again.
  std::vector<std::string> gappa_hints = {};
  /// The relative error, in ε, that every case's proven bound must meet; billiards-derive fails where
  /// Gappa proves no bound within it. Unset: any bound below 2^−10 is taken.
  std::optional<int> promised_error = {};
};

/// A monomial c Π x_i^(a_i) (c a number or an expression in other symbols, each a_i an integer)
/// computed on significands: for each x_i of `parameters` it reads, the steps `<x_i>_exponent` =
/// binary_exponent(x_i) and `scaled_<x_i>` = x_i · 2^−exponent, in [1, 2); then `scaled_<name>`, the
/// monomial of those, and `<name>_exponent` = Σ a_i exponent_i. `value` is scaled_<name> ·
/// 2^<name>_exponent: nothing overflows or underflows before this last scaling, which rounds once
/// (core/powers_of_two.hpp).
struct ScaledMonomial {
  std::vector<KernelStep> steps;
  GiNaC::ex value;
  GiNaC::exmap scaled;    ///< each parameter read → its step `scaled_<x_i>`
  GiNaC::exmap exponent;  ///< each parameter read → its step `<x_i>_exponent`
};
/// Throws std::invalid_argument when `monomial` is not a monomial in `parameters` of integer degrees.
ScaledMonomial scaled_monomial(const std::string& name, const GiNaC::ex& monomial,
                               const std::vector<GiNaC::ex>& parameters);

/// The name of the function that holds every step of a kernel with a fast path, `full_<name>`: the kernel
/// itself is printed as its range test, the fast kernel's call and a call of this one.
std::string full_form_name(const Kernel& kernel);

/// Every claim a kernel cites, in order and without repeats: `equals`, `claims`, the guards' claims, the
/// fast path's claim.
std::vector<std::string> cited_claims(const Kernel& kernel);

}  // namespace billiards::derive
