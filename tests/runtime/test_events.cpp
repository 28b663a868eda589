// The event polynomials and billiards::earliest_contact against hand-derived contact times: straight
// approaches, grazes placed exactly, t = 0 by each rule, degrees that drop, a cushion under a phase's
// deceleration, and the checked call's errors. The exact-arithmetic comparison over millions of
// polynomials is billiards-contact-roots (tests/accuracy).
#include <billiards/events.hpp>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace {

template <typename Scalar>
using V2 = Eigen::Matrix<Scalar, 2, 1>;

template <typename Scalar>
Scalar ulps(Scalar x, Scalar reference) {
  return std::fabs(x - reference) / (std::numeric_limits<Scalar>::epsilon() * std::fabs(reference));
}

}  // namespace

TEMPLATE_TEST_CASE("contact_polynomial is |Δr + Δv t + ½ Δa t²|² − D² at any t", "[events]", float, double) {
  using S = TestType;
  const V2<S> dr(S(-1.5), S(0.25)), dv(S(2), S(-0.5)), da(S(-0.75), S(0.5));
  const S distance = S(0.125);
  const std::array<S, 5> c = billiards::contact_polynomial(dr, dv, da, distance);
  for (const double t : {0.0, 0.5, 1.0, 2.0, 3.5}) {
    const V2<double> gap = dr.template cast<double>() + t * dv.template cast<double>() +
                           0.5 * t * t * da.template cast<double>();
    const double expected = gap.squaredNorm() - double(distance) * double(distance);
    const double value = double(c[0]) + t * (double(c[1]) + t * (double(c[2]) + t * (double(c[3]) + t * double(c[4]))));
    CHECK(std::fabs(value - expected) <= 64 * std::numeric_limits<S>::epsilon() * (1 + std::fabs(expected)) * 16);
  }
  // Equal accelerations: c4 = c3 = 0 exactly, a quadratic.
  const std::array<S, 5> same = billiards::contact_polynomial(dr, dv, V2<S>(0, 0), distance);
  CHECK(same[3] == 0);
  CHECK(same[4] == 0);
}

TEMPLATE_TEST_CASE("earliest_contact: two balls closing head on at constant speeds", "[events]", float, double) {
  using S = TestType;
  // Centres 1 apart along x, closing at 0.25: they touch (D = 0.125) at t = (1 − 0.125)/0.25 = 3.5.
  const std::array<S, 5> c = billiards::contact_polynomial(V2<S>(1, 0), V2<S>(S(-0.25), 0), V2<S>(0, 0), S(0.125));
  const std::optional<S> t = billiards::earliest_contact(c, S(10));
  REQUIRE(t);
  CHECK(ulps(*t, S(3.5)) <= 4);
  CHECK(*t <= S(3.5));  // never after the overlap begins
  // The horizon ends before the contact: none.
  CHECK_FALSE(billiards::earliest_contact(c, S(3.25)));
  // Moving apart: none.
  const std::array<S, 5> apart = billiards::contact_polynomial(V2<S>(1, 0), V2<S>(S(0.25), 0), V2<S>(0, 0), S(0.125));
  CHECK_FALSE(billiards::earliest_contact(apart, S(100)));
}

TEMPLATE_TEST_CASE("earliest_contact: a graze placed exactly is a contact", "[events]", float, double) {
  using S = TestType;
  // Ball 2 passes ball 1 at a miss distance of exactly D = 2: Δr = (−10, 2), Δv = (1, 0), so
  // |Δr(t)|² − 4 = (t − 10)², a double root at t = 10.
  const std::array<S, 5> c = billiards::contact_polynomial(V2<S>(-10, 2), V2<S>(1, 0), V2<S>(0, 0), S(2));
  CHECK(c[0] == 100);
  CHECK(c[1] == -20);
  CHECK(c[2] == 1);
  const std::optional<S> t = billiards::earliest_contact(c, S(20));
  REQUIRE(t);
  CHECK(std::fabs(*t - S(10)) <= S(10) * std::sqrt(std::numeric_limits<S>::epsilon()) * 8);
  // Passing one unit farther out (miss distance 3 > D): no contact.
  const std::array<S, 5> wide = billiards::contact_polynomial(V2<S>(-10, 3), V2<S>(1, 0), V2<S>(0, 0), S(2));
  CHECK_FALSE(billiards::earliest_contact(wide, S(20)));
  // A miss by less than the rounding of p: (t − ½)² + 2ε, its minimum 2ε at t = ½ evaluated exactly and
  // below the bound 4ε: reported as the graze it may be. A miss by 2^−10 is not.
  const S tiny = 2 * std::numeric_limits<S>::epsilon();
  const std::optional<S> close = billiards::earliest_contact(std::array<S, 3>{S(0.25) + tiny, -1, 1}, S(1));
  REQUIRE(close);
  CHECK(*close == S(0.5));
  CHECK_FALSE(billiards::earliest_contact(std::array<S, 3>{S(0.25) + S(0x1p-10), -1, 1}, S(1)));
  // The same graze as a quartic: (t − 1)² (t² + 1) = t⁴ − 2t³ + 2t² − 2t + 1.
  const std::array<S, 5> quartic{1, -2, 2, -2, 1};
  const std::optional<S> q = billiards::earliest_contact(quartic, S(3));
  REQUIRE(q);
  CHECK(std::fabs(*q - 1) <= std::sqrt(std::numeric_limits<S>::epsilon()) * 8);
}

TEMPLATE_TEST_CASE("earliest_contact: a polynomial within rounding of 0 at the horizon is a contact there", "[events]",
                   float, double) {
  using S = TestType;
  // (r − t)(t² + 1), falling through its one root r: a horizon a few ulps past r finds it, at r to rounding
  // or at the horizon where p evaluates within rounding of 0 there.
  const S r = S(3.1);
  const std::array<S, 4> c{r, -1, r, -1};
  const S horizon = r + 4 * std::numeric_limits<S>::epsilon() * r;
  const std::optional<S> t = billiards::earliest_contact(c, horizon);
  REQUIRE(t);
  CHECK(*t <= horizon);
  CHECK(std::fabs(*t - r) <= 8 * std::numeric_limits<S>::epsilon() * r);
  // The polynomial in float at the horizon of a cubic with three roots 3.41 ± 0.05 apart, where float
  // reads p(T) above 0 though the exact root lies just before T.
  if constexpr (std::is_same_v<S, float>) {
    const std::optional<S> cluster =
        billiards::earliest_contact(std::array<S, 5>{-39.591404f, 34.8572273f, -10.2272329f, 1, 0}, 3.45775008f);
    REQUIRE(cluster);
    CHECK(*cluster > 3.45f);
  }
}

TEMPLATE_TEST_CASE("earliest_contact at t = 0: touching or overlapping, approaching or not", "[events]", float, double) {
  using S = TestType;
  // Touching and approaching: a contact now.
  CHECK(billiards::earliest_contact(std::array<S, 5>{0, -1, 1, 0, 0}, S(1)) == S(0));
  // Overlapping and approaching.
  CHECK(billiards::earliest_contact(std::array<S, 5>{S(-0.5), -1, 0, 0, 0}, S(1)) == S(0));
  // Touching and separating: none, ever (the parabola only grows).
  CHECK_FALSE(billiards::earliest_contact(std::array<S, 5>{0, 1, 1, 0, 0}, S(10)));
  // Exact tangency, moving apart at second order (c1 = 0, c2 > 0): none.
  CHECK_FALSE(billiards::earliest_contact(std::array<S, 5>{0, 0, 1, 0, 0}, S(10)));
  // Exact tangency, approaching at second order (c1 = 0, c2 < 0): a contact now.
  CHECK(billiards::earliest_contact(std::array<S, 5>{0, 0, -1, 0, 1}, S(10)) == S(0));
  // Touching and separating, then closing again: t (t − 1)(t − 2) = t³ − 3t² + 2t is apart on (0, 1)
  // and touches again at t = 1, from above.
  const std::optional<S> back = billiards::earliest_contact(std::array<S, 5>{0, 2, -3, 1, 0}, S(5));
  REQUIRE(back);
  CHECK(ulps(*back, S(1)) <= 16);
  CHECK(*back > 0);
}

TEMPLATE_TEST_CASE("earliest_contact: the degree is what the coefficients make it", "[events]", float, double) {
  using S = TestType;
  // Linear: 1 − 4t, root ¼.
  const std::optional<S> linear = billiards::earliest_contact(std::array<S, 5>{1, -4, 0, 0, 0}, S(1));
  REQUIRE(linear);
  CHECK(ulps(*linear, S(0.25)) <= 4);
  // A constant never changes.
  CHECK_FALSE(billiards::earliest_contact(std::array<S, 5>{1, 0, 0, 0, 0}, S(1)));
  CHECK_FALSE(billiards::earliest_contact(std::array<S, 5>{-1, 0, 0, 0, 0}, S(1)));
  // A quartic whose leading coefficient is far below the others: (1 − 4t) + 2^−60 t⁴ still meets 0 at ¼.
  const std::optional<S> nearly = billiards::earliest_contact(std::array<S, 5>{1, -4, 0, 0, S(0x1p-60)}, S(1));
  REQUIRE(nearly);
  CHECK(ulps(*nearly, S(0.25)) <= 8);
  // Arrays of fewer coefficients: a cushion's quadratic.
  const std::optional<S> q = billiards::earliest_contact(std::array<S, 3>{S(0.75), -1, 0}, S(2));
  REQUIRE(q);
  CHECK(ulps(*q, S(0.75)) <= 4);
  // Roots many decades apart: (t − 1e−6)(t − 1)(t − 2)(t − 3), the first at 1e−6.
  const double r = 1e-6;
  const std::array<S, 5> spread{S(6 * r), S(-(11 * r + 6)), S(6 * r + 11), S(-(r + 6)), 1};
  const std::optional<S> first = billiards::earliest_contact(spread, S(4));
  REQUIRE(first);
  CHECK(std::fabs(double(*first) - r) <= r * 1e-3);
}

TEMPLATE_TEST_CASE("earliest_contact: a ball decelerating toward a cushion", "[events]", float, double) {
  using S = TestType;
  // Sliding at 2 m/s toward the cushion, decelerating at μ_s g = 1.962 m/s², 0.5 m from the line, R =
  // 0.028575: s0 − R + v_n t + ½ a_n t² with v_n = −2, a_n = +1.962 (the deceleration points away from the
  // cushion). Its smaller root, from the quadratic formula in long double.
  const S radius = S(0.028575), gap = S(0.5), speed = S(-2), acceleration = S(1.962);
  const std::array<S, 3> c = billiards::cushion_polynomial(gap, speed, acceleration, radius);
  const long double a = 0.5L * acceleration, b = speed, k = (long double)gap - radius;
  const long double expected = (-b - std::sqrt(b * b - 4 * a * k)) / (2 * a);
  const std::optional<S> t = billiards::earliest_contact(c, S(5));
  REQUIRE(t);
  CHECK(std::fabs(*t - S(expected)) <= 16 * std::numeric_limits<S>::epsilon() * S(expected));
  // At 1 m/s it stops after v²/(2a) = 0.255 m, short of the cushion 0.471 m away: none.
  const std::array<S, 3> slow = billiards::cushion_polynomial(gap, S(-1), acceleration, radius);
  CHECK_FALSE(billiards::earliest_contact(slow, S(5)));
}

TEMPLATE_TEST_CASE("checked::earliest_contact names the argument it rejects", "[events][checked]", float, double) {
  using S = TestType;
  const S nan = std::numeric_limits<S>::quiet_NaN(), inf = std::numeric_limits<S>::infinity();
  CHECK_THROWS_WITH(billiards::checked::earliest_contact(std::array<S, 5>{1, nan, 0, 0, 0}, S(1)),
                    Catch::Contains("billiards::checked::earliest_contact: c[1] is nan, expected a finite coefficient"));
  CHECK_THROWS_WITH(billiards::checked::earliest_contact(std::array<S, 3>{1, -1, inf}, S(1)),
                    Catch::Contains("c[2] is inf"));
  CHECK_THROWS_WITH(billiards::checked::earliest_contact(std::array<S, 3>{1, -1, 0}, S(-1)),
                    Catch::Contains("horizon is -1, expected a time >= 0, finite"));
  CHECK_THROWS_WITH(billiards::checked::earliest_contact(std::array<S, 3>{1, -1, 0}, inf),
                    Catch::Contains("horizon is inf"));
  CHECK(billiards::checked::earliest_contact(std::array<S, 3>{1, -1, 0}, S(2)) ==
        billiards::earliest_contact(std::array<S, 3>{1, -1, 0}, S(2)));
}
