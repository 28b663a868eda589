// Vector algebra in symbolic components, and the few exact operations GiNaC does not provide as one
// call: reduction modulo n·n = 1, the square root of a perfect square, and resolving |w| once the
// sign of w is known.
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <string>
#include <vector>

namespace billiards::derive {

/// A vector of V written in components (2-D or 3-D), each a GiNaC expression.
using Vec = std::vector<GiNaC::ex>;

/// The components of a vector named `name` in `dimension` dimensions: realsymbols name_x, name_y,
/// name_z, written in TeX as tex_letter_{tex_subscript,x} (v_{1,x}) or tex_letter_{x} (n_{x}).
/// Symbols are cached by name, so the same name always yields the same symbols.
Vec component_symbols(const std::string& name, const std::string& tex_letter,
                      const std::string& tex_subscript, std::size_t dimension);

Vec add(const Vec& a, const Vec& b);
Vec subtract(const Vec& a, const Vec& b);
Vec scale(const GiNaC::ex& factor, const Vec& a);
GiNaC::ex dot(const Vec& a, const Vec& b);
/// a × b of two 3-D component vectors.
Vec cross(const Vec& a, const Vec& b);
/// The components as a GiNaC list, the form a claim compares.
GiNaC::lst to_lst(const Vec& a);
/// The components of each vector in turn, as one list.
GiNaC::lst concatenate(const std::vector<Vec>& vectors);

/// a∥ = (a·n) n: the part along n.
Vec parallel_part(const Vec& a, const Vec& n);
/// a⊥ = a − a∥: the part across n.
Vec perpendicular_part(const Vec& a, const Vec& n);

/// The relation n_d² = 1 − Σ_{i<d} n_i² for the last component of a component vector n: imposing
/// n·n = 1 by substitution, never by choosing a numeric n.
GiNaC::ex unit_normal_relation(const Vec& n);

/// Expands `e` and substitutes `relation` (of the form x² == r) algebraically until no power of x
/// above the first remains. The result is canonical: polynomial of degree ≤ 1 in x.
GiNaC::ex reduce_modulo(const GiNaC::ex& e, const GiNaC::ex& relation);

/// √e for an `e` whose factorisation is a product of even powers (and a positive constant): the
/// product of |base|^(k/2). Returns GiNaC's plain sqrt(e) when `e` is not a perfect square, so that a
/// later exact comparison fails visibly rather than silently.
GiNaC::ex square_root_of_perfect_square(const GiNaC::ex& e);

/// True when normal(e) factors into positive constants, positive symbols and even powers only.
bool is_manifestly_nonnegative(const GiNaC::ex& e);

/// Replaces every |w| in `e` whose argument is (positive quantity) × `s` by sign·w·(…), given that
/// `s` has the sign `sign` (+1 or −1). Leaves any other |…| alone.
GiNaC::ex resolve_absolute_values(const GiNaC::ex& e, const GiNaC::ex& s, int sign);

/// GiNaC::clifford_to_lst(e, c, algebraic), the components of a Clifford vector. Declared here with
/// the symbol libginac exports: clang++ 14 infers an [abi:cxx11] tag for a function returning
/// GiNaC::lst (it holds a std::list) that GCC, which built libginac, does not, so calling GiNaC's own
/// declaration from clang-built code fails to link.
GiNaC::lst clifford_components(const GiNaC::ex& e, const GiNaC::ex& c, bool algebraic)
#if defined(__clang__)
    __asm__("_ZN5GiNaC15clifford_to_lstERKNS_2exES2_b")
#endif
        ;

}  // namespace billiards::derive
