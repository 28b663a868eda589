// billiards::checked: the same calls as <billiards/collision.hpp>, with every argument validated first.
// A rejected call throws billiards::invalid_argument naming the argument, its value and what was
// expected, and returns nothing; an accepted call returns exactly what the unchecked call returns,
// and that result is finite.
#pragma once

#include <billiards/collision.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace billiards {

/// Thrown by the checked calls for an argument outside their documented domain.
class invalid_argument : public std::invalid_argument {
 public:
  /// The message reads "function: argument is value, expected expected".
  invalid_argument(std::string function, std::string argument, std::string value, std::string expected)
      : std::invalid_argument(function + ": " + argument + " is " + value + ", expected " + expected),
        argument_(std::move(argument)),
        value_(std::move(value)),
        expected_(std::move(expected)) {}

  /// The parameter's name, e.g. "m1".
  [[nodiscard]] const std::string& argument() const noexcept { return argument_; }
  /// The rejected value as text, e.g. "-1" or "(1, 0, nan)".
  [[nodiscard]] const std::string& value() const noexcept { return value_; }
  /// What the argument must be.
  [[nodiscard]] const std::string& expected() const noexcept { return expected_; }

 private:
  std::string argument_;
  std::string value_;
  std::string expected_;
};

/// The largest velocity (or position) component the checked calls accept: √(largest finite) / 64,
/// about 2.1e152 for double and 2.9e17 for float. Within it every dot product, difference and
/// result the calls compute is finite.
template <typename Scalar>
[[nodiscard]] Scalar component_limit() noexcept {
  return std::sqrt(std::numeric_limits<Scalar>::max()) / Scalar(64);
}

/// The smallest contact distance checked::time_of_impact accepts, relative to |p2 − p1|:
/// 4 √(smallest normal), 6.0e-154 in double and 4.3e-19 in float. Below it r² underflows beside
/// |p2 − p1|², and whether the spheres hit is decided by far less than rounding (the miss distance
/// is known only to about ε |p2 − p1|).
template <typename Scalar>
[[nodiscard]] Scalar relative_contact_distance_limit() noexcept {
  return Scalar(4) * std::sqrt(std::numeric_limits<Scalar>::min());
}

/// True when this program may flush subnormal numbers to zero: compiled with fast-math
/// (BILLIARDS_RELAXED_MATH; linking with -ffast-math adds crtfastmath, which sets the FTZ and DAZ
/// flags at start-up), or running with FTZ or DAZ set by other means (probed at run time, for the
/// calling thread). The checked calls then reject masses, contact distances and directions that would
/// read as zero.
template <typename Scalar>
[[nodiscard]] bool subnormals_flushed() noexcept {
#if BILLIARDS_RELAXED_MATH
  return true;
#else
  // volatile: the probe must run on the floating-point unit, not be folded by the compiler.
  volatile Scalar smallest_normal = std::numeric_limits<Scalar>::min();
  volatile Scalar smallest_subnormal = std::numeric_limits<Scalar>::denorm_min();
  const Scalar half = smallest_normal / Scalar(2);  // 0 under FTZ
  const Scalar subnormal = smallest_subnormal;      // read as 0 under DAZ
  return !(half > 0) || !(subnormal > 0);
#endif
}

namespace detail {

// A number (the vectors, Eigen's matrices included, take the overload below, which writes "(x, y, z)" on
// one line: a plain Eigen::Matrix would otherwise match this one exactly and print a column).
template <typename Scalar>
  requires std::is_arithmetic_v<Scalar>
std::string to_text(Scalar value) {
  std::ostringstream out;
  out.precision(std::numeric_limits<Scalar>::max_digits10);
  out << value;
  return out.str();
}

template <typename Derived>
std::string to_text(const Eigen::MatrixBase<Derived>& v) {
  std::string text = "(";
  for (Eigen::Index i = 0; i < v.size(); ++i) text += (i ? ", " : "") + to_text(v[i]);
  return text + ")";
}

/// What "expected" adds where subnormals are flushed: that a subnormal value reads as zero.
template <typename Scalar>
std::string flushed_note() {
  return " of at least the smallest normal number " + to_text(std::numeric_limits<Scalar>::min()) +
         " (subnormal numbers are flushed to zero in this program: -ffast-math, or the FTZ/DAZ flags)";
}

/// True for a subnormal number, read from its bits (under DAZ a comparison would see zero).
template <typename Scalar>
[[nodiscard]] bool is_subnormal(Scalar x) noexcept {
  using Bits = std::conditional_t<sizeof(Scalar) == 4, std::uint32_t, std::uint64_t>;
  constexpr int stored_digits = std::numeric_limits<Scalar>::digits - 1;
  constexpr Bits fraction = (Bits(1) << stored_digits) - 1;
  constexpr Bits exponent = ((Bits(1) << (sizeof(Scalar) * 8 - 1)) - 1) & ~fraction;
  const Bits bits = std::bit_cast<Bits>(x);
  return (bits & exponent) == 0 && (bits & fraction) != 0;
}

/// Where subnormals are flushed, false for a value that would read as zero (a subnormal, or what
/// compares below the smallest normal); true otherwise.
template <typename Scalar>
[[nodiscard]] bool survives_flushing(Scalar x) noexcept {
  return !subnormals_flushed<Scalar>() ||
         !(is_subnormal(x) || std::fabs(x) < std::numeric_limits<Scalar>::min());
}

template <typename Scalar>
void check_mass(const char* function, const char* name, Scalar m) {
  const std::string expected = "a positive mass (finite, or +infinity for an immovable body)";
  if (!std::signbit(m) && !survives_flushing(m)) {
    throw invalid_argument(function, name, to_text(m), expected + flushed_note<Scalar>());
  }
  if (!is_mass(m)) throw invalid_argument(function, name, to_text(m), expected);
}

template <typename Scalar>
void check_masses(const char* function, Scalar m1, Scalar m2) {
  check_mass(function, "m1", m1);
  check_mass(function, "m2", m2);
  if (both_infinite(m1, m2)) {
    throw invalid_argument(function, "m2", to_text(m2),
                           "a finite mass when m1 is infinite (two immovable bodies do not collide)");
  }
}

template <typename Derived>
void check_components(const char* function, const char* name, const Eigen::MatrixBase<Derived>& v,
                      const char* what) {
  using Scalar = typename Derived::Scalar;
  const Scalar limit = component_limit<Scalar>();
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (!(std::fabs(v[i]) <= limit)) {  // also rejects NaN and infinities
      throw invalid_argument(
          function, name, to_text(v),
          std::string(what) + " with finite components of magnitude at most " + to_text(limit));
    }
  }
}

template <typename Derived>
void check_direction(const char* function, const char* name, const Eigen::MatrixBase<Derived>& d) {
  using Scalar = typename Derived::Scalar;
  check_components(function, name, d, "a direction");
  if (d.isZero(0)) throw invalid_argument(function, name, to_text(d), "a non-zero direction");
  if (!survives_flushing(d.cwiseAbs().maxCoeff())) {
    throw invalid_argument(function, name, to_text(d),
                           "a direction with a component" + flushed_note<Scalar>());
  }
}

template <typename Derived>
void check_unit_normal(const char* function, const char* name, const Eigen::MatrixBase<Derived>& n) {
  using Scalar = typename Derived::Scalar;
  check_components(function, name, n, "a unit normal");
  if (!is_unit(n)) {
    throw invalid_argument(function, name, to_text(n),
                           "a unit vector (|n·n − 1| ≤ " + to_text(unit_length_tolerance<Scalar>()) + ")");
  }
}

template <typename Scalar>
void check_restitution(const char* function, Scalar e) {
  if (!is_restitution(e)) {
    throw invalid_argument(function, "restitution", to_text(e), "a coefficient of restitution in [0, 1]");
  }
}

// What every collision call checks: the masses, both velocities and the restitution.
template <typename D1, typename D2>
void check_collision(const char* function, typename D1::Scalar m1, const Eigen::MatrixBase<D1>& v1,
                     typename D1::Scalar m2, const Eigen::MatrixBase<D2>& v2,
                     typename D1::Scalar restitution) {
  check_masses(function, m1, m2);
  check_components(function, "v1", v1, "a velocity");
  check_components(function, "v2", v2, "a velocity");
  check_restitution(function, restitution);
}

}  // namespace detail

/// The validated calls. Each checks every argument, then returns the unchecked call's result.
namespace checked {

/// billiards::collide (the paper's elastic collision, or with restitution e), validated: masses
/// positive (one may be +∞, not both), velocity components finite with magnitude at most
/// component_limit(), n a unit vector within unit_length_tolerance(), 0 ≤ e ≤ 1.
/// \throws billiards::invalid_argument naming the first argument out of its domain
template <typename D1, typename D2, typename DN>
[[nodiscard]] Collision<detail::PlainVector<D1>> collide(
    typename D1::Scalar m1, const Eigen::MatrixBase<D1>& v1, typename D1::Scalar m2,
    const Eigen::MatrixBase<D2>& v2, const Eigen::MatrixBase<DN>& n, typename D1::Scalar restitution = 1) {
  detail::require_vectors<D1, D2, DN>();
  constexpr const char* function = "billiards::checked::collide";
  detail::check_collision(function, m1, v1, m2, v2, restitution);
  detail::check_unit_normal(function, "n", n);
  return restitution == 1 ? billiards::collide(m1, v1, m2, v2, n)
                          : billiards::collide(m1, v1, m2, v2, n, restitution);
}

/// billiards::collide_along_direction, validated: as checked::collide, with d any non-zero
/// direction whose components are finite and at most component_limit() in magnitude.
template <typename D1, typename D2, typename DD>
[[nodiscard]] Collision<detail::PlainVector<D1>> collide_along_direction(
    typename D1::Scalar m1, const Eigen::MatrixBase<D1>& v1, typename D1::Scalar m2,
    const Eigen::MatrixBase<D2>& v2, const Eigen::MatrixBase<DD>& d, typename D1::Scalar restitution = 1) {
  detail::require_vectors<D1, D2, DD>();
  constexpr const char* function = "billiards::checked::collide_along_direction";
  detail::check_collision(function, m1, v1, m2, v2, restitution);
  detail::check_direction(function, "d", d);
  return billiards::collide_along_direction(m1, v1, m2, v2, d, restitution);
}

/// billiards::collide_if_approaching, validated: as checked::collide_along_direction, with the
/// centres p1, p2 finite, at most component_limit() in magnitude, and distinct.
template <typename DP1, typename D1, typename DP2, typename D2>
[[nodiscard]] Collision<detail::PlainVector<D1>> collide_if_approaching(
    typename D1::Scalar m1, const Eigen::MatrixBase<DP1>& p1, const Eigen::MatrixBase<D1>& v1,
    typename D1::Scalar m2, const Eigen::MatrixBase<DP2>& p2, const Eigen::MatrixBase<D2>& v2,
    typename D1::Scalar restitution = 1) {
  detail::require_vectors<D1, D2, DP1, DP2>();
  constexpr const char* function = "billiards::checked::collide_if_approaching";
  detail::check_collision(function, m1, v1, m2, v2, restitution);
  detail::check_components(function, "p1", p1, "a position");
  detail::check_components(function, "p2", p2, "a position");
  using Scalar = typename D1::Scalar;
  if ((p2 - p1).isZero(0) || !detail::survives_flushing((p2 - p1).cwiseAbs().maxCoeff())) {
    const std::string flushed =
        subnormals_flushed<Scalar>() ? ", by a difference" + detail::flushed_note<Scalar>() : std::string();
    throw invalid_argument(function, "p2", detail::to_text(p2),
                           "a centre distinct from p1 = " + detail::to_text(p1) + flushed);
  }
  return billiards::collide_if_approaching(m1, p1, v1, m2, p2, v2, restitution);
}

/// billiards::time_of_impact, validated: positions and velocities finite with components of magnitude
/// at most component_limit(), the contact distance positive, at most component_limit() and at least
/// relative_contact_distance_limit() · |p2 − p1|, and max(|p2 − p1|, contact distance) · |v2 − v1| at
/// most √(largest finite)/8 (the domain of 0.1; the call scales lengths and speeds by powers of two, so
/// no square it forms overflows or underflows anyway). Within it the time is right at every scale. The
/// result is never NaN: a time ≥ 0, or +∞ when the spheres never touch (or would touch only after
/// more than the largest finite time).
/// \throws billiards::invalid_argument naming the first argument out of its domain ("v2 − v1" for a
///         relative speed too large for the distances involved)
template <typename DP1, typename D1, typename DP2, typename D2>
[[nodiscard]] typename D1::Scalar time_of_impact(const Eigen::MatrixBase<DP1>& p1,
                                                 const Eigen::MatrixBase<D1>& v1,
                                                 const Eigen::MatrixBase<DP2>& p2,
                                                 const Eigen::MatrixBase<D2>& v2,
                                                 typename D1::Scalar contact_distance) {
  using Scalar = typename D1::Scalar;
  detail::require_vectors<D1, D2, DP1, DP2>();
  constexpr const char* function = "billiards::checked::time_of_impact";
  detail::check_components(function, "p1", p1, "a position");
  detail::check_components(function, "v1", v1, "a velocity");
  detail::check_components(function, "p2", p2, "a position");
  detail::check_components(function, "v2", v2, "a velocity");
  if (!(contact_distance > 0 && contact_distance <= component_limit<Scalar>()) ||
      !detail::survives_flushing(contact_distance)) {  // also rejects NaN
    throw invalid_argument(function, "contact_distance", detail::to_text(contact_distance),
                           "a positive contact distance (the sum of the radii) of at most " +
                               detail::to_text(component_limit<Scalar>()) +
                               (subnormals_flushed<Scalar>() ? " and" + detail::flushed_note<Scalar>() : ""));
  }
  // scaled_norm: a plain norm's squares underflow for tiny distances (|p2 − p1| = 2.6e-23 in float gave
  // 0, and a contact distance far below the limit passed the test; found by the fuzz harness).
  const Scalar distance = detail::scaled_norm(p2 - p1);
  if (!(contact_distance >= relative_contact_distance_limit<Scalar>() * distance)) {
    throw invalid_argument(function, "contact_distance", detail::to_text(contact_distance),
                           "a contact distance of at least relative_contact_distance_limit() · |p2 − p1| = " +
                               detail::to_text(relative_contact_distance_limit<Scalar>() * distance) +
                               " (below it whether the spheres hit is decided by less than rounding)");
  }
  const Scalar reach = std::max(distance, contact_distance), speed = detail::scaled_norm(v2 - v1);
  const Scalar largest_product = std::sqrt(std::numeric_limits<Scalar>::max()) / Scalar(8);
  if (!(reach * speed <= largest_product)) {
    const detail::PlainVector<D1> relative = v2 - v1;
    const Eigen::MatrixBase<detail::PlainVector<D1>>& relative_velocity = relative;  // printed as a vector
    throw invalid_argument(function, "v2 − v1", detail::to_text(relative_velocity),
                           "a relative velocity with max(|p2 − p1|, contact_distance) · |v2 − v1| at most " +
                               detail::to_text(largest_product) + " (it is " +
                               detail::to_text(reach * speed) + ")");
  }
  return billiards::time_of_impact(p1, v1, p2, v2, contact_distance);
}

/// billiards::reflect, validated: v's components finite and at most component_limit(), n a unit vector.
template <typename DV, typename DN>
[[nodiscard]] detail::PlainVector<DV> reflect(const Eigen::MatrixBase<DV>& v,
                                              const Eigen::MatrixBase<DN>& n) {
  detail::require_vectors<DV, DN>();
  constexpr const char* function = "billiards::checked::reflect";
  detail::check_components(function, "v", v, "a velocity");
  detail::check_unit_normal(function, "n", n);
  return billiards::reflect(v, n);
}

}  // namespace checked
}  // namespace billiards
