// The paper's result typed by hand from the paper, S. T. Parkin, "Billiard Ball Physics" (2023):
//   x1 = v1 + (2 m2/(m1 + m2)) ((v2 − v1)·n) n,  x2 = v2 + (2 m1/(m1 + m2)) ((v1 − v2)·n) n,
//   and at a cushion x = v − 2 (v·n) n.
// The independent reference for the runtime's tests: it includes no generated header, and it is
// evaluated in long double.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <limits>

namespace paper {

template <int N>
using Vector = Eigen::Matrix<long double, N, 1>;

template <int N>
struct Result {
  Vector<N> x1;
  Vector<N> x2;
};

template <int N>
Result<N> collision(long double m1, const Vector<N>& v1, long double m2, const Vector<N>& v2,
                    const Vector<N>& n) {
  return {v1 + (2 * m2 / (m1 + m2)) * (v2 - v1).dot(n) * n, v2 + (2 * m1 / (m1 + m2)) * (v1 - v2).dot(n) * n};
}

template <int N>
Vector<N> reflection(const Vector<N>& v, const Vector<N>& n) {
  return v - 2 * v.dot(n) * n;
}

// Beyond the paper, typed by hand from the textbook formulas (not from the audit): restitution e,
// x1 = v1 + (1 + e) m2/(m1 + m2) ((v2 − v1)·n) n, x2 = v2 − (1 + e) m1/(m1 + m2) ((v2 − v1)·n) n, with a
// non-unit direction d entering as n = d/|d|.
template <int N>
Result<N> restitution_collision(long double m1, const Vector<N>& v1, long double m2, const Vector<N>& v2,
                                const Vector<N>& d, long double e) {
  const Vector<N> n = d / d.norm();
  const long double approach = (v2 - v1).dot(n);
  return {v1 + (1 + e) * m2 / (m1 + m2) * approach * n, v2 - (1 + e) * m1 / (m1 + m2) * approach * n};
}

// The time of impact, typed from the textbook: spheres at p1 + t v1 and p2 + t v2 touch when
// |p + t w|² = r² (p = p2 − p1, w = v2 − v1, r the sum of the radii), whose smaller root is
// (−p·w − √((p·w)² − (w·w)(p·p − r²)))/(w·w). The first contact in the future while approaching, or +∞.
template <int N>
long double time_of_impact(const Vector<N>& p1, const Vector<N>& v1, const Vector<N>& p2, const Vector<N>& v2,
                           long double r) {
  const Vector<N> p = p2 - p1, w = v2 - v1;
  const long double a = w.dot(w), b = p.dot(w), c = p.dot(p) - r * r;
  const long double discriminant = b * b - a * c;
  if (a == 0 || b >= 0 || discriminant <= 0) return std::numeric_limits<long double>::infinity();
  const long double t = (-b - std::sqrt(discriminant)) / a;
  return t < 0 ? 0 : t;
}

}  // namespace paper
