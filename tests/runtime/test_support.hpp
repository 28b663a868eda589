// What the runtime tests share: the scalar type and dimension under test, exact copies of vectors, and
// numbers of every kind (edge values and random bit patterns).
#pragma once

#include "paper_formula.hpp"

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

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

/// The unsigned integer of Scalar's width.
template <typename Scalar>
using Bits = std::conditional_t<sizeof(Scalar) == 8, std::uint64_t, std::uint32_t>;

/// Edge values and `random_count` random bit patterns from `seed` (every exponent, subnormals, ±0, ±∞ and
/// NaNs among them).
template <typename Scalar>
std::vector<Scalar> every_kind_of(std::uint64_t seed, int random_count) {
  using limits = std::numeric_limits<Scalar>;
  std::vector<Scalar> values = {Scalar(0),
                                Scalar(-0.0),
                                limits::denorm_min(),
                                -limits::denorm_min(),
                                limits::min(),
                                std::nextafter(limits::min(), Scalar(0)),
                                Scalar(1),
                                Scalar(1.5),
                                -Scalar(3),
                                limits::max(),
                                -limits::max(),
                                limits::infinity(),
                                -limits::infinity(),
                                limits::quiet_NaN()};
  std::mt19937_64 random(seed);
  for (int i = 0; i < random_count; ++i) {
    const auto bits = static_cast<Bits<Scalar>>(random());
    Scalar x;
    std::memcpy(&x, &bits, sizeof x);
    values.push_back(x);
  }
  return values;
}

}  // namespace billiards_test
