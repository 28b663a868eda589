// Constants that kernels use by name and the C++ printer spells for the target (a symbol compared by
// identity, never by its text): the smallest normal number and +∞ of the kernel's Scalar type, and the
// bounds of the mass range where the plain (one-division) form keeps every intermediate normal.
#pragma once

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace billiards::derive {

/// std::numeric_limits<Scalar>::min(): printed as smallest_normal<Scalar>().
const GiNaC::symbol& smallest_normal();
/// +∞ of Scalar: printed as infinity<Scalar>().
const GiNaC::symbol& infinity();
/// The plain form's mass range [4 √x_min, 1/(4 √x_min)] of Scalar (2^−509 to 2^509 in double, 2^−61 to
/// 2^61 in float): printed as plain_mass_low<Scalar>() and plain_mass_high<Scalar>().
const GiNaC::symbol& plain_mass_low();
const GiNaC::symbol& plain_mass_high();
/// The conditions that both masses lie in that range: low ≤ m1 ≤ high and low ≤ m2 ≤ high, in that
/// order (a fast path's domain and predicate conditions, in both models).
std::vector<GiNaC::ex> plain_mass_range(const GiNaC::ex& m1, const GiNaC::ex& m2);

/// Masses beyond the plain range, where a full form takes over, for its rounding proof: one mass in
/// [1, 2) and the other in [2 plain_mass_high, 4 plain_mass_high), either way round; and one in [1/2, 5/8]
/// with the other in [(3/2)/x_min, (7/4)/x_min], either way round, where the light ball's share
/// m_light/(m_light + m_heavy) is below x_min = smallest_normal while the ratio m_heavy/m_light is finite.
/// Speeds of that case are taken `speed_scale` = 16 times larger, so that the heavy ball's change is a
/// normal number.
struct MassCase {
  std::vector<GiNaC::ex> masses;
  int speed_scale = 1;
};
std::vector<MassCase> beyond_plain_mass_cases(const GiNaC::ex& m1, const GiNaC::ex& m2);

/// The moderate range [2^−(E/4 − 2), 2^(E/4 − 2)] of Scalar, E = std::numeric_limits<Scalar>::max_exponent
/// (2^−254 to 2^254 in double, 2^−30 to 2^30 in float): a product or quotient of four numbers in it, times
/// 2/7 or 5/2, is a normal number, so a monomial kernel's plain form keeps every digit there. Printed as
/// moderate_low<Scalar>() and moderate_high<Scalar>().
const GiNaC::symbol& moderate_low();
const GiNaC::symbol& moderate_high();

/// True for a symbol that is one of the named constants above.
bool is_named_constant(const GiNaC::ex& e);

/// For the named constants that are positive and finite in float and double, their place in
/// increasing order: smallest_normal 0 (2^−126, 2^−1022), plain_mass_low 1 (2^−61, 2^−509),
/// moderate_low 2 (2^−30, 2^−254), moderate_high 3 (2^30, 2^254), plain_mass_high 4 (2^61, 2^509); −1
/// for anything else (+∞ included).
int positive_finite_rank(const GiNaC::ex& e);

/// Every named constant with the name a kernel's C++ calls it by (smallest_normal<Scalar>,
/// infinity<Scalar>, …), for reading printed kernels back.
const std::vector<std::pair<std::string, GiNaC::ex>>& named_constant_spellings();
/// The named constant a kernel's C++ calls `spelling()`; nothing for any other name.
std::optional<GiNaC::ex> named_constant_spelled(const std::string& spelling);

/// An IEEE binary format in the terms of std::numeric_limits: `digits` of significand, normal numbers
/// from 2^(min_exponent − 1) up to below 2^max_exponent.
struct BinaryFormat {
  std::string type;  ///< its C++ type, "float" or "double"
  int digits;
  int min_exponent;
  int max_exponent;
};
/// float (binary32) and double (binary64), the formats the kernels are emitted for.
const std::vector<BinaryFormat>& emitted_formats();

/// The exact value in `format` of a positive finite named constant, from its definition:
/// smallest_normal 2^(min_exponent − 1), plain_mass_low 4 √smallest_normal, moderate_low
/// 2^−(max_exponent/4 − 2), each high end the inverse of its low end. Nothing for +∞ or anything else.
std::optional<GiNaC::numeric> value_in(const GiNaC::ex& constant, const BinaryFormat& format);

}  // namespace billiards::derive
