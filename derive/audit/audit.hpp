// The derivation audit, for people (Markdown) and for machines (JSON). Both are pure functions of
// the derivation: no timestamps, no paths, stable order.
#pragma once

#include "emit/validate.hpp"
#include "model.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace billiards::derive {

/// The GiNaC library version the derivation ran with, e.g. "1.8.6".
std::string ginac_version();

std::string audit_markdown(const Derivation& derivation);
std::string audit_json(const Derivation& derivation);

/// What billiards-derive prints for one model: the summary and the files written to `out`, and to `err`
/// one line per failed claim naming it and its residual (or why its comparison failed) and one line per
/// kernel problem naming the kernel and the claim. Returns the number of failed claims plus problems.
int report(const Derivation& derivation, const std::vector<KernelProblem>& problems,
           const std::vector<std::string>& written, std::ostream& out, std::ostream& err);

/// The latex of what the audit shows for each side of a claim: the display form when one is set (which
/// check() proves equal to the compared expression), otherwise the expression itself; a label, when
/// set, stands beside it as "label = …".
std::string paper_latex(const Claim& claim);
std::string derived_latex(const Claim& claim);

}  // namespace billiards::derive
