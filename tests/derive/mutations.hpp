// The mutation suite: realistic mistakes in a model's kernels, each a named edit of the built kernel
// data — what a slip in the model's kernel code would produce. Each must make billiards-derive fail
// with exit status 1, naming the kernel (tests/derive/CMakeLists.txt runs every one through
// billiards-derive-mutant).
#pragma once

#include "emit/kernel.hpp"
#include "model.hpp"

#include <functional>
#include <string>
#include <vector>

namespace billiards::derive::testing {

struct Mutation {
  std::string name;    ///< what was got wrong, e.g. relative_speed_sign_flipped
  std::string kernel;  ///< the kernel it edits, which the failure must name
  std::function<void(Kernel&)> edit;
};

/// Every mutation of the paper's model.
const std::vector<Mutation>& paper_mutations();
/// Every mutation of the spinning-ball model.
const std::vector<Mutation>& spin_mutations();

/// `derivation` with `mutation` applied to its kernel (kernels or reference kernels). Throws
/// std::invalid_argument when the kernel or a name the edit looks for is missing.
void apply(const Mutation& mutation, Derivation& derivation);

}  // namespace billiards::derive::testing
