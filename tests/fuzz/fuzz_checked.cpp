// libFuzzer harness for the checked API. Arbitrary bytes are shaped into arguments so that most
// inputs are valid (masses over the whole range, finite velocities, unit normals, restitution in
// [0, 1]) and a few are not (NaN, infinities, zero or negative masses, non-unit normals). For every
// accepted input: no crash, no sanitizer report, no NaN or infinity in the result, and for elastic
// collisions of finite masses, momentum conserved to rounding. A rejected input must throw
// billiards::invalid_argument and nothing else.
#include <billiards/checked.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <string>

namespace {

long accepted_inputs = 0;
long all_inputs = 0;
std::map<std::string, long> rejected_by_argument;

// Prints the acceptance figure when the fuzzer exits (libFuzzer calls exit()).
struct Report {
  ~Report() {
    std::fprintf(stderr, "billiards fuzz: %ld of %ld inputs accepted by the checked API\n", accepted_inputs,
                 all_inputs);
    for (const auto& [argument, count] : rejected_by_argument) {
      std::fprintf(stderr, "  rejected for %s: %ld\n", argument.c_str(), count);
    }
  }
} report;

class Shaper {
 public:
  Shaper(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  // The input read cyclically (a short input still shapes every argument); an empty one is all 128s.
  std::uint8_t byte() { return size_ == 0 ? 128 : data_[position_++ % size_]; }

  // A value of `Scalar` that is almost always valid for its role, and sometimes one of the edge cases.
  // Edge cases are behind a rare selector byte (0xA5), not behind 0–6, which the fuzzer's mutations
  // favour: so most inputs are valid and the rest still reach every edge case.
  template <typename Scalar>
  Scalar special_or(Scalar usual) {
    if (byte() != 0xA5) return usual;
    switch (byte() % 8) {
      case 0: return std::numeric_limits<Scalar>::quiet_NaN();
      case 1: return std::numeric_limits<Scalar>::infinity();
      case 2: return -std::numeric_limits<Scalar>::infinity();
      case 3: return Scalar(0);
      case 4: return -usual;
      case 5: return std::numeric_limits<Scalar>::denorm_min();
      case 6: return std::numeric_limits<Scalar>::max();
      default: return usual;
    }
  }
  template <typename Scalar>
  Scalar mass() {
    const int exponent = static_cast<int>(byte()) - 128;  // 2^-128 … 2^127, then scaled
    const Scalar usual = std::ldexp(Scalar(1) + Scalar(byte()) / Scalar(256), exponent);
    return special_or(usual > 0 ? usual : std::numeric_limits<Scalar>::denorm_min());
  }
  template <typename Scalar>
  Scalar component() {
    const int exponent = static_cast<int>(byte() % 64) - 32;
    const Scalar magnitude = std::ldexp(Scalar(byte()) / Scalar(255), exponent);
    return special_or(byte() % 2 ? magnitude : -magnitude);
  }
  template <typename Vector>
  Vector vector() {
    Vector v;
    for (int i = 0; i < v.size(); ++i) v[i] = component<typename Vector::Scalar>();
    return v;
  }
  template <typename Vector>
  Vector unit() {
    Vector v = vector<Vector>();
    const auto norm = v.norm();
    if (byte() != 0xA5 && std::isfinite(norm) && norm > 0) v /= norm;  // 0xA5: leave it unnormalised
    return v;
  }
  template <typename Scalar>
  Scalar restitution() {
    return special_or(Scalar(byte()) / Scalar(255));
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

// A broken property: say which, with the values, then crash so that libFuzzer keeps the input.
template <typename Vector>
[[noreturn]] void fail(const char* property, const billiards::Collision<Vector>& result) {
  std::fprintf(stderr, "billiards fuzz: %s violated\n", property);
  for (int i = 0; i < result.first.size(); ++i) {
    std::fprintf(stderr, "  x1[%d] = %.17Lg  x2[%d] = %.17Lg\n", i, static_cast<long double>(result.first[i]),
                 i, static_cast<long double>(result.second[i]));
  }
  std::abort();
}

template <typename Vector>
void require_finite(const billiards::Collision<Vector>& result) {
  if (!result.first.allFinite() || !result.second.allFinite()) fail("finite result", result);
}

// Momentum m1 v1 + m2 v2 conserved to rounding (finite masses only).
template <typename Vector>
void require_momentum(typename Vector::Scalar m1, const Vector& v1, typename Vector::Scalar m2,
                      const Vector& v2, const billiards::Collision<Vector>& result) {
  if (std::isinf(m1) || std::isinf(m2)) return;
  using Long = Eigen::Matrix<long double, Vector::RowsAtCompileTime, 1>;
  const long double M1 = m1, M2 = m2;
  const Long before = M1 * v1.template cast<long double>() + M2 * v2.template cast<long double>();
  const Long after =
      M1 * result.first.template cast<long double>() + M2 * result.second.template cast<long double>();
  const long double scale = M1 * v1.template cast<long double>().norm() +
                            M2 * v2.template cast<long double>().norm() +
                            M1 * result.first.template cast<long double>().norm() +
                            M2 * result.second.template cast<long double>().norm();
  // Rounding is relative (ε) for normal results and absolute (the smallest subnormal) below them: a
  // heavy ball's velocity cannot change by less than denorm_min, whatever momentum that carries.
  const long double epsilon = std::numeric_limits<typename Vector::Scalar>::epsilon();
  const long double absolute = (M1 + M2) * std::numeric_limits<typename Vector::Scalar>::denorm_min() * 4;
  if (!((after - before).cwiseAbs().maxCoeff() <= 64 * epsilon * scale + absolute)) {
    std::fprintf(stderr, "  m1 = %.17Lg m2 = %.17Lg, momentum change %.17Lg, scale %.17Lg\n", M1, M2,
                 (after - before).cwiseAbs().maxCoeff(), scale);
    fail("momentum conservation", result);
  }
}

template <typename Vector>
void exercise(Shaper& shape) {
  using Scalar = typename Vector::Scalar;
  const Scalar m1 = shape.mass<Scalar>(), m2 = shape.mass<Scalar>();
  const Vector v1 = shape.vector<Vector>(), v2 = shape.vector<Vector>();
  ++all_inputs;
  try {
    // One of the checked calls, chosen and shaped by the input; the properties are checked once below.
    const auto result = [&] {
      switch (shape.byte() % 4) {
        case 0: return billiards::checked::collide(m1, v1, m2, v2, shape.unit<Vector>());
        case 1: {
          const Vector n = shape.unit<Vector>();
          return billiards::checked::collide(m1, v1, m2, v2, n, shape.restitution<Scalar>());
        }
        case 2: {
          const Vector d = shape.vector<Vector>();
          return billiards::checked::collide_along_direction(m1, v1, m2, v2, d, shape.restitution<Scalar>());
        }
        default: {
          const Vector p1 = shape.vector<Vector>(), p2 = shape.vector<Vector>();
          return billiards::checked::collide_if_approaching(m1, p1, v1, m2, p2, v2,
                                                            shape.restitution<Scalar>());
        }
      }
    }();
    require_finite(result);
    require_momentum(m1, v1, m2, v2, result);
    if (!billiards::checked::reflect(v1, Vector::Unit(0)).allFinite()) fail("finite reflection", result);
    ++accepted_inputs;
  } catch (const billiards::invalid_argument& error) {
    ++rejected_by_argument[error.argument()];
    // Rejected with a clear error: fine. Anything else escaping is a bug and crashes the fuzzer.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Shaper shape(data, size);
  switch (shape.byte() % 4) {
    case 0: exercise<Eigen::Vector3d>(shape); break;
    case 1: exercise<Eigen::Vector2d>(shape); break;
    case 2: exercise<Eigen::Vector3f>(shape); break;
    default: exercise<Eigen::Vector2f>(shape); break;
  }
  return 0;
}
