// The prover checked: before any model is proven, every run asks its own proof machinery questions whose
// answers are known — properties Gappa must refuse and must prove, a range at the edge of overflow and one
// ulp past it, a float script whose bound holds only in double, the error bound of one rounding in each
// format, a cached answer asked for a script one line apart, and how C++ groups what the reader reads —
// by the very functions the kernels' proofs call. A wrong answer stops the run: no header is printed,
// and the audit says which canary answered what. Generic: it names no model.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace billiards::derive {

/// A question with a known answer.
struct Canary {
  std::string id;                    ///< e.g. gappa.refuses_a_false_property
  std::string statement;             ///< what it asks, in words
  std::string expected;              ///< the answer a sound prover gives
  std::function<std::string()> ask;  ///< the prover's answer, by the path the kernels' proofs take
};

/// What a canary answered.
struct CanaryOutcome {
  std::string id;
  std::string statement;
  std::string expected;
  std::string answered;
  [[nodiscard]] bool as_expected() const { return answered == expected; }
};

/// The canaries every run asks, in order.
const std::vector<Canary>& prover_canaries();

/// Asks each canary; an exception while asking is its answer ("failed: …"). Never throws.
std::vector<CanaryOutcome> ask_canaries(const std::vector<Canary>& canaries);

}  // namespace billiards::derive
