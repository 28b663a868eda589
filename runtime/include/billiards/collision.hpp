// billiards::collide and billiards::reflect: the paper's collision for Eigen vectors of any fixed
// dimension, float or double, on top of the generated scalar kernels.
#pragma once

#include <billiards/detail/arithmetic.hpp>
#include <billiards/kernels.hpp>
#include <billiards/version.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

/// 1 when the compiler may rewrite floating-point expressions: -ffast-math (`__FAST_MATH__`), or its
/// parts -fassociative-math and -freciprocal-math, which g++ announces (`__ASSOCIATIVE_MATH__`,
/// `__RECIPROCAL_MATH__`) also under -ffast-math -fno-finite-math-only; otherwise 0. Then the
/// bit-level promises (collide_batch equal to collide, bit-for-bit symmetry) and the accuracy bounds do
/// not hold, and billiards::checked treats subnormal numbers as flushed to zero. clang++ announces
/// only the full -ffast-math (which the kernels header rejects); the checked calls' run-time probe
/// catches the flushing its -ffast-math link sets up.
#if defined(__FAST_MATH__) || defined(__ASSOCIATIVE_MATH__) || defined(__RECIPROCAL_MATH__)
#define BILLIARDS_RELAXED_MATH 1
#else
#define BILLIARDS_RELAXED_MATH 0
#endif

namespace billiards {

/// The velocities of the two balls after a collision. An aggregate, so structured bindings work:
/// `auto [x1, x2] = billiards::collide(m1, v1, m2, v2, n);`
template <typename Vector>
struct Collision {
  Vector first;   ///< \f$x_1\f$, the first ball's velocity after the collision
  Vector second;  ///< \f$x_2\f$, the second ball's velocity after the collision
};

/// How far n·n may be from 1 where a unit normal is required: 64 ε (7.6e-6 for float, 1.4e-14 for
/// double), loose enough for a vector normalised in its own precision. The debug asserts of the
/// unchecked calls and billiards::checked use the same tolerance.
template <typename Scalar>
[[nodiscard]] constexpr Scalar unit_length_tolerance() noexcept {
  return Scalar(64) * std::numeric_limits<Scalar>::epsilon();
}

namespace detail {

/// The plain fixed-size column vector type of an Eigen expression.
template <typename Derived>
using PlainVector = Eigen::Matrix<typename Derived::Scalar, Derived::RowsAtCompileTime, 1>;

template <typename Derived>
constexpr void require_vector() {
  static_assert(Derived::ColsAtCompileTime == 1,
                "billiards: velocities and normals must be column vectors (Eigen::Matrix<Scalar, N, 1>)");
  static_assert(Derived::RowsAtCompileTime != Eigen::Dynamic,
                "billiards: vectors must have a size fixed at compile time (e.g. Eigen::Vector3d); "
                "dynamic-size vectors are not supported");
  static_assert(
      std::is_same_v<typename Derived::Scalar, float> || std::is_same_v<typename Derived::Scalar, double>,
      "billiards: the scalar type must be float or double");
}

/// One compile-time check for every vector argument of a call: fixed-size column vectors of float or
/// double, all of one scalar type and one dimension.
template <typename First, typename... Rest>
constexpr void require_vectors() {
  require_vector<First>();
  (require_vector<Rest>(), ...);
  static_assert((std::is_same_v<typename First::Scalar, typename Rest::Scalar> && ...),
                "billiards: all vectors must have the same scalar type (all float or all double)");
  static_assert(
      ((static_cast<int>(First::RowsAtCompileTime) == static_cast<int>(Rest::RowsAtCompileTime)) && ...),
      "billiards: all vectors must have the same dimension");
}

/// a·b, summed in component order by detail::dot (the one definition collide_batch shares).
template <typename DA, typename DB>
[[nodiscard]] typename DA::Scalar dot(const Eigen::MatrixBase<DA>& a,
                                      const Eigen::MatrixBase<DB>& b) noexcept {
  return dot<static_cast<std::size_t>(DA::RowsAtCompileTime)>(
      [&](std::size_t k) { return a[Eigen::Index(k)]; }, [&](std::size_t k) { return b[Eigen::Index(k)]; });
}

/// (b − a)·d through detail::difference_dot (the one definition collide_batch shares).
template <typename DA, typename DB, typename DD>
[[nodiscard]] typename DA::Scalar difference_dot(const Eigen::MatrixBase<DA>& a,
                                                 const Eigen::MatrixBase<DB>& b,
                                                 const Eigen::MatrixBase<DD>& d) noexcept {
  return difference_dot<static_cast<std::size_t>(DA::RowsAtCompileTime)>(
      [&](std::size_t k) { return a[Eigen::Index(k)]; }, [&](std::size_t k) { return b[Eigen::Index(k)]; },
      [&](std::size_t k) { return d[Eigen::Index(k)]; });
}

/// v + c d component by component through detail::plus_multiple: where c d is 0, v's bits unchanged.
template <typename DV, typename DD>
[[nodiscard]] PlainVector<DV> plus_multiple(const Eigen::MatrixBase<DV>& v, typename DV::Scalar c,
                                            const Eigen::MatrixBase<DD>& d) noexcept {
  PlainVector<DV> result;
  for (Eigen::Index k = 0; k < v.size(); ++k) result[k] = plus_multiple(v[k], c, d[k]);
  return result;
}

/// The exponent e with 2^(e−1) ≤ x < 2^e (std::frexp's) for a finite x > 0; 0 for zero, for what is
/// not finite and for what compares as zero (a subnormal where subnormals are flushed).
/// For IEEE float and double it reads the exponent field (no libm call, which the compilers would not
/// inline); other types go through std::frexp.
template <typename Scalar>
inline constexpr bool has_exponent_field = std::numeric_limits<Scalar>::is_iec559 &&
                                           (sizeof(Scalar) == 4 || sizeof(Scalar) == 8);
template <typename Scalar>
using FloatBits = std::conditional_t<sizeof(Scalar) == 4, std::uint32_t, std::uint64_t>;

template <typename Scalar>
[[nodiscard]] int binary_exponent(Scalar x) noexcept {
  if (!(x > 0) || !std::isfinite(x)) return 0;
  using limits = std::numeric_limits<Scalar>;
  if constexpr (has_exponent_field<Scalar>) {
    const int field =
        static_cast<int>(std::bit_cast<FloatBits<Scalar>>(x) >> (limits::digits - 1));  // no sign
    if (field == 0) {  // subnormal: scaled exactly into the normal range first
      return binary_exponent(x * (Scalar(1) / limits::epsilon()) * Scalar(2)) - limits::digits;
    }
    return field - (limits::max_exponent - 1) + 1;
  } else {
    int exponent = 0;
    static_cast<void>(std::frexp(x, &exponent));
    return exponent;
  }
}

/// Whether 2^exponent is a finite normal number of Scalar.
template <typename Scalar>
[[nodiscard]] constexpr bool is_normal_power_of_two(int exponent) noexcept {
  return exponent >= std::numeric_limits<Scalar>::min_exponent - 1 &&
         exponent <= std::numeric_limits<Scalar>::max_exponent - 1;
}

/// 2^exponent where is_normal_power_of_two(exponent): built from the exponent field for IEEE float and
/// double, std::ldexp for other types.
template <typename Scalar>
[[nodiscard]] Scalar power_of_two(int exponent) noexcept {
  if constexpr (has_exponent_field<Scalar>) {
    using limits = std::numeric_limits<Scalar>;
    return std::bit_cast<Scalar>(static_cast<FloatBits<Scalar>>(exponent + limits::max_exponent - 1)
                                 << (limits::digits - 1));
  } else {
    return std::ldexp(Scalar(1), exponent);
  }
}

/// x · 2^exponent, correctly rounded (exact unless it falls into the subnormal range): one
/// multiplication where 2^exponent is a normal number, std::ldexp otherwise.
template <typename Scalar>
requires std::is_floating_point_v<Scalar>
[[nodiscard]] Scalar times_power_of_two(Scalar x, int exponent) noexcept {
  return is_normal_power_of_two<Scalar>(exponent) ? x * power_of_two<Scalar>(exponent)
                                                  : std::ldexp(x, exponent);
}

/// max_k |v_k|, in component order, by scalar std::max: for the short fixed-size vectors here Eigen's
/// cwiseAbs().maxCoeff() builds a partial SIMD reduction that costs several times as much.
template <typename Derived>
[[nodiscard]] typename Derived::Scalar largest_magnitude(const Eigen::MatrixBase<Derived>& v) noexcept {
  typename Derived::Scalar largest = std::fabs(v[0]);
  for (Eigen::Index k = 1; k < v.size(); ++k) largest = std::max(largest, std::fabs(v[k]));
  return largest;
}

/// The binary exponent of v's largest component magnitude (0 for a zero vector).
template <typename Derived>
[[nodiscard]] int largest_component_exponent(const Eigen::MatrixBase<Derived>& v) noexcept {
  return binary_exponent(largest_magnitude(v));
}

/// v · 2^exponent, each component correctly rounded (exact unless it falls into the subnormal range):
/// one multiplication where 2^exponent is a normal number, std::ldexp per component otherwise.
template <typename Derived>
[[nodiscard]] PlainVector<Derived> times_power_of_two(const Eigen::MatrixBase<Derived>& v,
                                                      int exponent) noexcept {
  using Scalar = typename Derived::Scalar;
  if (is_normal_power_of_two<Scalar>(exponent)) return v * power_of_two<Scalar>(exponent);
  PlainVector<Derived> scaled;
  for (Eigen::Index k = 0; k < scaled.size(); ++k) scaled[k] = std::ldexp(v[k], exponent);
  return scaled;
}

/// The exponent field of IEEE float and double in place (masked, not shifted), and the powers of two
/// built from it by one integer subtraction: for scalings by the exponent of the largest of a few
/// numbers without a floating-point maximum (an integer maximum of the masked fields is the field of the
/// largest magnitude) and without binary_exponent's branches.
template <typename Scalar>
struct ExponentField {
  using Bits = FloatBits<Scalar>;
  static constexpr int fraction_bits = std::numeric_limits<Scalar>::digits - 1;
  static constexpr Bits bias = std::numeric_limits<Scalar>::max_exponent - 1;
  static constexpr Bits one = Bits(1) << fraction_bits;  ///< the field 1, in place
  static constexpr Bits mask = (2 * bias + 1) << fraction_bits;

  /// x's field, in place; no sign.
  [[nodiscard]] static constexpr Bits of(Scalar x) noexcept { return std::bit_cast<Bits>(x) & mask; }
  /// The largest field of the components of v.
  template <std::size_t N>
  [[nodiscard]] static constexpr Bits largest(const std::array<Scalar, N>& v) noexcept {
    Bits field = of(v[0]);
    for (std::size_t k = 1; k < N; ++k) field = std::max(field, of(v[k]));
    return field;
  }
  /// Whether 2^−e (e = f − bias + 1, binary_exponent's for a number with the field f) is a normal
  /// number and f that of a normal number: 1 ≤ f ≤ 2 bias − 2 (unsigned, so 0 wraps around).
  [[nodiscard]] static constexpr bool has_normal_inverse(Bits field) noexcept {
    return field - one < (2 * bias - 2) << fraction_bits;
  }
  /// 2^−e for the field f, where has_normal_inverse(f): the field 2 bias − 1 − f.
  [[nodiscard]] static constexpr Scalar inverse(Bits field) noexcept {
    return std::bit_cast<Scalar>(static_cast<Bits>(((2 * bias - 1) << fraction_bits) - field));
  }
};

/// `d` scaled in place by the power of two that puts its largest component in [0.5, 1). The scaling is
/// exact (short of components 2^p times smaller than the largest, which change by less than rounding)
/// and a collision along d does not depend on |d| (audit claim `beyond.any_normal.scale_invariant`);
/// it keeps the multiple of d that a kernel returns from underflowing or overflowing because |d| is
/// extreme.
///
/// For IEEE float and double whose largest component is normal and below the top two binades (every d
/// but the subnormal, the huge and the non-finite) the factor 2^−e is built straight from the largest
/// exponent field, f: e = f − bias + 1, so 2^−e has the field 2·bias − 1 − f — one integer
/// subtraction. The largest field is the integer maximum of the components' masked fields, not the
/// field of the largest |component|: the same number, without a floating-point maximum on the way
/// (the factor comes first in every product the call forms, so each cycle to it is a cycle of the
/// call). The rest take times_power_of_two's general path; both give the same factor wherever both
/// apply. Always inlined, on an array of scalars: GCC kept the call out of line, and a returned
/// Eigen vector went through memory.
template <typename Scalar, std::size_t N>
[[gnu::always_inline]] inline void scale_to_unit_binade(std::array<Scalar, N>& d) noexcept {
  if constexpr (has_exponent_field<Scalar>) {
    using Field = ExponentField<Scalar>;
    if (const auto field = Field::largest(d); Field::has_normal_inverse(field)) {
      const Scalar factor = Field::inverse(field);
      for (std::size_t k = 0; k < N; ++k) d[k] *= factor;
      return;
    }
  }
  Scalar largest = std::fabs(d[0]);
  for (std::size_t k = 1; k < N; ++k) largest = std::max(largest, std::fabs(d[k]));
  const int exponent = -binary_exponent(largest);
  for (std::size_t k = 0; k < N; ++k) d[k] = times_power_of_two(d[k], exponent);
}

/// 2^(E/4), E = max_exponent (2^256 in double, 2^32 in float): the top of the squared lengths d·d for
/// which collide_along() takes d as it is (has_moderate_squared_length).
template <typename Scalar>
[[nodiscard]] constexpr Scalar moderate_squared_length_high() noexcept {
  Scalar power = 1;
  for (int k = 0; k < std::numeric_limits<Scalar>::max_exponent / 4; ++k) power *= 2;
  return power;
}

/// Whether d·d (`squared_length`) lies in [1, 2^(E/4)] (false for NaN, ±∞, zero and negatives). On IEEE
/// float and double the test compares bits, as kernels::within_plain_mass_range does
/// (kernels::bits_above): one subtraction, one comparison.
template <typename Scalar>
[[nodiscard]] constexpr bool has_moderate_squared_length(Scalar squared_length) noexcept {
  constexpr Scalar low = 1, high = moderate_squared_length_high<Scalar>();
  if constexpr (kernels::orders_as_bits<Scalar>()) {
    return kernels::bits_above(squared_length, low) <= kernels::bits_above(high, low);
  } else {
    return low <= squared_length && squared_length <= high;
  }
}

/// An Eigen vector as an array of its scalars, which the compilers keep in registers.
template <typename Derived>
[[gnu::always_inline]] inline auto scalars_of(const Eigen::MatrixBase<Derived>& v) noexcept {
  std::array<typename Derived::Scalar, static_cast<std::size_t>(Derived::RowsAtCompileTime)> scalars;
  for (std::size_t k = 0; k < scalars.size(); ++k) scalars[k] = v[Eigen::Index(k)];
  return scalars;
}

/// The collision along d' = factor · d by `kernel`, one of the direction kernels, given d and
/// squared_length = d'·d'/factor: the kernel takes 0, (v2 − v1)·d and squared_length, and returns the
/// multiples c1, c2 of d'; out come v1 + c1 d' and v2 + c2 d', on scalars throughout. The kernel's
/// quotient (v2 − v1)·d/squared_length is (v2 − v1)·d'/(d'·d'), so with d already scaled, factor 1 and
/// squared_length d·d, this is the collision along d as the kernel defines it.
template <typename D1, typename D2, typename Scalar, std::size_t N, typename Kernel>
[[gnu::always_inline]] inline Collision<PlainVector<D1>> collide_along_multiple(
    const Eigen::MatrixBase<D1>& v1, const Eigen::MatrixBase<D2>& v2, const std::array<Scalar, N>& d,
    Scalar squared_length, Scalar factor, Kernel kernel) noexcept {
  const auto along = [&d](std::size_t k) { return d[k]; };
  const auto first = [&v1](std::size_t k) { return v1[Eigen::Index(k)]; };
  const auto second = [&v2](std::size_t k) { return v2[Eigen::Index(k)]; };
  const auto change = kernel(Scalar(0), difference_dot<N>(first, second, along), squared_length);
  Collision<PlainVector<D1>> after;
  for (std::size_t k = 0; k < N; ++k) {
    const Scalar scaled = d[k] * factor;
    after.first[Eigen::Index(k)] = plus_multiple(first(k), change.first, scaled);
    after.second[Eigen::Index(k)] = plus_multiple(second(k), change.second, scaled);
  }
  return after;
}

/// The collision along `d`, of any length, by `kernel` (collide_along_multiple): the same bits as
/// scaling d to its unit binade first (scale_to_unit_binade) wherever the intermediates of both are
/// normal numbers, and no fewer digits elsewhere.
///
/// Scaling d by 2^−e (d' = 2^−e d, |d'|∞ in [1/2, 1)) scales v·d by 2^−e and d·d by 2^−2e, exactly
/// while they stay normal, and the multiple of d' the kernel returns is that of d times 2^e
/// (beyond.any_normal.scale_invariant). So where d·d lies in [1, 2^(E/4)] (has_moderate_squared_length)
/// the dot products are taken on d itself, and the kernel is given d·d · 2^−e: it then divides
/// (v2 − v1)·d 2^−e by d·d 2^−2e, to the bit, and returns the multiple of d' that it returns for d'
/// itself, which is applied to d' = 2^−e d (exact). Only the factor 2^−e waits for the integer
/// maximum of d's exponent fields, beside the dot products rather than before them (1.76 → 1.5 times
/// the hand-written form's time in the benchmark). In that range 2^−e ≤ 1, so every product of
/// components is at least as large as its scaled twin: none underflows where the scaled one would
/// not, and d·d ≤ 2^(E/4) keeps |d|∞ ≤ 2^(E/8), so none overflows for velocities below the checked
/// API's component_limit. Elsewhere, and for scalars without an IEEE exponent field, d is scaled
/// first.
template <typename D1, typename D2, typename Scalar, std::size_t N, typename Kernel>
[[gnu::always_inline]] inline Collision<PlainVector<D1>> collide_along(const Eigen::MatrixBase<D1>& v1,
                                                                       const Eigen::MatrixBase<D2>& v2,
                                                                       std::array<Scalar, N> d,
                                                                       Kernel kernel) noexcept {
  if constexpr (has_exponent_field<Scalar>) {
    const auto along = [&d](std::size_t k) { return d[k]; };
    if (const Scalar dd = dot<N>(along, along); has_moderate_squared_length(dd)) {
      using Field = ExponentField<Scalar>;
      const Scalar factor = Field::inverse(Field::largest(d));  // 2^−e, a normal number here
      return collide_along_multiple(v1, v2, d, dd * factor, factor, kernel);
    }
  }
  scale_to_unit_binade(d);
  const auto scaled = [&d](std::size_t k) { return d[k]; };
  return collide_along_multiple(v1, v2, d, dot<N>(scaled, scaled), Scalar(1), kernel);
}

/// |v| from v scaled by the power of two of its largest component (exact) and scaled back: the squares
/// neither overflow nor underflow, as with Eigen's stableNorm(), at the cost of norm() and no libm call
/// where the exponent is in the normal range. For IEEE float and double whose largest component is
/// normal and below the top two binades, both powers of two straight from its exponent field
/// (ExponentField): the same factors, the same bits, without binary_exponent's branches. That path is
/// always inlined: out of line, with the vector passed through memory, collide_with_friction took 1.05
/// (double) to 1.1 (float) times as long. scaled_norm_by_exponent, the general path, is not.
template <typename Derived>
[[nodiscard]] typename Derived::Scalar scaled_norm_by_exponent(const Eigen::MatrixBase<Derived>& v) noexcept {
  const int exponent = largest_component_exponent(v);
  return times_power_of_two(times_power_of_two(v, -exponent).norm(), exponent);
}
template <typename Derived>
[[nodiscard, gnu::always_inline]] inline typename Derived::Scalar scaled_norm(
    const Eigen::MatrixBase<Derived>& v) noexcept {
  using Scalar = typename Derived::Scalar;
  if constexpr (has_exponent_field<Scalar>) {
    using Field = ExponentField<Scalar>;
    const auto field = Field::largest(scalars_of(v));
    if (Field::has_normal_inverse(field)) {
      // 2^e has the field f + 1, a normal number wherever 2^−e is one
      return (v * Field::inverse(field)).norm() *
             std::bit_cast<Scalar>(static_cast<typename Field::Bits>(field + Field::one));
    }
    // The zero vector (a ball at rest, a spin without its horizontal part): 0 without the general path.
    if (field == 0 && (v.array() == Scalar(0)).all()) return Scalar(0);
  }
  return scaled_norm_by_exponent(v);
}

/// |p × w|² in any dimension: the sum over i < j of (p_i w_j − p_j w_i)² (Lagrange's identity makes
/// it |p|²|w|² − (p·w)², which would cancel). 2-D: (p_x w_y − p_y w_x)²; 3-D: the cross product's
/// squared norm.
///
/// In 3-D each component is read once into a scalar of its own, the same products summed in the same
/// order as the loop: GCC compiled the loop's pairs (p_1, p_2) to a two-wide load straddling the
/// stores that had just written p (Eigen's two-wide packet and a scalar), which the processor cannot
/// forward — a stall that made time_of_impact 1.4× slower. (Where the compiler fuses a multiply and an
/// add is its own choice, here as in the loop: the last bit may differ between compilers.)
template <typename Scalar, std::size_t N>
[[gnu::always_inline]] inline Scalar cross_squared(const std::array<Scalar, N>& p,
                                                   const std::array<Scalar, N>& w) noexcept {
  if constexpr (N == 3) {
    const Scalar p0 = p[0], p1 = p[1], p2 = p[2], w0 = w[0], w1 = w[1], w2 = w[2];
    const Scalar c01 = p0 * w1 - p1 * w0, c02 = p0 * w2 - p2 * w0, c12 = p1 * w2 - p2 * w1;
    Scalar sum = 0;
    sum += c01 * c01;
    sum += c02 * c02;
    sum += c12 * c12;
    return sum;
  } else {
    Scalar sum = 0;
    for (std::size_t i = 0; i < N; ++i) {
      for (std::size_t j = i + 1; j < N; ++j) {
        const Scalar component = p[i] * w[j] - p[j] * w[i];
        sum += component * component;
      }
    }
    return sum;
  }
}

// The preconditions, one predicate each: the unchecked calls assert them in debug builds (compiled out
// with NDEBUG) and the checked API (billiards/checked.hpp) validates the same and throws instead.
template <typename Scalar>
[[nodiscard]] bool is_mass(Scalar m) noexcept {
  return m > 0;  // finite or +infinity; false for NaN
}

template <typename Scalar>
[[nodiscard]] bool both_infinite(Scalar m1, Scalar m2) noexcept {
  return std::isinf(m1) && std::isinf(m2);
}

template <typename Scalar>
[[nodiscard]] bool is_restitution(Scalar e) noexcept {
  return e >= 0 && e <= 1;  // false for NaN
}

template <typename Derived>
[[nodiscard]] bool is_unit(const Eigen::MatrixBase<Derived>& n) noexcept {
  using Scalar = typename Derived::Scalar;
  return std::fabs(n.squaredNorm() - Scalar(1)) <= unit_length_tolerance<Scalar>();  // false for NaN
}

template <typename Scalar>
void assert_masses([[maybe_unused]] Scalar m1, [[maybe_unused]] Scalar m2) noexcept {
  assert(is_mass(m1) && is_mass(m2) && "billiards: masses must be positive (finite or +infinity)");
  assert(!both_infinite(m1, m2) && "billiards: two infinite masses do not collide");
}

template <typename Derived>
void assert_unit([[maybe_unused]] const Eigen::MatrixBase<Derived>& n) noexcept {
  assert(is_unit(n) && "billiards: the contact normal must be a unit vector");
}

template <typename Scalar>
void assert_restitution([[maybe_unused]] Scalar e) noexcept {
  assert(is_restitution(e) && "billiards: restitution must lie in [0, 1]");
}

}  // namespace detail

/// \brief The paper's perfectly elastic collision of two balls.
///
/// Two balls of masses \f$m_1, m_2\f$ and velocities \f$v_1, v_2\f$ meet with unit contact normal
/// \f$n\f$ (either direction). Momentum and kinetic energy are conserved and the tangential parts are
/// unchanged (frictionless, spinless, instantaneous contact):
/// \f[
///   x_1 = v_1 + \frac{2 m_2}{m_1 + m_2}\,\big((v_2 - v_1)\cdot n\big)\,n, \qquad
///   x_2 = v_2 - \frac{2 m_1}{m_1 + m_2}\,\big((v_2 - v_1)\cdot n\big)\,n,
/// \f]
/// computed as \f$2/(1 + m_1/m_2)\f$ and \f$2/(1 + m_2/m_1)\f$ so that no mass overflows and a mass
/// may be \f$+\infty\f$: an immovable body (a cushion, a wall), which keeps its velocity while the other
/// ball is reflected. Audit claims `result.x1_simplified_form`, `result.x2_by_symmetry`,
/// `beyond.immovable.mass_ratio_form`; kernel kernels::elastic_normal_velocity_change.
///
/// Preconditions (not checked): \f$m_1, m_2 > 0\f$, each finite or \f$+\infty\f$ but not both infinite
/// (two infinite masses are not a collision: the result is then NaN); \f$|n| = 1\f$. The result does
/// not depend on the sign of \f$n\f$ (bit for bit), and swapping the balls swaps the results.
///
/// \param m1, m2 the masses, in the vectors' scalar type
/// \param v1, v2, n fixed-size Eigen column vectors of one dimension and one scalar type (float or
///        double); Map, Ref, blocks and expressions are accepted
/// \return {x1, x2}, plain vectors; nothing is allocated
template <typename D1, typename D2, typename DN>
[[nodiscard]] Collision<detail::PlainVector<D1>> collide(typename D1::Scalar m1,
                                                         const Eigen::MatrixBase<D1>& v1,
                                                         typename D1::Scalar m2,
                                                         const Eigen::MatrixBase<D2>& v2,
                                                         const Eigen::MatrixBase<DN>& n) noexcept {
  detail::require_vectors<D1, D2, DN>();
  detail::assert_masses(m1, m2);
  detail::assert_unit(n);
  const auto change = kernels::elastic_normal_velocity_change(m1, m2, typename D1::Scalar(0),
                                                              detail::difference_dot(v1, v2, n));
  return {detail::plus_multiple(v1, change.first, n), detail::plus_multiple(v2, change.second, n)};
}

/// \brief A collision with a coefficient of restitution \f$e\f$ (beyond the paper).
///
/// Momentum is conserved and Newton's law \f$(x_2 - x_1)\cdot n = -e\,(v_2 - v_1)\cdot n\f$ holds:
/// \f[
///   x_1 = v_1 + \frac{1 + e}{1 + m_1/m_2}\,\big((v_2 - v_1)\cdot n\big)\,n, \qquad
///   x_2 = v_2 - \frac{1 + e}{1 + m_2/m_1}\,\big((v_2 - v_1)\cdot n\big)\,n.
/// \f]
/// \f$e = 1\f$ is the paper's elastic collision (the same bits as the five-argument call), \f$e = 0\f$
/// leaves equal normal velocities; the kinetic energy lost is
/// \f$\tfrac12 \mu (1 - e^2)((v_2 - v_1)\cdot n)^2\f$, \f$\mu = m_1 m_2/(m_1 + m_2)\f$. Audit claims
/// `beyond.restitution.impulse_coefficients`, `beyond.restitution.energy_loss`,
/// `beyond.immovable.mass_ratio_form`; kernel kernels::normal_velocity_change.
/// Preconditions as for the elastic call, and \f$0 \le e \le 1\f$ (not checked).
template <typename D1, typename D2, typename DN>
[[nodiscard]] Collision<detail::PlainVector<D1>> collide(typename D1::Scalar m1,
                                                         const Eigen::MatrixBase<D1>& v1,
                                                         typename D1::Scalar m2,
                                                         const Eigen::MatrixBase<D2>& v2,
                                                         const Eigen::MatrixBase<DN>& n,
                                                         typename D1::Scalar restitution) noexcept {
  detail::require_vectors<D1, D2, DN>();
  detail::assert_masses(m1, m2);
  detail::assert_unit(n);
  detail::assert_restitution(restitution);
  const auto change = kernels::normal_velocity_change(m1, m2, typename D1::Scalar(0),
                                                      detail::difference_dot(v1, v2, n), restitution);
  return {detail::plus_multiple(v1, change.first, n), detail::plus_multiple(v2, change.second, n)};
}

/// \brief The collision along a direction \f$d\f$ that need not be a unit vector (beyond the paper).
///
/// \f[ x_1 = v_1 + \frac{1 + e}{1 + m_1/m_2}\,\frac{(v_2 - v_1)\cdot d}{d\cdot d}\,d \f] (and \f$x_2\f$
/// alike): the same as collide() with \f$n = d/|d|\f$, without a square root, and unchanged when
/// \f$d\f$ is scaled. Audit claims `beyond.any_normal.direction_form`,
/// `beyond.any_normal.scale_invariant`; kernel kernels::direction_velocity_change.
/// d is scaled by a power of two (exact; detail::collide_along), so its length does not matter: d and
/// 2^k d give the same bits wherever the products (v2 − v1)_i d'_i and d'_i d'_i of d scaled to its
/// unit binade (d', largest component in ±[1/2, 1)), and their partial sums, are zero or normal numbers.
/// Below that — relative velocities within 2^digits of the smallest normal number, about 1e-31 m/s in
/// float — those products lose digits to underflow at different scales, and the last bits of the results
/// (subnormal or not) may differ between d and 2^k d; each is still as accurate as its own rounding.
/// Preconditions (not checked): \f$d \ne 0\f$ and finite (a zero direction gives NaN), masses as
/// for collide().
template <typename D1, typename D2, typename DD>
[[nodiscard, gnu::always_inline]] inline Collision<detail::PlainVector<D1>> collide_along_direction(
    typename D1::Scalar m1, const Eigen::MatrixBase<D1>& v1, typename D1::Scalar m2,
    const Eigen::MatrixBase<D2>& v2, const Eigen::MatrixBase<DD>& d,
    typename D1::Scalar restitution = 1) noexcept {
  detail::require_vectors<D1, D2, DD>();
  detail::assert_masses(m1, m2);
  detail::assert_restitution(restitution);
  return detail::collide_along(v1, v2, detail::scalars_of(d), [&](auto v1d, auto v2d, auto dd) {
    return kernels::direction_velocity_change(m1, m2, v1d, v2d, dd, restitution);
  });
}

/// \brief Resolves the contact of two balls centred at \f$p_1, p_2\f$ only if they approach (beyond
/// the paper).
///
/// The direction is \f$d = p_2 - p_1\f$, from ball 1 to ball 2, so the convention cannot be got wrong.
/// The balls approach iff \f$(v_2 - v_1)\cdot d < 0\f$; then the result is collide_along_direction(),
/// otherwise the velocities are returned unchanged (bit for bit), so rounding can never make a
/// separating pair collide again. Audit claims `beyond.approaching.resolve_only_approaching`,
/// `beyond.approaching.kernel_form`; kernel kernels::approaching_direction_velocity_change.
/// Preconditions (not checked): \f$p_1 \ne p_2\f$, masses as for collide(), \f$0 \le e \le 1\f$.
template <typename DP1, typename D1, typename DP2, typename D2>
[[nodiscard, gnu::always_inline]] inline Collision<detail::PlainVector<D1>> collide_if_approaching(
    typename D1::Scalar m1, const Eigen::MatrixBase<DP1>& p1, const Eigen::MatrixBase<D1>& v1,
    typename D1::Scalar m2, const Eigen::MatrixBase<DP2>& p2, const Eigen::MatrixBase<D2>& v2,
    typename D1::Scalar restitution = 1) noexcept {
  detail::require_vectors<D1, D2, DP1, DP2>();
  detail::assert_masses(m1, m2);
  detail::assert_restitution(restitution);
  return detail::collide_along(v1, v2, detail::scalars_of(p2 - p1), [&](auto v1d, auto v2d, auto dd) {
    return kernels::approaching_direction_velocity_change(m1, m2, v1d, v2d, dd, restitution);
  });
}

namespace detail {

/// kernels::time_of_impact on p = p2 − p1, w = v2 − v1 and r scaled (q, u, r), as time_of_impact()
/// calls it; the time comes out scaled likewise.
template <typename Scalar, std::size_t N>
[[gnu::always_inline]] inline Scalar scaled_time_of_impact(const std::array<Scalar, N>& q,
                                                           const std::array<Scalar, N>& u,
                                                           Scalar r) noexcept {
  const auto at_q = [&q](std::size_t k) { return q[k]; };
  const auto at_u = [&u](std::size_t k) { return u[k]; };
  return kernels::time_of_impact(dot<N>(at_q, at_q), dot<N>(at_q, at_u), dot<N>(at_u, at_u),
                                 cross_squared(q, u), r);
}

/// time_of_impact() on p = p2 − p1 and w = v2 − v1, scaled by binary_exponent and times_power_of_two:
/// the general path, for every input (and the reference of time_of_impact_scaled's fast path).
///
/// Lengths scaled by 2^−e (e the exponent of max(|p|∞, r)) and speeds by 2^−f (f that of |w|∞)
/// describe the same contact, at the time t · 2^(f − e) (audit claim
/// `beyond.time_of_impact.scale_invariant`). Scaled, the largest length and the largest speed component
/// lie in [1/2, 1): no square the kernel forms overflows, and r² w·w underflows only when r is below the
/// precondition's 4 √(smallest normal) |p2 − p1|, however small or large the inputs. The scalings are
/// exact but for components that fall into the subnormal range.
template <typename Scalar, std::size_t N>
[[nodiscard]] Scalar time_of_impact_by_exponents(const std::array<Scalar, N>& p,
                                                 const std::array<Scalar, N>& w,
                                                 Scalar contact_distance) noexcept {
  Scalar centre_distance = std::fabs(p[0]), largest_speed = std::fabs(w[0]);
  for (std::size_t k = 1; k < N; ++k) {
    centre_distance = std::max(centre_distance, std::fabs(p[k]));
    largest_speed = std::max(largest_speed, std::fabs(w[k]));
  }
  const int length_exponent = binary_exponent(std::max(centre_distance, contact_distance));
  const int speed_exponent = binary_exponent(largest_speed);
  // Spheres whose centres are closer than 2^−(digits + 2) r overlap by all but rounding: p·p − r² is
  // −r² to the last bit and the answer depends only on the sign of p·w (0 if approaching, else +∞).
  // p is then lifted to about 2^−(digits + 2) r, which keeps both and keeps p·w from underflowing.
  constexpr int negligible = std::numeric_limits<Scalar>::digits + 2;
  const int centre_exponent = binary_exponent(centre_distance);
  const bool centres_negligible = centre_distance > 0 && centre_exponent < length_exponent - negligible;
  const int position_exponent = centres_negligible ? centre_exponent + negligible : length_exponent;
  // times_power_of_two is std::ldexp to the bit: one multiplication where the power is a normal number,
  // a call into libm only beyond.
  std::array<Scalar, N> q, u;
  for (std::size_t k = 0; k < N; ++k) {
    q[k] = times_power_of_two(p[k], -position_exponent);
    u[k] = times_power_of_two(w[k], -speed_exponent);
  }
  const Scalar r = times_power_of_two(contact_distance, -length_exponent);
  return times_power_of_two(scaled_time_of_impact(q, u, r), length_exponent - speed_exponent);
}

/// time_of_impact() on p = p2 − p1 and w = v2 − v1: for IEEE float and double where every power of two
/// involved is a normal number and the centres are not negligible, the factors straight from the
/// exponent fields, as scale_to_unit_binade builds them (integer maxima of the masked fields in place,
/// one subtraction each): the same factors as time_of_impact_by_exponents, so the same bits, without
/// its floating-point maxima and its branches on each exponent's range on the way to the kernel
/// (16 → 10 ns a call in the benchmark). Everything else goes the general way.
template <typename Scalar, std::size_t N>
[[gnu::always_inline]] inline Scalar time_of_impact_scaled(const std::array<Scalar, N>& p,
                                                           const std::array<Scalar, N>& w,
                                                           Scalar contact_distance) noexcept {
  if constexpr (has_exponent_field<Scalar>) {
    using Field = ExponentField<Scalar>;
    using Bits = typename Field::Bits;
    const Bits centre = Field::largest(p), speed = Field::largest(w);
    const Bits length = std::max(centre, Field::of(contact_distance));
    // The field of 2^(e − f), the time's factor (wrapped around where e − f is out of range).
    const Bits time_field = (Field::bias << Field::fraction_bits) + length - speed;
    constexpr Bits negligible = Bits(std::numeric_limits<Scalar>::digits + 2) << Field::fraction_bits;
    // Each factor a normal number, the centres' field normal (p = 0 and a subnormal |p|∞, whose field
    // is no exponent, go the general way) and not negligible (centre ≥ length − digits − 2), and
    // 2^(e − f) a normal number (1 ≤ its field ≤ 2 bias, unsigned).
    if (Field::has_normal_inverse(length) && Field::has_normal_inverse(speed) && centre >= Field::one &&
        centre + negligible >= length &&
        time_field - Field::one < (2 * Field::bias) << Field::fraction_bits) {
      const Scalar to_length = Field::inverse(length), to_speed = Field::inverse(speed);
      std::array<Scalar, N> q, u;
      for (std::size_t k = 0; k < N; ++k) {
        q[k] = p[k] * to_length;
        u[k] = w[k] * to_speed;
      }
      return scaled_time_of_impact(q, u, contact_distance * to_length) * std::bit_cast<Scalar>(time_field);
    }
  }
  return time_of_impact_by_exponents(p, w, contact_distance);
}

}  // namespace detail

/// \brief When two spheres moving in straight lines first touch (beyond the paper).
///
/// Centres \f$p_1 + t v_1\f$ and \f$p_2 + t v_2\f$ touch when \f$|p + t w| = r\f$, \f$p = p_2 - p_1\f$,
/// \f$w = v_2 - v_1\f$, \f$r\f$ the contact distance (the sum of the radii): a quadratic
/// \f$a t^2 + 2 b t + c = 0\f$ with \f$a = w\cdot w\f$, \f$b = p\cdot w\f$, \f$c = p\cdot p - r^2\f$, whose
/// earlier root is taken in the form \f$t = c/(\sqrt{D} - b)\f$ (no cancellation, no division by
/// \f$a\f$), with \f$D = b^2 - a c\f$ computed as \f$(w\cdot w) r^2 - |p \times w|^2\f$ (no cancellation when
/// the spheres are far apart). Audit claims `beyond.time_of_impact.*`; kernel kernels::time_of_impact.
///
/// Positions are scaled by the power of two of max(|p|∞, r) and velocities by that of |w|∞ first
/// (exact; the time scales back by their ratio, audit claim `beyond.time_of_impact.scale_invariant`),
/// so the answer does not depend on the units: a
/// relative speed of 1e-161, spheres of radius 1e-170 or a gap of 1e150 give the right time, never a
/// miss by underflow or overflow.
///
/// \return the earliest \f$t \ge 0\f$ at which the spheres touch while approaching; 0 when they already
///         touch (or overlap by rounding) and approach; \f$+\infty\f$ when they never touch: separating
///         (\f$b \ge 0\f$), no relative motion, a miss (\f$D < 0\f$) or a graze (\f$D = 0\f$, no closing
///         speed at the contact, so nothing to resolve), or when the time exceeds the largest finite
///         number. Hit or miss is decided by the computed \f$D\f$: the miss distance
///         \f$|p \times w|/|w|\f$ against \f$r\f$, to within rounding of order \f$\varepsilon |p|\f$, so a
///         pair that passes within a few ulps of \f$|p|\f$ of grazing may go either way.
///
/// Preconditions (not checked; billiards::checked::time_of_impact validates them): every component
/// finite, \f$v_2 - v_1\f$ and \f$p_2 - p_1\f$ finite, \f$r > 0\f$ and finite (asserted in debug
/// builds), and \f$r \ge 4\sqrt{\text{smallest normal}}\,|p_2 - p_1|\f$ (6e-154 |p2 − p1| in double, 4e-19
/// in float): below it \f$r^2\f$ underflows beside \f$|p|^2\f$ and the hit is decided far below
/// rounding.
template <typename DP1, typename D1, typename DP2, typename D2>
[[nodiscard, gnu::always_inline]] inline typename D1::Scalar time_of_impact(
    const Eigen::MatrixBase<DP1>& p1, const Eigen::MatrixBase<D1>& v1, const Eigen::MatrixBase<DP2>& p2,
    const Eigen::MatrixBase<D2>& v2, typename D1::Scalar contact_distance) noexcept {
  detail::require_vectors<D1, D2, DP1, DP2>();
  assert(contact_distance > 0 && std::isfinite(contact_distance) &&
         "billiards: the contact distance must be positive and finite");
  using Scalar = typename D1::Scalar;
  constexpr auto N = static_cast<std::size_t>(D1::RowsAtCompileTime);
  std::array<Scalar, N> p, w;
  for (std::size_t k = 0; k < N; ++k) {
    p[k] = p2[Eigen::Index(k)] - p1[Eigen::Index(k)];
    w[k] = v2[Eigen::Index(k)] - v1[Eigen::Index(k)];
  }
  return detail::time_of_impact_scaled(p, w, contact_distance);
}

/// \brief A ball bouncing off an immovable cushion: the reflection \f$v - 2 (v\cdot n)\,n = -n v n\f$.
///
/// The paper's limit \f$m_2 \to \infty\f$ with \f$v_2 = 0\f$; the same bits as
/// `collide(m, v, infinity, zero, n).first`. Audit claims: `cushion.limit`,
/// `cushion.reflection_is_sandwich.3d`; computed by kernels::cushion_normal_velocity_change.
/// Preconditions (not checked): \f$|n| = 1\f$.
template <typename DV, typename DN>
[[nodiscard]] detail::PlainVector<DV> reflect(const Eigen::MatrixBase<DV>& v,
                                              const Eigen::MatrixBase<DN>& n) noexcept {
  detail::require_vectors<DV, DN>();
  detail::assert_unit(n);
  return detail::plus_multiple(v, kernels::cushion_normal_velocity_change(detail::dot(v, n)), n);
}

}  // namespace billiards
