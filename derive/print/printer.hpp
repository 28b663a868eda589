// Printing is a layer of its own. GiNaC orders the terms of a sum and the factors of a product by
// hash values that depend on where libginac is loaded (ASLR), and factor() may return (a − b)² on one
// run and (b − a)² on the next. Our output must be byte-identical on every run, so this printer
// walks the expression tree itself: terms and factors sorted by their printed text, every sum inside
// a product turned so that its first term is positive. Leaves (symbols, numbers) are printed by
// GiNaC's own printers.
#pragma once

#include <ginac/ginac.h>

#include <string>

namespace billiards::derive {

enum class Notation {
  text,   ///< plain, one line: m1*(v1n-v2n)^2/(m1+m2)
  latex,  ///< LaTeX math from GiNaC's TeX names: \frac{m_{1} \left(…\right)^{2}}{m_{1} + m_{2}}
  /// C++ for a `template <typename Scalar>` body: Scalar(2) * m2 / total_mass, and conditions a < b. No pow
  /// (integer powers are products), no floating literals (every number is Scalar(integer)); anything else
  /// throws.
  cpp,
};

/// Prints `e` in a canonical, run-independent form.
std::string print(const GiNaC::ex& e, Notation notation);

/// True when print() writes `e` with a leading minus sign, e.g. −2 m1/(m1 + m2).
bool prints_negative(const GiNaC::ex& e);

/// True when print() turns the sum `sum` around, writing −(b − a) for a − b in a product.
bool reads_negated(const GiNaC::ex& sum);

/// A rational expression in its canonical factored form: factor(numerator) / factor(denominator).
/// Unique up to the order and sign of factors, which print() fixes.
GiNaC::ex factored_form(const GiNaC::ex& e);

/// A rational expression as expanded numerator / expanded denominator: canonical, and cheap where
/// factored_form() would have to factor large polynomials.
GiNaC::ex expanded_form(const GiNaC::ex& e);

}  // namespace billiards::derive
