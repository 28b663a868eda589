// What the runtime tests share: the scalar type and dimension under test, and exact copies of vectors.
#pragma once

#include "paper_formula.hpp"

#include <Eigen/Core>

namespace billiards_test {

/// One configuration of a TEMPLATE_TEST_CASE: a scalar type S in D dimensions.
template <typename S, int D>
struct Config {
  using Scalar = S;
  static constexpr int dimension = D;
  using Vector = Eigen::Matrix<S, D, 1>;
};

/// v in long double: exact, since every float and double is a long double.
template <typename Vector>
paper::Vector<Vector::RowsAtCompileTime> exact(const Vector& v) {
  return v.template cast<long double>();
}

}  // namespace billiards_test
