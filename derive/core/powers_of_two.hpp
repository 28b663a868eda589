// Scaling by powers of two: the primitive for kernels whose inputs span the whole exponent range. A
// product of such inputs is computed on their significands (each in [1, 2), where nothing overflows or
// underflows) and scaled back once by the sum of their exponents. binary_exponent(x) is a GiNaC
// function (exact for a rational, ⌊log2 |x|⌋; printed as the emitted header's binary_exponent), and
// x · 2^k is x * pow(2, k); the validator proves such forms for any k by resolve_powers_of_two.
// scaled_monomial (emit/kernel.hpp) builds a kernel's steps from them.
#pragma once

#include <ginac/ginac.h>

#include <optional>

namespace billiards::derive {

/// ⌊log2 |x|⌋ for a nonzero rational x, 0 for 0; held unevaluated for a symbol. Printed in C++ as
/// binary_exponent(x), a Scalar holding that integer.
DECLARE_FUNCTION_1P(binary_exponent)

/// a b + c rounded once: printed in C++ as std::fma(a, b, c). Its value is a b + c: it evaluates to that
/// wherever it is evaluated (a substitution into it, a comparison), so that every algebraic check sees
/// the exact sum; a kernel step holds it unevaluated (fused_multiply_add_held) to be printed as one
/// operation — the way to keep a product's rounding error, e.g. std::fma(x, x, −x²) is exactly
/// x·x − (x·x rounded).
DECLARE_FUNCTION_3P(fused_multiply_add)

/// fused_multiply_add(a, b, c), held: printed as std::fma(a, b, c).
GiNaC::ex fused_multiply_add_held(const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::ex& c);

/// x · 2^k: printed in C++ as times_power_of_two(x, k).
GiNaC::ex times_power_of_two(const GiNaC::ex& x, const GiNaC::ex& k);

/// k where n = 2^k exactly for an integer k (of either sign); nothing for any other number.
std::optional<int> exact_binary_logarithm(const GiNaC::numeric& n);

/// True for 2^k whose exponent k is not a number: a scaling by a power of two.
bool is_power_of_two_with_symbolic_exponent(const GiNaC::ex& e);

/// True when `e` contains binary_exponent(…) or a power of two whose exponent is not a number: a
/// kernel that needs the emitted header's scaling helpers.
bool uses_power_of_two_scaling(const GiNaC::ex& e);

/// `e` with every 2^E whose exponent E is not a number rewritten, E = c0 + Σ c_i a_i expanded, as
/// 2^c0 Π t_i^c_i: t_i a positive symbol standing for 2^a_i, one per distinct a_i (the same symbol
/// on every call). A rational identity in the t_i then holds for every value of the a_i, so a form
/// scaled by any power of two is proven equal to the unscaled one by normal().
GiNaC::ex resolve_powers_of_two(const GiNaC::ex& e);

}  // namespace billiards::derive
