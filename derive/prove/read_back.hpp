// Proven is what is printed: a header the emitter printed is read back (cpp_reader.hpp) and every
// function in it proven again from its text, before the header is written. Generic: it reads a header,
// the kernels it was printed from and the claims, never a model.
#pragma once

#include "core/claim.hpp"
#include "emit/kernel.hpp"
#include "prove/rounding.hpp"
#include "emit/validate.hpp"

#include <functional>
#include <string>
#include <vector>

namespace billiards::derive {

/// Reads `header` back and proves what it prints, function by function:
/// - each kernel (for a kernel with a fast path, `full_<name>`) becomes a kernel again from its text —
///   parameters, `const Scalar` steps, guarded steps and their `if` lines, the return — and is
///   validated against the claims (validate_kernel), with each guard's kind and claim taken from the
///   form; it must also be the form, step for step: the same steps, expressions, conditions (the same
///   relational operator) and outputs, once the hoisted common subexpressions are put back. Every number
///   must be written `Scalar(d)` with d exact in float;
/// - each kernel with a fast path is the dispatch `if (predicate(…)) return fast(…); return
///   full_<name>(…);`, every call passing the callee's parameters by name, in order, and naming the
///   predicate and the fast kernel of the form;
/// - each predicate's comparisons are the fast path's conditions, and its bit comparison, where printed,
///   tests the same interval;
/// - each named constant's float and double values are its definition's (core/named_constants.hpp),
///   spelled with the literal suffix of the type, and its generic form gives the same values;
/// - absolute_value is |x|.
/// - the bit helpers — binary_exponent, times_power_of_two, bits_above, larger, orders_as_bits — run from
///   their text over every exponent of float and double, on the host path and the device path, against
///   exact references (bit_helpers.hpp);
/// - every statement, printed again from what was read, is the text it was read from (the round trip:
///   the reader kept C++'s grouping, so the proofs and Gappa see the header's order of operations).
/// A function the header defines that none of these covers is a problem too.
/// Each kernel with a domain (a fast path's plain form) or rounding cases is also proven safe there from
/// its text, by Gappa (prove_rounding), its bounds appended to `bounds`. `kernels` are the ones printed into this header.
/// `proves_rounding_of`, when given, limits the Gappa proofs to the kernels it accepts (by the kernel's
/// name or the name the header spells it with); the mutation suite uses it to prove only its culprit. Never throws.
std::vector<KernelProblem> prove_printed(
    const std::string& header, const std::vector<Kernel>& kernels, const std::vector<Claim>& claims,
    std::vector<RoundingBound>& bounds,
    const std::function<bool(const std::string&)>& proves_rounding_of = {});

/// Reads back a kernel list (kernel_list_header: for tests, not installed) and proves it calls what it
/// says: `call` has one branch per kernel and reference kernel, in order, labelled with its name, calling
/// it with `at("p")` for each parameter p in order and returning each output in order, then the throw;
/// `sum_of_every_kernel` calls every kernel (reference kernels aside), in order, with a[0], a[1], … and
/// adds each output; `largest_arity` is the most parameters any kernel takes. Nothing else is defined.
/// Never throws.
std::vector<KernelProblem> prove_kernel_list(const std::string& header, const std::vector<Kernel>& kernels,
                                             const std::vector<Kernel>& reference_kernels,
                                             const std::string& reference_namespace);

}  // namespace billiards::derive
