// A claim is data: what the paper prints, what the program derived, how the two are compared, and
// the verdict. One small function, check(), decides every verdict.
#pragma once

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace billiards::derive {

enum class Verdict { verified, failed, assumption };

/// A relation x² == r imposed by substitution before comparing, with the words the audit prints.
struct Constraint {
  GiNaC::ex relation;
  std::string words;  ///< e.g. "n·n = 1"
};

/// A case a claim establishes: where every condition (relationals) holds, the quantity is `value`. A
/// kernel's piecewise guard is validated against such a case.
struct Case {
  GiNaC::lst conditions;
  /// The value under the conditions: one expression, or for a claim whose derived expression is a
  /// list, a list of the same length (a kernel's outputs, each in its place).
  GiNaC::ex value;
};

/// How check() compares the derived expression with the paper's.
enum class Comparison {
  /// derived − paper is exactly zero (componentwise for lists) after normal(), and after reducing
  /// the numerator modulo the claim's `constraints` (e.g. n·n = 1) when there are any.
  identity,
  /// derived and paper are lists holding the same elements in some order, each pair an identity.
  same_set,
  /// derived factors into positive constants, positive symbols and even powers of real expressions:
  /// it is ≥ 0. Every symbol in it must be real. When the paper side is not 0 it must also equal the
  /// derived side (an identity), so the audit's "as typed" is what was shown to be ≥ 0.
  nonnegative,
  /// Not checked: a modelling assumption, stated with its reason.
  assumption,
};

/// Notes, as a claim is built, which claim that is: a member of Claim initialised right after its id, so
/// that while the rest of a `Claim{.id = …, …}` is computed, claim_being_built() names it. An exception
/// in a derivation step then names the claim it stopped in (record_steps in core/record.hpp).
struct ClaimUnderConstruction {
  explicit ClaimUnderConstruction(const std::string& id);
  ClaimUnderConstruction(const ClaimUnderConstruction&) = default;
  ClaimUnderConstruction& operator=(const ClaimUnderConstruction&) = default;
};

/// The id of the claim most recently begun and not yet recorded (Recorder::add clears it); empty when
/// none is.
const std::string& claim_being_built();
/// Forgets the claim being built (Recorder::add, once the claim is recorded).
void clear_claim_being_built();

struct Claim {
  std::string id;                                 ///< stable and descriptive, e.g. "discriminant.factored"
  ClaimUnderConstruction under_construction{id};  ///< names this claim while the rest is computed
  std::string section;    ///< the audit section (a step of the derivation) it belongs to
  std::string paper;      ///< where it stands in the paper; empty when the paper does not state it
  std::string paper_tex;  ///< the paper's equation, verbatim LaTeX from the paper; empty if it prints none
  std::string statement;  ///< one sentence a reader can check
  std::string method;     ///< how the derived side was obtained and compared, in words
  Comparison comparison = Comparison::identity;
  GiNaC::ex paper_expression;           ///< typed exactly as the paper prints it
  GiNaC::ex derived_expression;         ///< computed by the derivation, never typed
  std::vector<Constraint> constraints;  ///< imposed by substitution before comparing
  /// Shown in the audit instead of paper_expression (a readable form: shorthand, vectors): check()
  /// proves it equal to what was compared, or the claim fails. Unset: the expression itself is shown.
  GiNaC::ex paper_display = GiNaC::fail();
  GiNaC::ex derived_display = GiNaC::fail();  ///< likewise for derived_expression
  GiNaC::ex paper_label = GiNaC::fail();      ///< a name shown beside the paper side, e.g. P(x1, x2)
  GiNaC::ex derived_label = GiNaC::fail();    ///< a name shown beside the derived side
  /// What the displays' own symbols stand for (P·n → m1 v1·n + m2 v2·n), substituted before comparing.
  GiNaC::exmap display_definitions = {};
  /// For displays written with vector symbols (v1 + κ n) against a list of components: the substitution
  /// that turns the display into component i (v1 → v1_x, n → n_x). Each element of a list display
  /// expands into as many components.
  std::vector<GiNaC::exmap> display_components = {};
  std::string note;                     ///< where the paper is imprecise, or what the claim adds
  std::vector<std::string> depends_on;  ///< definitions and claims it rests on
  std::vector<Case> cases = {};         ///< the piecewise cases it establishes, if any

  Verdict verdict = Verdict::failed;  ///< set by check()
  GiNaC::ex residual = 0;             ///< set by check(): what is left of derived − paper
  std::string failure;                ///< set by check() when the comparison itself failed: the reason
};

/// Decides `claim.verdict` and `claim.residual`. Never throws: anything that is not shown to be zero
/// is a failure, with the residual to show for it, and an exception inside the comparison (GiNaC
/// cannot reduce an expression) is a failure with its message in `claim.failure`.
void check(Claim& claim);

std::string to_string(Verdict verdict);
std::string to_string(Comparison comparison);

}  // namespace billiards::derive
