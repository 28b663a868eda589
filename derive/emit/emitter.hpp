// The C++ emitter: prints the derivation's kernels as a header of `template <typename Scalar>`
// functions. GiNaC's csrc printers are not used (they print pow(), double literals and, in 1.8.6, drop
// the reciprocal of a power with exponent −1.0); printer.cpp's C++ notation prints integer powers as
// products and every number as Scalar(integer). Common subexpressions are hoisted into named consts.
#pragma once

#include "emit/kernel.hpp"
#include "model.hpp"

#include <string>
#include <vector>

namespace billiards::derive {

/// A kernel printed as C++: its body lines and the number of arithmetic operations they perform.
struct EmittedKernel {
  /// `const Scalar name = …;` lines, then the `return …;` line. For a kernel with a fast path: the
  /// predicate's test returning the fast kernel, then `return full_<name>(…);`.
  std::vector<std::string> body;
  /// For a kernel with a fast path, the body of `full_<name>`: every step, for every valid input (a
  /// function of its own, so that the compilers inline the test and the fast kernel into the caller
  /// however long the full form is); empty otherwise.
  std::vector<std::string> full_body;
  int operation_count = 0;  ///< +, −, ×, ÷ and negations in the steps and outputs
};

/// Prints one kernel's body. Throws std::invalid_argument naming the kernel when an expression has no
/// C++ form (a non-integer power, an irrational number, an unknown function).
EmittedKernel emit_kernel(const Kernel& kernel);

/// A stable fingerprint of `text`: "fnv1a64:" and 16 hex digits.
std::string fingerprint(const std::string& text);

/// The model's kernels header (billiards/kernels.hpp for the paper): a preamble whose fingerprint covers
/// the header's own text and `audit_text` (the audit's JSON), the support header's include, then every
/// kernel with a comment naming the claim it was proven equal to, the claims it implements and its
/// operation count. The kernels must have been validated (validate.hpp) first.
std::string kernels_header(const Derivation& derivation, const std::string& audit_text);

/// Where the numeric helpers are printed, once (the output folder's billiards/kernel_support.hpp), and
/// their namespace, which every model's kernels namespace lies in.
inline constexpr const char* kernel_support_path = "billiards/kernel_support.hpp";
inline constexpr const char* support_namespace = "billiards::kernels";

/// The numeric helpers every kernels header includes (kernel_support_path): the fast-math check, the
/// device macro, |x|, the smallest normal number, +∞, the plain and moderate ranges, the bit comparison
/// and the scaling by powers of two; fingerprinted by its own text.
std::string kernel_support_header();

/// The reference header (billiards/reference_kernels.hpp for the paper): the model's reference kernels
/// (the raw derivation before simplification, for the benchmark only) on top of its kernels header,
/// fingerprinted the same way.
std::string reference_kernels_header(const Derivation& derivation, const std::string& audit_text);

/// The model's test-only kernel list (billiards/kernel_list.hpp for the paper), namespace
/// `<kernels_namespace>::list`: `largest_arity`, `call<Scalar>(name, at)` calling any kernel or
/// reference kernel with arguments looked up by parameter name, and `sum_of_every_kernel<Scalar>(a)`,
/// which calls every kernel on the host or a device and so instantiates each for Scalar.
std::string kernel_list_header(const Derivation& derivation, const std::string& audit_text);

}  // namespace billiards::derive
