// The mutation suite: realistic mistakes, each a named edit — of the built kernel data (a slip in the
// model's kernel code), of the derivation's claims or of a header's printed text (a slip in the printer,
// the emitter or the support code it prints). Each must make billiards-derive fail with exit status 1,
// naming the kernel, function or claim it broke; a harmless edit (a comment) must pass
// (tests/derive/CMakeLists.txt runs every one through billiards-derive-mutant).
#pragma once

#include "emit/kernel.hpp"
#include "model.hpp"

#include <functional>
#include <string>
#include <vector>

namespace billiards::derive::testing {

struct Mutation {
  std::string name;    ///< what was got wrong, e.g. relative_speed_sign_flipped
  std::string kernel;  ///< the kernel `edit` edits; what the failure must name (a function or claim id)
  std::function<void(Kernel&)> edit = {};
  std::function<void(Derivation&)> edit_derivation = {};  ///< an edit of the claims, the kernels' data
  std::string header = {};  ///< the header (path in the output folder) that edit_printed edits
  std::function<std::string(const std::string&)> edit_printed = {};
  bool harmless = false;  ///< must pass: exit status 0 and the headers written
};

/// Every mutation of the paper's model.
const std::vector<Mutation>& paper_mutations();
/// Every mutation of the spinning-ball model.
const std::vector<Mutation>& spin_mutations();

/// The mutations by class, beside each model's own: of the printer (operators, literals, suffixes), of
/// the emitter (the calls a fast path prints), of printed support code (constants, ranges), of parameter
/// meanings and of claims no kernel cites; and a comment, which must pass.
const std::vector<Mutation>& paper_class_mutations();
const std::vector<Mutation>& spin_class_mutations();

/// Every mutation of the shot model.
const std::vector<Mutation>& shot_mutations();

/// The claim `id` with its typed (paper) side retyped by `retype` and checked again: a slip in typing a
/// published formula, which must fail the run naming the claim.
Mutation claim_retyped(const std::string& name, const std::string& id,
                       const std::function<GiNaC::ex(const GiNaC::ex&)>& retype);

/// `text` with `from` replaced by `to` (every occurrence, at least one) inside the body of the function
/// defined as `name(` (e.g. "plain_mass_low<double>"). Throws std::invalid_argument when there is
/// none.
std::string edit_function(const std::string& text, const std::string& name, const std::string& from,
                          const std::string& to);

/// `derivation` with `mutation` applied to its kernel (kernels or reference kernels). Throws
/// std::invalid_argument when the kernel or a name the edit looks for is missing.
void apply(const Mutation& mutation, Derivation& derivation);

}  // namespace billiards::derive::testing
