#include "core/claim.hpp"

#include "core/algebra.hpp"

#include <algorithm>
#include <numeric>

namespace billiards::derive {

namespace {
thread_local std::string building;
}  // namespace

ClaimUnderConstruction::ClaimUnderConstruction(const std::string& id) { building = id; }

const std::string& claim_being_built() { return building; }

void clear_claim_being_built() { building.clear(); }

using GiNaC::ex;

namespace {

// Zero of a single difference: normal() brings it to numerator/denominator; the numerator is then
// reduced modulo each constraint (n·n = 1). Returns what is left, 0 when the identity holds.
ex identity_residual(const ex& difference, const std::vector<Constraint>& constraints) {
  const ex numerator_denominator = GiNaC::normal(difference).numer_denom();
  ex numerator = numerator_denominator.op(0).expand();
  for (const Constraint& constraint : constraints) numerator = reduce_modulo(numerator, constraint.relation);
  return GiNaC::normal(numerator / numerator_denominator.op(1));
}

// Componentwise residuals of two expressions that are both lists, or both single expressions.
ex residual_of(const ex& derived, const ex& paper, const std::vector<Constraint>& constraints) {
  if (GiNaC::is_a<GiNaC::lst>(derived) != GiNaC::is_a<GiNaC::lst>(paper)) return derived - paper;
  if (!GiNaC::is_a<GiNaC::lst>(derived)) return identity_residual(derived - paper, constraints);
  if (derived.nops() != paper.nops()) return derived - paper;
  GiNaC::lst residuals;
  for (std::size_t i = 0; i < derived.nops(); ++i) {
    residuals.append(identity_residual(derived.op(i) - paper.op(i), constraints));
  }
  return residuals;
}

bool all_zero(const ex& residual) {
  if (!GiNaC::is_a<GiNaC::lst>(residual)) return residual.is_zero();
  return std::all_of(residual.begin(), residual.end(), [](const ex& r) { return r.is_zero(); });
}

// The paper's elements permuted so that they pair with the derived ones, when some order does.
ex residual_as_sets(const ex& derived, const ex& paper, const std::vector<Constraint>& constraints) {
  if (!GiNaC::is_a<GiNaC::lst>(derived) || !GiNaC::is_a<GiNaC::lst>(paper) ||
      derived.nops() != paper.nops()) {
    return residual_of(derived, paper, constraints);
  }
  std::vector<std::size_t> order(paper.nops());
  std::iota(order.begin(), order.end(), 0);
  ex first_residual;
  bool first = true;
  do {
    GiNaC::lst permuted;
    for (std::size_t i : order) permuted.append(paper.op(i));
    const ex residual = residual_of(derived, permuted, constraints);
    if (all_zero(residual)) return residual;
    if (first) first_residual = residual;
    first = false;
  } while (std::next_permutation(order.begin(), order.end()));
  return first_residual;
}

// True when every symbol in `e` is real (realsymbol, possymbol): a sign claim about a complex symbol
// proves nothing (z² ≥ 0 is false for z = i).
bool all_symbols_real(const ex& e) {
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->info(GiNaC::info_flags::real)) return false;
  }
  return true;
}

// A display in the terms of what was compared: its own symbols defined, and a vector display expanded
// into components.
ex display_as_compared(const ex& display, const Claim& claim) {
  const ex defined = display.subs(claim.display_definitions).subs(claim.display_definitions);
  if (claim.display_components.empty()) return defined;
  GiNaC::lst components;
  const auto expand = [&](const ex& element) {
    for (const GiNaC::exmap& component : claim.display_components) components.append(element.subs(component));
  };
  if (GiNaC::is_a<GiNaC::lst>(defined)) {
    for (const ex& element : defined) expand(element);
  } else {
    expand(defined);
  }
  return components;
}

// Fails the claim when a display is set that is not what was compared.
void check_displays(Claim& claim) {
  const std::pair<const ex*, const ex*> sides[] = {{&claim.paper_display, &claim.paper_expression},
                                                   {&claim.derived_display, &claim.derived_expression}};
  for (const auto& [display, expression] : sides) {
    if (GiNaC::is_a<GiNaC::fail>(*display)) continue;
    const ex residual = residual_of(*expression, display_as_compared(*display, claim), claim.constraints);
    if (all_zero(residual)) continue;
    claim.verdict = Verdict::failed;
    claim.residual = residual;
    claim.failure = std::string("the ") + (display == &claim.paper_display ? "paper" : "derived") +
                    " side shown is not the expression compared";
    return;
  }
}

void decide(Claim& claim) {
  switch (claim.comparison) {
    case Comparison::assumption:
      claim.verdict = Verdict::assumption;
      claim.residual = 0;
      return;
    case Comparison::nonnegative: {
      if (!all_symbols_real(claim.derived_expression)) {
        claim.verdict = Verdict::failed;
        claim.residual = claim.derived_expression;
        claim.failure = "a sign claim needs real symbols; the derived side has a complex one";
        return;
      }
      // The paper side, when it states an expression, must be the derived one.
      if (!claim.paper_expression.is_zero()) {
        claim.residual = residual_of(claim.derived_expression, claim.paper_expression, claim.constraints);
        if (!all_zero(claim.residual)) {
          claim.verdict = Verdict::failed;
          return;
        }
      }
      claim.verdict =
          is_manifestly_nonnegative(claim.derived_expression) ? Verdict::verified : Verdict::failed;
      claim.residual = claim.verdict == Verdict::verified ? ex(0) : GiNaC::factor(claim.derived_expression);
      return;
    }
    case Comparison::identity:
      claim.residual = residual_of(claim.derived_expression, claim.paper_expression, claim.constraints);
      break;
    case Comparison::same_set:
      claim.residual = residual_as_sets(claim.derived_expression, claim.paper_expression, claim.constraints);
      break;
  }
  claim.verdict = all_zero(claim.residual) ? Verdict::verified : Verdict::failed;
}

}  // namespace

void check(Claim& claim) {
  claim.failure.clear();
  try {
    decide(claim);
    if (claim.verdict == Verdict::verified) check_displays(claim);
  } catch (const std::exception& error) {
    claim.verdict = Verdict::failed;
    // Arithmetic on lists would throw again: the residual is then the derived side as it stands.
    const bool lists =
        GiNaC::is_a<GiNaC::lst>(claim.derived_expression) || GiNaC::is_a<GiNaC::lst>(claim.paper_expression);
    claim.residual = lists ? claim.derived_expression : claim.derived_expression - claim.paper_expression;
    claim.failure = std::string("the comparison could not be carried out: ") + error.what();
  }
}

std::string to_string(Verdict verdict) {
  switch (verdict) {
    case Verdict::verified: return "verified";
    case Verdict::failed: return "failed";
    case Verdict::assumption: return "assumption";
  }
  return "failed";
}

std::string to_string(Comparison comparison) {
  switch (comparison) {
    case Comparison::identity: return "identity";
    case Comparison::same_set: return "same set";
    case Comparison::nonnegative: return "sign";
    case Comparison::assumption: return "assumption";
  }
  return "identity";
}

}  // namespace billiards::derive
