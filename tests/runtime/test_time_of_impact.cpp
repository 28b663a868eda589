// billiards::time_of_impact: the first contact of two moving spheres, against the textbook quadratic
// formula (paper_formula.hpp) in long double, and the cases the audit names: a head-on approach, a
// miss, a graze, separating, at rest relative to each other, touching now.
#include <billiards/checked.hpp>
#include <billiards/collision.hpp>

#include "paper_formula.hpp"
#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <cfenv>
#include <cmath>
#include <limits>
#include <random>

namespace {

using billiards_test::Config;
using billiards_test::exact;

template <typename Vector>
Vector from(double x, double y, double z = 0) {
  Vector v = Vector::Zero();
  v[0] = static_cast<typename Vector::Scalar>(x);
  v[1] = static_cast<typename Vector::Scalar>(y);
  if (v.size() > 2) v[2] = static_cast<typename Vector::Scalar>(z);
  return v;
}

// Whether `call` raises the invalid flag (FE_INVALID). Its result is stored to a volatile first, so the
// computation is done before the flag is read.
template <typename Call>
bool raises_invalid(Call call) {
  std::feclearexcept(FE_ALL_EXCEPT);
  volatile auto result = call();
  static_cast<void>(result);
  return std::fetestexcept(FE_INVALID) != 0;
}

}  // namespace

TEMPLATE_TEST_CASE("time_of_impact raises no invalid flag on a miss", "[runtime][time_of_impact]",
                   (Config<float, 2>), (Config<double, 2>), (Config<float, 3>), (Config<double, 3>)) {
  // A miss has D = (w·w) r² − |p × w|² < 0. The kernel takes √ of 0 there, not of D (its overridden
  // guard), as the time is +∞ either way: √ of a negative number raises the invalid flag, which kills
  // a program that traps it (feenableexcept(FE_INVALID), a common guard against NaNs), and went
  // through libm's errno path on every miss.
  using Scalar = typename TestType::Scalar;
  using Vector = typename TestType::Vector;
  const Scalar infinity = std::numeric_limits<Scalar>::infinity();
  const Vector origin = Vector::Zero();
  SECTION("the audit's miss") {
    const auto miss = [&] {
      return billiards::time_of_impact(origin, origin, from<Vector>(10, 3), from<Vector>(-1, 0), Scalar(2));
    };
    CHECK_FALSE(raises_invalid(miss));
    CHECK(miss() == infinity);
  }
  SECTION("random approaching misses") {
    std::mt19937_64 random(14);
    std::uniform_real_distribution<double> coordinate(-10, 10);
    int misses = 0, flagged = 0;
    for (int i = 0; i < 2000; ++i) {
      const Vector p1 = from<Vector>(coordinate(random), coordinate(random), coordinate(random));
      const Vector p2 = from<Vector>(coordinate(random), coordinate(random), coordinate(random));
      const Vector v1 = from<Vector>(coordinate(random), coordinate(random), coordinate(random));
      const Vector v2 = from<Vector>(coordinate(random), coordinate(random), coordinate(random));
      const Vector p = p2 - p1, w = v2 - v1;
      const Scalar r = Scalar(0.5);
      // Approaching (p·w < 0), apart (|p| > r) and missing: the closest approach |p × w|/|w| beyond r.
      const double pw = double(p.dot(w)), ww = double(w.squaredNorm()), pp = double(p.squaredNorm());
      if (!(pw < 0) || pp <= 4 * double(r) * double(r) || pp - pw * pw / ww <= 4 * double(r) * double(r))
        continue;
      ++misses;
      const auto call = [&] { return billiards::time_of_impact(p1, v1, p2, v2, r); };
      flagged += raises_invalid(call) ? 1 : 0;
      CHECK(call() == infinity);
    }
    CHECK(misses > 500);
    CHECK(flagged == 0);
  }
}

TEMPLATE_TEST_CASE("time_of_impact: the cases of the audit", "[runtime][time_of_impact]", (Config<float, 2>),
                   (Config<double, 2>), (Config<float, 3>), (Config<double, 3>)) {
  using Scalar = typename TestType::Scalar;
  using Vector = typename TestType::Vector;
  const Scalar infinity = std::numeric_limits<Scalar>::infinity();
  const Vector origin = Vector::Zero();
  SECTION("head on: the gap closes at the relative speed") {
    // Centres 10 apart, radii summing to 2, closing at 4: they touch after (10 − 2)/4 = 2.
    CHECK(billiards::time_of_impact(origin, from<Vector>(1, 0), from<Vector>(10, 0), from<Vector>(-3, 0),
                                    Scalar(2)) == Scalar(2));
  }
  SECTION("moving the other ball instead gives the same time") {
    CHECK(billiards::time_of_impact(from<Vector>(10, 0), from<Vector>(-3, 0), origin, from<Vector>(1, 0),
                                    Scalar(2)) == Scalar(2));
  }
  SECTION("a miss (the line of motion passes farther than the contact distance) never touches") {
    CHECK(billiards::time_of_impact(origin, origin, from<Vector>(10, 3), from<Vector>(-1, 0), Scalar(2)) ==
          infinity);
  }
  SECTION("a graze (the line passes at exactly the contact distance) is no contact") {
    // D = (w·w) r² − |p × w|² = 4 − 4 = 0 exactly.
    CHECK(billiards::time_of_impact(origin, origin, from<Vector>(10, 2), from<Vector>(-1, 0), Scalar(2)) ==
          infinity);
  }
  SECTION("just inside the graze is a contact, where the spheres touch") {
    const Scalar t =
        billiards::time_of_impact(origin, origin, from<Vector>(10, 1.5), from<Vector>(-1, 0), Scalar(2));
    REQUIRE(std::isfinite(t));
    const Vector p = from<Vector>(10, 1.5) + t * from<Vector>(-1, 0);
    CHECK(p.norm() == Approx(2).epsilon(1e-5));
  }
  SECTION("separating spheres never touch") {
    CHECK(billiards::time_of_impact(origin, from<Vector>(-1, 0), from<Vector>(10, 0), origin, Scalar(2)) ==
          infinity);
  }
  SECTION("spheres at rest relative to each other never touch") {
    CHECK(billiards::time_of_impact(origin, from<Vector>(1, 1), from<Vector>(10, 0), from<Vector>(1, 1),
                                    Scalar(2)) == infinity);
  }
  SECTION("touching and approaching: the contact is now") {
    CHECK(billiards::time_of_impact(origin, origin, from<Vector>(2, 0), from<Vector>(-1, 0), Scalar(2)) ==
          Scalar(0));
  }
  SECTION("overlapping by rounding and approaching: now, never a time in the past") {
    const Scalar inside = std::nextafter(Scalar(2), Scalar(0));
    CHECK(billiards::time_of_impact(origin, origin, from<Vector>(inside, 0), from<Vector>(-1, 0),
                                    Scalar(2)) == Scalar(0));
  }
  SECTION("touching and separating (just after a collision): no contact") {
    CHECK(billiards::time_of_impact(origin, origin, from<Vector>(2, 0), from<Vector>(1, 0), Scalar(2)) ==
          infinity);
  }
  SECTION("nearly touching: no cancellation, the tiny gap closes at the relative speed") {
    // A gap of 2^-k of the contact distance (p·p still exact), closing at 1: 2·2^-k to a few ulps. The
    // textbook (−b − √D)/a would cancel and lose about k bits here.
    const Scalar gap = std::ldexp(Scalar(1), std::is_same_v<Scalar, float> ? -8 : -20);
    const Scalar t = billiards::time_of_impact(origin, origin, from<Vector>(2 + 2 * gap, 0),
                                               from<Vector>(-1, 0), Scalar(2));
    CHECK(std::fabs(t - 2 * gap) <= 8 * std::numeric_limits<Scalar>::epsilon() * 2 * gap);
  }
}

TEMPLATE_TEST_CASE("time_of_impact agrees with the textbook quadratic formula", "[runtime][time_of_impact]",
                   (Config<float, 2>), (Config<double, 2>), (Config<float, 3>), (Config<double, 3>)) {
  using Scalar = typename TestType::Scalar;
  using Vector = typename TestType::Vector;
  constexpr int N = TestType::dimension;
  std::mt19937_64 random(20261124);
  std::uniform_real_distribution<double> coordinate(-10, 10), radius(0.25, 3);
  const auto random_vector = [&] {
    Vector v;
    for (int i = 0; i < N; ++i) v[i] = static_cast<Scalar>(coordinate(random));
    return v;
  };
  const long double epsilon = std::numeric_limits<Scalar>::epsilon();
  int contacts = 0, no_contacts = 0;
  for (int sample = 0; sample < 20000; ++sample) {
    const Vector p1 = random_vector(), p2 = random_vector(), v1 = random_vector();
    // Every other sample aimed roughly at the other ball, so that contacts are common.
    const Vector v2 = sample % 2 == 0 ? random_vector() : Vector(v1 - (p2 - p1) / 2 + random_vector() / 10);
    const Scalar r = static_cast<Scalar>(radius(random));
    if ((p2 - p1).norm() <= r) continue;  // overlapping: not a valid configuration
    const long double reference = paper::time_of_impact<N>(exact(p1), exact(v1), exact(p2), exact(v2), r);
    // Near a graze or a standstill the decision and the root are ill-conditioned: skip those.
    const paper::Vector<N> p = exact(p2) - exact(p1), w = exact(v2) - exact(v1);
    const long double a = w.dot(w), b = p.dot(w), c = p.dot(p) - static_cast<long double>(r) * r;
    const long double scale = b * b + a * (p.dot(p) + static_cast<long double>(r) * r);
    if (std::fabs(b * b - a * c) < 1e-3L * scale || std::fabs(b) < 1e-3L * std::sqrt(a * p.dot(p))) continue;
    const Scalar t = billiards::time_of_impact(p1, v1, p2, v2, r);
    INFO("sample " << sample << ": reference " << static_cast<double>(reference) << ", computed " << t);
    if (std::isinf(reference)) {
      CHECK(std::isinf(t));
      ++no_contacts;
      continue;
    }
    REQUIRE(std::isfinite(t));
    // Where it puts the contact: within 64 ε of the distances involved.
    CHECK(std::fabs(t - reference) * std::sqrt(a) <=
          64 * epsilon * (std::sqrt(p.dot(p)) + reference * std::sqrt(a)));
    ++contacts;
  }
  // Both kinds of outcome were exercised.
  CHECK(contacts > 1000);
  CHECK(no_contacts > 1000);
}

TEMPLATE_TEST_CASE("time_of_impact is right at every scale: no miss by underflow or overflow",
                   "[runtime][time_of_impact]", (Config<float, 2>), (Config<double, 2>), (Config<float, 3>),
                   (Config<double, 3>)) {
  using Scalar = typename TestType::Scalar;
  using Vector = typename TestType::Vector;
  constexpr int N = TestType::dimension;
  using limits = std::numeric_limits<Scalar>;
  const Scalar infinity = limits::infinity();
  const Vector origin = Vector::Zero();
  SECTION("extreme scales: a crawl over a gap, overlapping specks") {
    // A relative speed of 1e-161 (1e-20 in float) over a gap of 1.4 − 0.057: a hit, after about 1.3e161.
    const Scalar crawl = std::is_same_v<Scalar, double> ? Scalar(1e-161) : Scalar(1e-20);
    const Scalar t = billiards::time_of_impact(origin, origin, from<Vector>(1.4, 0), from<Vector>(-crawl, 0),
                                               Scalar(0.057));
    const long double expected = (1.4L - static_cast<long double>(Scalar(0.057))) / crawl;
    CHECK(std::fabs(t - expected) <= 4 * limits::epsilon() * expected);
    // Overlapping spheres of radius 2e-170 (2e-25 in float), approaching: they touch now.
    const Scalar speck = std::is_same_v<Scalar, double> ? Scalar(2e-170) : Scalar(2e-25);
    CHECK(billiards::time_of_impact(origin, from<Vector>(1, 0), from<Vector>(speck, 0), origin, 2 * speck) ==
          Scalar(0));
    // A speck crossing a gap of a hundred radii head on at a tiny speed: (100 − 2) r / s.
    const Scalar t2 = billiards::time_of_impact(origin, origin, from<Vector>(100 * speck, 0),
                                                from<Vector>(-crawl, 0), 2 * speck);
    const long double expected2 = 98.0L * speck / crawl;
    CHECK(std::fabs(t2 - expected2) <= 4 * limits::epsilon() * expected2);
    // A time beyond the largest finite number is +infinity; so is a miss at any scale.
    CHECK(billiards::time_of_impact(origin, origin, from<Vector>(1e30, 0), from<Vector>(-limits::min(), 0),
                                    Scalar(1)) == infinity);
    CHECK(billiards::time_of_impact(origin, origin, from<Vector>(10 * speck, 3 * speck),
                                    from<Vector>(-crawl, 0), 2 * speck) == infinity);
  }
  SECTION("random contacts with lengths and speeds scaled over the whole exponent range") {
    std::mt19937_64 random(20261125);
    std::uniform_real_distribution<double> coordinate(-10, 10), radius(0.25, 3);
    // Exponents for lengths and speeds that keep components normal and within the checked API's limit.
    std::uniform_int_distribution<int> exponent(limits::min_exponent + limits::digits + 8,
                                                limits::max_exponent / 2 - 12);
    const auto random_vector = [&] {
      Vector v;
      for (int i = 0; i < N; ++i) v[i] = static_cast<Scalar>(coordinate(random));
      return v;
    };
    const long double epsilon = limits::epsilon();
    int hits = 0, misses = 0;
    for (int sample = 0; sample < 20000; ++sample) {
      const Vector p2 = random_vector(), v1 = random_vector();
      const Vector v2 = sample % 2 == 0 ? random_vector() : Vector(v1 - p2 / 2 + random_vector() / 10);
      Scalar r = static_cast<Scalar>(radius(random));
      const int a = exponent(random), b = exponent(random);
      // Scaled by powers of two, exactly: the true contact time scales by 2^(a − b).
      const Vector q = p2 * std::ldexp(Scalar(1), a), u1 = v1 * std::ldexp(Scalar(1), b),
                   u2 = v2 * std::ldexp(Scalar(1), b);
      r = std::ldexp(r, a);
      const paper::Vector<N> p = exact(q), w = exact(u2) - exact(u1);
      const long double rr = static_cast<long double>(r) * r, aa = w.dot(w), bb = p.dot(w);
      const long double discriminant = bb * bb - aa * (p.dot(p) - rr);
      const long double scale = bb * bb + aa * (p.dot(p) + rr);
      // Near a graze or a standstill the decision is ill-conditioned: skip those.
      if (std::fabs(discriminant) < 1e-3L * scale || std::fabs(bb) < 1e-3L * std::sqrt(aa * p.dot(p)))
        continue;
      const long double reference = paper::time_of_impact<N>(exact(origin), exact(u1), p, exact(u2), r);
      const Scalar t = billiards::time_of_impact(origin, u1, q, u2, r);
      INFO("sample " << sample << ", lengths 2^" << a << ", speeds 2^" << b << ": reference "
                     << static_cast<double>(reference) << ", computed " << t);
      if (std::isinf(reference) || reference > static_cast<long double>(limits::max())) {
        CHECK(std::isinf(t));
        ++misses;
        continue;
      }
      REQUIRE(std::isfinite(t));
      const long double speed = std::sqrt(aa);
      CHECK(std::fabs(t - reference) <=
            64 * epsilon * (std::sqrt(p.dot(p)) / speed + reference) + limits::denorm_min());
      ++hits;
    }
    CHECK(hits > 1000);
    CHECK(misses > 1000);
  }
}

TEMPLATE_TEST_CASE("time_of_impact: centres closer than rounding of the contact distance",
                   "[runtime][time_of_impact]", (Config<float, 3>), (Config<double, 3>)) {
  using Scalar = typename TestType::Scalar;
  using Vector = typename TestType::Vector;
  // Found by the fuzzer: centres 1.2e-34 apart inside spheres of contact distance 2^47, approaching
  // at 8.8e-21. p·w underflows at the contact distance's scale; they overlap and approach: touching now.
  const Vector origin = Vector::Zero(), p2(0, Scalar(1.2461900045309303e-34), 0);
  const Vector v1(0, Scalar(-4.110002118727082e-16), Scalar(9.3132257461547852e-10)),
      v2(0, Scalar(-4.1100897336975636e-16), Scalar(9.3132257461547852e-10));
  const Scalar r = Scalar(140737479966720.0);
  CHECK(billiards::time_of_impact(origin, v1, p2, v2, r) == 0);
  CHECK(billiards::time_of_impact(origin, v2, p2, v1, r) ==
        std::numeric_limits<Scalar>::infinity());  // separating
  CHECK(billiards::checked::time_of_impact(origin, v1, p2, v2, r) == 0);
}

TEMPLATE_TEST_CASE("time_of_impact's fast path has the general path's bits at every scale",
                   "[runtime][time_of_impact]", (Config<float, 2>), (Config<double, 2>), (Config<float, 3>),
                   (Config<double, 3>)) {
  // detail::time_of_impact_scaled builds the scale factors from the exponent fields where every power
  // of two is a normal number and the centres are not negligible, and calls the general path
  // (binary_exponent and times_power_of_two) otherwise; wherever it takes the fast path the bits must
  // be the general path's. Lengths, speeds and the contact distance at independent exponents over the
  // whole range, subnormals and the top binades included (the fast path's edges), and zero vectors.
  using Scalar = typename TestType::Scalar;
  constexpr auto N = static_cast<std::size_t>(TestType::dimension);
  using limits = std::numeric_limits<Scalar>;
  using Bits = billiards::detail::FloatBits<Scalar>;
  std::mt19937_64 random(20261203);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  std::uniform_int_distribution<int> exponent(limits::min_exponent - limits::digits, limits::max_exponent),
      nearby(-80, 80), kind(0, 9);
  const auto scaled_vector = [&](int e) {
    std::array<Scalar, N> v{};
    if (kind(random) == 0) return v;  // a zero vector now and then
    for (Scalar& component : v) component = std::ldexp(static_cast<Scalar>(coordinate(random)), e);
    return v;
  };
  int compared = 0;
  for (int sample = 0; sample < 200000; ++sample) {
    const int length = exponent(random);
    const std::array<Scalar, N> p = scaled_vector(length), w = scaled_vector(exponent(random));
    // The contact distance near the lengths (where contacts happen) or anywhere.
    Scalar r = std::ldexp(Scalar(0.75), kind(random) < 7 ? length + nearby(random) : exponent(random));
    if (!(r > 0) || !std::isfinite(r)) r = limits::min();
    const Scalar fast = billiards::detail::time_of_impact_scaled(p, w, r);
    const Scalar general = billiards::detail::time_of_impact_by_exponents(p, w, r);
    INFO("sample " << sample << ": p[0] = " << p[0] << ", w[0] = " << w[0] << ", r = " << r << ": " << fast
                   << " against " << general);
    REQUIRE(std::bit_cast<Bits>(fast) == std::bit_cast<Bits>(general));
    ++compared;
  }
  CHECK(compared == 200000);
}
