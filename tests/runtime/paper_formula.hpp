// The paper's result typed by hand from the paper, S. T. Parkin, "Billiard Ball Physics" (2023):
//   x1 = v1 + (2 m2/(m1 + m2)) ((v2 − v1)·n) n,  x2 = v2 + (2 m1/(m1 + m2)) ((v1 − v2)·n) n,
//   and at a cushion x = v − 2 (v·n) n.
// The independent reference for the runtime's tests: it includes no generated header, and it is
// evaluated in long double.
#pragma once

#include <Eigen/Core>

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

}  // namespace paper
