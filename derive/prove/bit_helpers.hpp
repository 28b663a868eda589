// The bit manipulation printed beside the kernels — orders_as_bits, bits_above, larger, binary_exponent,
// times_power_of_two — proven from its printed text: the functions as read back (cpp_reader.hpp) are
// evaluated, statement by statement, for float and double, on the host path and on the device path
// (`#if !defined(__CUDA_ARCH__)` not taken), over every binary exponent of each format, and each result
// compared with an exact reference: ⌊log2 |x|⌋ from the significand and exponent the C library splits x
// into, x · 2^k rounded once (long double holds it exactly), the range tests the bit comparisons stand for.
// Generic: it reads functions by name, never a model.
#pragma once

#include "prove/cpp_reader.hpp"
#include "emit/validate.hpp"

#include <string>
#include <vector>

namespace billiards::derive {

/// The bit helpers this proves, by name.
const std::vector<std::string>& bit_helper_names();

/// Proves each bit helper `functions` defines (and the functions they call, which must be defined there
/// too, or be the C library's std::ilogb and std::ldexp). Returns a problem, naming the helper, the
/// format, the path and the first input it answers wrongly, for each helper that is not proven. Never
/// throws.
std::vector<KernelProblem> prove_bit_helpers(const std::vector<CppFunction>& functions);

}  // namespace billiards::derive
