// Every emitted line proven: before a kernel is printed it is checked against the claims of the
// derivation. Generic: it reads a kernel and a list of claims, never a model.
#pragma once

#include "core/claim.hpp"
#include "emit/kernel.hpp"

#include <string>
#include <vector>

namespace billiards::derive {

/// Why a kernel is not proven: the kernel, the claim concerned (empty when none is) and the reason.
struct KernelProblem {
  std::string kernel;
  std::string claim;
  std::string reason;
};

/// Checks `kernel` against `claims` (exact arithmetic, GiNaC):
/// - its free symbols are its parameters, earlier steps (a guard may also read its own step) or named
///   constants, and no step reuses a name;
/// - every claim it cites exists and is verified;
/// - its outputs, every step substituted, equal the derived expression of the claim `equals` (with
///   `in_claim_terms` applied to both sides; square roots of perfect squares taken and |…| resolved
///   by the signs the branch's conditions fix), decided by check() under that claim's constraints;
/// - the same with every same_value guard of one condition taken;
/// - each piecewise guard either keeps the outputs equal to that claim given its condition, or its
///   condition (with the later guards of its step not taken) and its value are a case of its claim;
/// - each unreachable guard reads `x < 0` where its claim is a verified sign claim that x ≥ 0;
/// - each overridden guard has piecewise guards of the same condition, and taken beside them (with any
///   combination of the other guards) it leaves every output as it is.
/// Returns every problem found; none means the kernel is proven. Never throws.
std::vector<KernelProblem> validate_kernel(const Kernel& kernel, const std::vector<Claim>& claims);

/// The problems of every kernel in `kernels`, in order, and of each fast path: it must take a kernel
/// printed before it with the same parameters, claim and claim terms, whose domain is the path's
/// conditions (relationals in the parameters and named constants; one predicate name, one set). The
/// printed functions' names must be distinct: no kernel may share another's name or the name
/// `full_<name>` of a kernel with a fast path (full_form_name), where the header would define one
/// function twice.
std::vector<KernelProblem> validate_kernels(const std::vector<Kernel>& kernels,
                                            const std::vector<Claim>& claims);

}  // namespace billiards::derive
