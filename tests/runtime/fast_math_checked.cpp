// Built with -ffast-math -fno-finite-math-only (compile and link: g++ then links crtfastmath, which
// flushes subnormals to zero, FTZ and DAZ): the checked API must still never return a non-finite result
// for an input it accepts. Masses, directions and contact distances over the whole exponent range,
// subnormals included, both as run-time values and as constants the compiler could fold.
#include <billiards/checked.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

namespace {

template <typename Scalar>
Scalar opaque(Scalar x) {  // a value the compiler cannot fold: the arithmetic on it runs with FTZ/DAZ
  volatile Scalar copy = x;
  return copy;
}

template <typename Vector>
bool finite(const billiards::Collision<Vector>& result) {
  return result.first.allFinite() && result.second.allFinite();
}

}  // namespace

TEMPLATE_TEST_CASE("Under -ffast-math the checked calls accept only what they can compute",
                   "[runtime][fast_math]", float, double) {
  using Scalar = TestType;
  using Vector = Eigen::Matrix<Scalar, 3, 1>;
  using limits = std::numeric_limits<Scalar>;
  // g++ announces the relaxed arithmetic; both compilers' -ffast-math link flushes subnormals.
#if defined(__GNUC__) && !defined(__clang__)
  STATIC_REQUIRE(BILLIARDS_RELAXED_MATH == 1);
#endif
  CHECK(billiards::subnormals_flushed<Scalar>());
  volatile Scalar smallest = std::numeric_limits<Scalar>::min();
  CHECK(smallest / 2 == 0);  // FTZ is on: what the test is about
  std::mt19937_64 random(12);
  std::uniform_real_distribution<double> component(-10, 10);
  const auto random_vector = [&] {
    return Vector(Scalar(component(random)), Scalar(component(random)), Scalar(component(random)));
  };
  std::size_t accepted = 0, rejected = 0, non_finite = 0;
  const auto run = [&](auto&& call, auto&& is_finite) {
    try {
      if (!is_finite(call())) {
        ++non_finite;
        FAIL_CHECK("a non-finite result from an accepted input");
      }
      ++accepted;
    } catch (const billiards::invalid_argument& error) {
      ++rejected;
    }
  };
  const auto collision_finite = [](const auto& result) { return finite(result); };
  // Every exponent, subnormals included, and +infinity.
  std::vector<Scalar> masses;
  for (int k = limits::min_exponent - limits::digits; k < limits::max_exponent; k += 3)
    masses.push_back(std::ldexp(Scalar(1), k));
  masses.push_back(limits::infinity());
  const Vector n = Vector(1, 2, 2) / Scalar(3);
  for (const Scalar m1 : masses) {
    for (const Scalar m2 : masses) {
      const Vector v1 = random_vector(), v2 = random_vector();
      run([&] { return billiards::checked::collide(opaque(m1), v1, opaque(m2), v2, n); }, collision_finite);
      run([&] { return billiards::checked::collide(m1, v1, m2, v2, n, Scalar(0.5)); }, collision_finite);
      run(
          [&] {
            return billiards::checked::collide_along_direction(opaque(m1), v1, m2, v2, random_vector());
          },
          collision_finite);
      run(
          [&] {
            return billiards::checked::collide_if_approaching(m1, Vector::Zero().eval(), v1, opaque(m2), n,
                                                              v2);
          },
          collision_finite);
    }
  }
  // A subnormal mass is rejected, and the message says why; also written as a constant the compiler
  // could fold.
  const Scalar subnormal = limits::denorm_min() * 8;
  CHECK_THROWS_WITH(
      billiards::checked::collide(opaque(subnormal), Vector(1, 0, 0), Scalar(1), Vector(-1, 0, 0), n),
      Catch::Contains("m1 is") && Catch::Contains("flushed to zero"));
  CHECK_THROWS_WITH(billiards::checked::collide(Scalar(1), Vector(1, 0, 0), subnormal, Vector(-1, 0, 0), n),
                    Catch::Contains("m2 is") && Catch::Contains("flushed to zero"));
  run(
      [&] {
        return billiards::checked::collide(Scalar(1e-41f), Vector(1, 0, 0), Scalar(1e-41f), Vector(-1, 0, 0),
                                           n);
      },
      collision_finite);
  // Directions, separations and contact distances down to the smallest subnormal.
  for (int k = limits::min_exponent - limits::digits; k < limits::max_exponent / 2 - 8; k += 5) {
    const Scalar tiny = std::ldexp(Scalar(1), k);
    const Vector small = random_vector() * tiny;
    run(
        [&] {
          return billiards::checked::collide_along_direction(Scalar(1), random_vector(), Scalar(2),
                                                             random_vector(), small);
        },
        collision_finite);
    run(
        [&] {
          return billiards::checked::collide_if_approaching(Scalar(1), Vector::Zero().eval(), random_vector(),
                                                            Scalar(2), small, random_vector());
        },
        collision_finite);
    run([&] { return billiards::checked::reflect(small, n); }, [](const Vector& v) { return v.allFinite(); });
    const auto time_finite_or_infinite = [](Scalar t) { return !std::isnan(t) && t >= 0; };
    run(
        [&] {
          return billiards::checked::time_of_impact(Vector::Zero().eval(), small, small, -small,
                                                    opaque(tiny));
        },
        time_finite_or_infinite);
    run(
        [&] {
          return billiards::checked::time_of_impact(Vector::Zero().eval(), random_vector(), Vector(1, 0, 0),
                                                    small, Scalar(0.1));
        },
        time_finite_or_infinite);
  }
  INFO(accepted << " accepted, " << rejected << " rejected");
  CHECK(non_finite == 0);
  CHECK(accepted > 1000);
  CHECK(rejected > 100);  // the subnormal masses, directions and distances
}
