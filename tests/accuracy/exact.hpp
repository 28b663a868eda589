// Floating-point numbers as exact rationals. GiNaC's numeric(double) is a CLN floating-point number,
// not a rational: arithmetic on it rounds. exact_rational() splits x into its integer significand
// and power of two, both exact.
#pragma once

#include <ginac/ginac.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace billiards::accuracy {

template <typename Scalar>
GiNaC::numeric exact_rational(Scalar x) {
  if (!std::isfinite(x))
    throw std::invalid_argument("exact_rational: x is " + std::to_string(x) + ", expected a finite number");
  if (x == 0) return 0;
  int exponent = 0;
  const Scalar fraction = std::frexp(x, &exponent);  // x = fraction · 2^exponent, 0.5 ≤ |fraction| < 1
  constexpr int digits = std::numeric_limits<Scalar>::digits;
  const auto significand = static_cast<long long>(std::ldexp(fraction, digits));  // exact: |·| < 2^digits
  return GiNaC::numeric(significand) * GiNaC::numeric(2).power(exponent - digits);
}

}  // namespace billiards::accuracy
