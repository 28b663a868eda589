// The fuzz harness's references: each checked call's result computed again in long double, from the
// formulas as the guides print them (not from the kernels), with the rounding the call may add as an
// explicit bound. long double has 11 more bits and a far wider exponent range than double, so the
// reference neither overflows nor underflows where the calls must not.
#pragma once

#include <billiards/collision.hpp>

#include <Eigen/Core>

#include <cmath>
#include <cstring>
#include <limits>

namespace billiards_fuzz {

using Long = long double;
template <typename Vector>
using LongVector = Eigen::Matrix<Long, Vector::RowsAtCompileTime, 1>;

/// How many ε of the magnitudes involved a result may be off; loose beside the 2–4 the accuracy tool
/// sees, tight beside any wrong formula (a wrong coefficient or sign is off by order 1).
constexpr Long tolerance = 32;

/// What a collision call must return: the reference velocities with a bound per component; or the
/// inputs unchanged to the bit; or, on the edge of approaching, either.
template <typename Vector>
struct Expected {
  LongVector<Vector> first, second;              ///< the reference results
  LongVector<Vector> first_bound, second_bound;  ///< the largest |computed − reference| allowed
  bool collision = true;                         ///< the reference results apply
  bool unchanged = false;                        ///< returning v1, v2 unchanged (bit for bit) is right
  Vector v1, v2;
  Vector direction;  ///< n or d as the call received it (for the report)
};

template <typename Vector>
LongVector<Vector> to_long(const Vector& v) {
  return v.template cast<Long>();
}

/// (1 + e) m_other/(m1 + m2), with an infinite mass as the limit: 1 + e against a wall, 0 for the wall.
template <typename Scalar>
Long coefficient(Scalar own, Scalar other, Scalar e) {
  if (std::isinf(other)) return 1 + Long(e);
  if (std::isinf(own)) return 0;
  return (1 + Long(e)) * Long(other) / (Long(own) + Long(other));
}

/// x1 = v1 + c1 ((v2 − v1)·d)/(d·d) d, x2 = v2 − c2 ((v2 − v1)·d)/(d·d) d; `unit`: d is the given
/// (unit) normal, not divided by d·d, as billiards::collide computes.
template <typename Vector>
Expected<Vector> expected_collision(typename Vector::Scalar m1, const Vector& v1, typename Vector::Scalar m2,
                                    const Vector& v2, const Vector& d, typename Vector::Scalar e, bool unit) {
  using Scalar = typename Vector::Scalar;
  const LongVector<Vector> a = to_long(v1), b = to_long(v2), n = to_long(d);
  const Long dd = unit ? Long(1) : n.squaredNorm();
  const Long s = (b - a).dot(n) / dd;
  const Long spread = (a.cwiseAbs() + b.cwiseAbs()).dot(n.cwiseAbs()) / dd;  // bounds the rounding of s
  const Long c1 = coefficient(m1, m2, e), c2 = coefficient(m2, m1, e);
  const Long epsilon = std::numeric_limits<Scalar>::epsilon(),
             tiny = std::numeric_limits<Scalar>::denorm_min();
  Expected<Vector> expected;
  expected.first = a + c1 * s * n;
  expected.second = b - c2 * s * n;
  // Relative rounding (ε), and absolute rounding where d's components, scaled to put the largest in
  // [1/2, 1), or the products fall below the normal range: each moves s by at most
  // (|v1|₁ + |v2|₁ + dimension) times the smallest subnormal, which the update scales by c.
  const Long underflow = 16 * tiny * (a.cwiseAbs().sum() + b.cwiseAbs().sum() + Long(a.size()));
  expected.first_bound = tolerance * epsilon * (a.cwiseAbs() + c1 * spread * n.cwiseAbs()) +
                         LongVector<Vector>::Constant(4 * tiny + c1 * underflow);
  expected.second_bound = tolerance * epsilon * (b.cwiseAbs() + c2 * spread * n.cwiseAbs()) +
                          LongVector<Vector>::Constant(4 * tiny + c2 * underflow);
  expected.v1 = v1;
  expected.v2 = v2;
  expected.direction = d;
  return expected;
}

/// collide_if_approaching: the collision along d = p2 − p1 when (v2 − v1)·d < 0, else v1, v2
/// unchanged to the bit; within rounding of 0, either.
template <typename Vector>
Expected<Vector> expected_if_approaching(typename Vector::Scalar m1, const Vector& p1, const Vector& v1,
                                         typename Vector::Scalar m2, const Vector& p2, const Vector& v2,
                                         typename Vector::Scalar e) {
  using Scalar = typename Vector::Scalar;
  const LongVector<Vector> d = to_long(p2) - to_long(p1);
  // The direction the call uses is p2 − p1 rounded to Scalar; its approach test may differ from the
  // exact one by the rounding of the dot product.
  Vector rounded = p2 - p1;
  Expected<Vector> expected = expected_collision(m1, v1, m2, v2, rounded, e, /*unit=*/false);
  const Long s = (to_long(v2) - to_long(v1)).dot(d);
  const Long spread = (to_long(v1).cwiseAbs() + to_long(v2).cwiseAbs()).dot(d.cwiseAbs());
  // Rounding: relative ε in the products, and absolute where d's components, scaled to put the largest
  // in [1/2, 1), or the products fall below the normal range (the smallest subnormal, scaled back).
  const Long underflow = 4 * std::numeric_limits<Scalar>::denorm_min() * 2 * d.cwiseAbs().maxCoeff() *
                         (to_long(v1).cwiseAbs().sum() + to_long(v2).cwiseAbs().sum() + d.size());
  const Long uncertain = tolerance * std::numeric_limits<Scalar>::epsilon() * spread + underflow;
  expected.collision = s < uncertain;
  expected.unchanged = s >= -uncertain;
  return expected;
}

/// reflect: v − 2 (v·n) n as computed (n not divided by n·n); the second "ball" is v2, unchanged.
template <typename Vector>
Expected<Vector> expected_reflection(const Vector& v, const Vector& n, const Vector& v2) {
  using Scalar = typename Vector::Scalar;
  const LongVector<Vector> a = to_long(v), u = to_long(n);
  const Long epsilon = std::numeric_limits<Scalar>::epsilon(),
             tiny = std::numeric_limits<Scalar>::denorm_min();
  Expected<Vector> expected;
  expected.first = a - 2 * a.dot(u) * u;
  expected.first_bound =
      tolerance * epsilon * (a.cwiseAbs() + 2 * a.cwiseAbs().dot(u.cwiseAbs()) * u.cwiseAbs()) +
      LongVector<Vector>::Constant(4 * tiny);
  expected.second = to_long(v2);
  expected.second_bound = LongVector<Vector>::Zero();
  expected.v1 = v;
  expected.v2 = v2;
  return expected;
}

template <typename Vector>
bool same_bits(const Vector& a, const Vector& b) {
  return std::memcmp(a.data(), b.data(), sizeof(typename Vector::Scalar) * std::size_t(a.size())) == 0;
}

/// nullptr when `result` is right, else what is wrong.
template <typename Vector>
const char* compare(const billiards::Collision<Vector>& result, const Expected<Vector>& expected) {
  if (expected.unchanged && same_bits(result.first, expected.v1) && same_bits(result.second, expected.v2)) {
    return nullptr;
  }
  if (!expected.collision) return "a separating pair was not returned unchanged (bit for bit)";
  const bool close =
      ((to_long(result.first) - expected.first).cwiseAbs().array() <= expected.first_bound.array()).all() &&
      ((to_long(result.second) - expected.second).cwiseAbs().array() <= expected.second_bound.array()).all();
  return close ? nullptr : "the result is farther from the reference than rounding allows";
}

/// time_of_impact against the same quadratic in long double: t ≥ 0 or +∞, never NaN; +∞ exactly
/// where the spheres separate, stand still or miss by more than rounding; a finite time where they
/// surely hit, within rounding of the reference root c/(√D − b); and any finite time is the root of
/// inputs perturbed by rounding (its backward error, as billiards-accuracy judges it).
template <typename Vector>
const char* compare_time(typename Vector::Scalar t, const Vector& p1, const Vector& v1, const Vector& p2,
                         const Vector& v2, typename Vector::Scalar r) {
  using Scalar = typename Vector::Scalar;
  if (std::isnan(t) || t < 0) return "a time that is NaN or negative";
  const LongVector<Vector> p = to_long(p2) - to_long(p1), w = to_long(v2) - to_long(v1);
  const Long a = w.squaredNorm(), b = p.dot(w), pp = p.squaredNorm(), rr = Long(r) * Long(r), c = pp - rr;
  Long cross = 0;  // |p × w|² as Σ_{i<j} (p_i w_j − p_j w_i)²
  for (int i = 0; i < p.size(); ++i) {
    for (int j = i + 1; j < p.size(); ++j) cross += (p[i] * w[j] - p[j] * w[i]) * (p[i] * w[j] - p[j] * w[i]);
  }
  const Long discriminant = a * rr - cross;
  const Long epsilon = std::numeric_limits<Scalar>::epsilon(), K = tolerance;
  const Long length = std::sqrt(pp), speed = std::sqrt(a);
  const bool approaching = b<-K * epsilon * length * speed, separating = b> K * epsilon * length * speed;
  // The rounding of p2 − p1 and v2 − v1 (and of the products) moves the miss distance |p × w|/|w| by
  // δ/|w|, δ = K ε |p| |w|: |p × w|² by 2 δ |p × w| + δ². The second-order term rules where the pair is
  // nearly head on and r is below a few ε |p| (float, r = 2^−149 beside |p| = 3.8e-38: the computed
  // differences alone put the spheres 1.4 r apart; found by the fuzz bounded run in CI).
  const Long miss_rounding = K * epsilon * length * speed;
  const Long discriminant_error = K * epsilon * a * rr + miss_rounding * (std::sqrt(cross) + miss_rounding);
  const bool hit = discriminant > discriminant_error, miss = discriminant < -discriminant_error;
  if (a == 0 || separating || miss) {
    return std::isinf(t) ? nullptr : "a finite time where the spheres separate, stand still or miss";
  }
  const Long largest = std::numeric_limits<Scalar>::max();
  if (approaching && hit) {
    const Long root = c <= 0 ? Long(0) : c / (std::sqrt(discriminant) - b);
    const Long denominator = std::sqrt(discriminant) - b;
    // The rounding of c, of b and of D (already a bound, through √D's derivative) moves the root.
    const Long bound = K * epsilon * ((pp + rr) / denominator + root * length * speed / denominator) +
                       root * discriminant_error / (2 * std::sqrt(discriminant)) / denominator +
                       std::numeric_limits<Scalar>::denorm_min();
    if (std::isinf(t))
      return root + bound >= largest ? nullptr : "+infinity (no contact) where the spheres surely hit";
    return std::fabs(Long(t) - root) <= bound ? nullptr
                                              : "a time farther from the reference root than rounding allows";
  }
  // Within rounding of a graze or of standing still: +∞; 0 for spheres that touch or overlap (to
  // rounding); or a time that solves the inputs to rounding.
  if (std::isinf(t)) return nullptr;
  if (t == 0 && c <= K * epsilon * (pp + rr)) return nullptr;
  const Long T = t, residual = a * T * T + 2 * b * T + c;
  const Long scale = a * T * T + 2 * std::fabs(b) * T + pp + rr;
  return std::fabs(residual) <= K * epsilon * scale + std::numeric_limits<Scalar>::denorm_min()
             ? nullptr
             : "a time that is no contact time of the inputs, even perturbed by rounding";
}

}  // namespace billiards_fuzz
