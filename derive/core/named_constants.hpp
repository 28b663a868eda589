// Constants that kernels use by name and the C++ printer spells for the target (a symbol compared by
// identity, never by its text): the smallest normal number and +∞ of the kernel's Scalar type.
#pragma once

#include <ginac/ginac.h>

#include <vector>

namespace billiards::derive {

/// std::numeric_limits<Scalar>::min(): printed as smallest_normal<Scalar>().
const GiNaC::symbol& smallest_normal();
/// +∞ of Scalar: printed as infinity<Scalar>().
const GiNaC::symbol& infinity();

/// True for a symbol that is one of the named constants above.
bool is_named_constant(const GiNaC::ex& e);

}  // namespace billiards::derive
