// The two vector operations the runtime computes around the generated kernels, written once for every
// caller: the dot product and "v plus a multiple of d". billiards::collide and friends (Eigen vectors)
// and billiards::collide_batch (structure-of-arrays spans) both use these, so that they round alike
// under the same compiler flags, -march=native's fused multiply-adds included (the same expression
// tree contracts the same way). No Eigen here.
#pragma once

#include <billiards/kernels.hpp>

#include <cmath>
#include <cstddef>
#include <type_traits>

namespace billiards::detail {

/// a b + c. Where the target has fused multiply-adds (__FMA__, as with -march=native) it is one, by
/// std::fma: GCC contracts a0 b0 + a1 b1 into an FMA of either product, and chooses differently in
/// different code around the same expression, so only an explicit one rounds alike in every caller.
/// Elsewhere (and in constant evaluation) it is a b + c as written.
template <typename Scalar>
[[nodiscard]] constexpr Scalar multiply_add(Scalar a, Scalar b, Scalar c) noexcept {
#if defined(__FMA__) && !defined(__CUDA_ARCH__)
  if (!std::is_constant_evaluated()) return std::fma(a, b, c);
#endif
  return a * b + c;
}

/// Σ a(k) b(k) for k = 0 … Dimension − 1, summed in that order: ((a0 b0 + a1 b1) + a2 b2) + …, each
/// step one multiply_add.
/// `a` and `b` map a component index to a value.
template <std::size_t Dimension, typename A, typename B>
[[nodiscard]] constexpr auto dot(const A& a, const B& b) noexcept {
  static_assert(Dimension > 0, "billiards: vectors have at least one component");
  auto sum = a(0) * b(0);
  for (std::size_t k = 1; k < Dimension; ++k) sum = multiply_add(a(k), b(k), sum);
  return sum;
}

/// (b − a)·d = Σ (b(k) − a(k)) d(k), summed as dot(): the relative velocity of two balls along d in
/// one dot product. The collision kernels depend on v1·d and v2·d only through v2·d − v1·d
/// (kernel.relative_speed_only), so the callers pass 0 and this: three subtractions where the two dot
/// products cost three multiplications more, and no cancellation between two large dot products.
/// Swapping a and b, or negating d, negates it exactly.
template <std::size_t Dimension, typename A, typename B, typename D>
[[nodiscard]] constexpr auto difference_dot(const A& a, const B& b, const D& d) noexcept {
  return dot<Dimension>([&](std::size_t k) { return b(k) - a(k); }, d);
}

/// v + c d, and v itself (every bit, the sign of a zero included) when c d is zero: an unchanged
/// velocity stays unchanged, −0 is not turned into +0. Computed as v − (0 − c d): 0 − c d is
/// −(c d) exactly, and +0 for either zero, and v − (+0) = v for every v (±0 included), whereas
/// v + (+0) turns −0 into +0. No select, so loops of it vectorise at any target (GCC does not if-convert
/// a floating-point comparison under -ftrapping-math without masking). Needs signed zeros (not
/// -fno-signed-zeros, which -ffast-math implies and which may fold it into v + c d).
template <typename Scalar>
[[nodiscard]] constexpr Scalar plus_multiple(Scalar v, Scalar c, Scalar d) noexcept {
  return v - (Scalar(0) - c * d);
}

}  // namespace billiards::detail
