// The event polynomials and billiards::earliest_contact against hand-derived contact times: straight
// approaches, grazes placed exactly, t = 0 by each rule, degrees that drop, a cushion under a phase's
// deceleration, and the checked call's errors. The exact-arithmetic comparison over millions of
// polynomials is billiards-contact-roots (tests/accuracy).
#include <billiards/events.hpp>

#include <Eigen/Core>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <random>

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

TEMPLATE_TEST_CASE("earliest_contact: a graze is a contact exactly where the polynomial reaches 0", "[events]", float,
                   double) {
  using S = TestType;
  // Ball 2 passes ball 1 at a miss distance of exactly D = 2: Δr = (−10, 2), Δv = (1, 0), so
  // |Δr(t)|² − 4 = (t − 10)², a double root at t = 10.
  const std::array<S, 5> c = billiards::contact_polynomial(V2<S>(-10, 2), V2<S>(1, 0), V2<S>(0, 0), S(2));
  CHECK(c[0] == 100);
  CHECK(c[1] == -20);
  CHECK(c[2] == 1);
  CHECK(billiards::earliest_contact(c, S(20)) == S(10));
  // Passing one unit farther out (miss distance 3 > D): no contact.
  const std::array<S, 5> wide = billiards::contact_polynomial(V2<S>(-10, 3), V2<S>(1, 0), V2<S>(0, 0), S(2));
  CHECK_FALSE(billiards::earliest_contact(wide, S(20)));
  // (t − ½)² touches 0 at ½; (t − ½)² + 2ε, whose minimum 2ε lies below its rounding bound 4ε, never does:
  // decided for the coefficients as given, in both directions.
  const S tiny = 2 * std::numeric_limits<S>::epsilon();
  CHECK(billiards::earliest_contact(std::array<S, 3>{S(0.25), -1, 1}, S(1)) == S(0.5));
  CHECK_FALSE(billiards::earliest_contact(std::array<S, 3>{S(0.25) + tiny, -1, 1}, S(1)));
  CHECK_FALSE(billiards::earliest_contact(std::array<S, 3>{S(0.25) + S(0x1p-10), -1, 1}, S(1)));
  // The same graze as a quartic: (t − 1)² (t² + 1) = t⁴ − 2t³ + 2t² − 2t + 1.
  CHECK(billiards::earliest_contact(std::array<S, 5>{1, -2, 2, -2, 1}, S(3)) == S(1));
  // A graze at an irrational time: (t² − 2)² = t⁴ − 4t² + 4 touches 0 at √2 only. The contact is the
  // largest value of the type at or below √2 (√2 rounded, less one ulp where it rounded up: s² > 2 by
  // a fused multiply-add, exact in its sign).
  const S root = std::sqrt(S(2));
  const S below = std::fma(root, root, S(-2)) > 0 ? std::nextafter(root, S(0)) : root;
  CHECK(billiards::earliest_contact(std::array<S, 5>{4, 0, -4, 0, 1}, S(3)) == below);
  // Lifted by the smallest step of the type at 4 it misses, however far inside its rounding that is;
  // lowered by one, it crosses 0 twice, first before √2.
  const S lifted = std::nextafter(S(4), S(5)), lowered = std::nextafter(S(4), S(3));
  CHECK_FALSE(billiards::earliest_contact(std::array<S, 5>{lifted, 0, -4, 0, 1}, S(3)));
  const std::optional<S> crossing = billiards::earliest_contact(std::array<S, 5>{lowered, 0, -4, 0, 1}, S(3));
  REQUIRE(crossing);
  CHECK(*crossing < below);
  CHECK(*crossing > S(1.41));
}

TEST_CASE("earliest_contact: a near miss far into a long window is no contact", "[events]") {
  // Two balls of radius R = 0.028575 m, one accelerating away along x at a = 1/8 m/s² from 1/64 m/s,
  // whose centres pass 7e-8 R outside contact (and, the other way, inside it) at t = 80 s: Δr(t) =
  // (f(t), D ± 7e-8 R) with f(t) = s (t − 80) + ½ a (t² − 80²), so that p = f² + (D ± 7e-8 R)² − D².
  // Every coefficient but c0 is exact and c0 is off by less than 1e-10 m², so the exact minimum keeps
  // the sign of (D ± 7e-8 R)² − D² (about ±2.3e-10 m²); the rounding bound of p near t = 80 s is about
  // 1e-9 m², which the rule of a graze within rounding called a contact.
  const double R = 0.028575, D = 2 * R, s = 1.0 / 64, a = 1.0 / 8, t1 = 80;
  for (const double miss : {7e-8 * R, -7e-8 * R}) {
    const Eigen::Vector2d dr(-(s * t1 + a * t1 * t1 / 2), D + miss), dv(s, 0), da(a, 0);
    const std::array<double, 5> c = billiards::contact_polynomial<double>(dr, dv, da, D);
    const std::optional<double> t = billiards::earliest_contact(c, 100.0);
    if (miss > 0) {
      CHECK_FALSE(t);
    } else {
      // The first of the two roots: f(t) = −h, h = √(D² − (D + miss)²), a quadratic in t.
      REQUIRE(t);
      const long double h = std::sqrt((long double)D * D - ((long double)D + miss) * ((long double)D + miss));
      const long double constant = s * t1 + a * t1 * t1 / 2 - h;
      const long double root = (-s + std::sqrt((long double)s * s + 2 * a * constant)) / a;
      CHECK(std::fabs(*t - (double)root) < 1e-9 * t1);
    }
  }
}

TEMPLATE_TEST_CASE("earliest_contact: a root within rounding of the horizon is decided exactly", "[events]",
                   float, double) {
  using S = TestType;
  // (r − t)(t² + 1), falling through its one root r: a horizon a few ulps past r finds it, at r to rounding
  // or at the horizon where p evaluates within rounding of 0 there.
  const S r = S(3.1);
  const std::array<S, 4> c{r, -1, r, -1};
  const S horizon = r + 4 * std::numeric_limits<S>::epsilon() * r;
  // p(r) is 0 exactly (r is the type's own value): the contact is r itself, exactly.
  CHECK(billiards::earliest_contact(c, horizon) == r);
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
  // Touching and separating, then grazing at t = 1: t (t − 1)² = t³ − 2t² + t, a contact at 1 exactly
  // (p / t touches 0 there: no proof of staying apart may pass over it).
  const std::optional<S> graze = billiards::earliest_contact(std::array<S, 5>{0, 1, -2, 1, 0}, S(2));
  REQUIRE(graze);
  CHECK(ulps(*graze, S(1)) <= 16);
  // Missing that graze by 2^-20 (t ((t − 1)² + 2^-20): p / t above 0 throughout) is no contact; touching
  // again by as much (t ((t − 1)² − 2^-20)) is one, 2^-10 before t = 1.
  const S miss = std::ldexp(S(1), -20);
  CHECK_FALSE(billiards::earliest_contact(std::array<S, 5>{0, 1 + miss, -2, 1, 0}, S(2)));
  const std::optional<S> touch = billiards::earliest_contact(std::array<S, 5>{0, 1 - miss, -2, 1, 0}, S(2));
  REQUIRE(touch);
  CHECK(ulps(*touch, 1 - std::ldexp(S(1), -10)) <= 16);
}

// The test of no contact by the terms (c0 less every negative term at the horizon) keeps a margin above
// its rounding: for these falling quadratics, found in exact rational arithmetic, the terms as rounded
// sum to just above 0 at the horizon (5.6e-17, 1.1e-16, 4.4e-16) where the exact polynomial is at or
// below 0 (−3.5e-16, −1.0e-16, −3.9e-17): a contact by the horizon, for bodies apart at 0 and, over t,
// for bodies touching at 0 and separating.
TEST_CASE("earliest_contact: terms above 0 by less than their rounding prove nothing", "[events]") {
  const std::array<std::array<double, 4>, 3> cases{{{6.000191610392548, 7.105993908980331, 0.7536222604556637,
                                                     0.7798807685392913},
                                                    {6.7059375522575575, 8.660507776153864, 1.1010154034886839,
                                                     0.7101912300132364},
                                                    {7.4332100207262375, 3.643141761225411, 1.0078645239637576,
                                                     1.4548120945688918}}};
  for (const auto& [a, b, c, horizon] : cases) {
    INFO("a = " << a << ", b = " << b << ", c = " << c << ", horizon " << horizon);
    const std::optional<double> apart = billiards::earliest_contact(std::array<double, 3>{a, -b, -c}, horizon);
    REQUIRE(apart);
    CHECK(ulps(*apart, horizon) <= 16);
    const std::optional<double> touching =
        billiards::earliest_contact(std::array<double, 4>{0, a, -b, -c}, horizon);
    REQUIRE(touching);
    CHECK(ulps(*touching, horizon) <= 16);
  }
}

TEMPLATE_TEST_CASE("detail::separates_for_good: touching and separating, apart to the horizon", "[events]", float,
                   double) {
  using S = TestType;
  using billiards::detail::EventPolynomial, billiards::detail::separates_for_good;
  // p / t = 1 + t: its terms alone show it above 0.
  CHECK(separates_for_good(EventPolynomial<S>{{0, 1, 1, 0, 0}, 2}, S(10)));
  // p / t = (1 − t)²: above 0 on [0, 1/2] (at least 1/4) by its Bernstein coefficients, not by its terms
  // (1 − 2 · 1/2 = 0); touching 0 at t = 1 within [0, 2].
  CHECK(separates_for_good(EventPolynomial<S>{{0, 1, -2, 1, 0}, 3}, S(0.5)));
  CHECK_FALSE(separates_for_good(EventPolynomial<S>{{0, 1, -2, 1, 0}, 3}, S(2)));
  // Not touching (apart, or overlapping), not separating, or no window: not this proof's to give.
  CHECK_FALSE(separates_for_good(EventPolynomial<S>{{S(1e-3), 1, 1, 0, 0}, 2}, S(1)));
  CHECK_FALSE(separates_for_good(EventPolynomial<S>{{S(-1e-3), 1, 1, 0, 0}, 2}, S(1)));
  CHECK_FALSE(separates_for_good(EventPolynomial<S>{{0, 0, 1, 0, 0}, 2}, S(1)));
  CHECK_FALSE(separates_for_good(EventPolynomial<S>{{0, 1, 1, 0, 0}, 2}, S(0)));
}

TEMPLATE_TEST_CASE("earliest_contact: a root below the smallest step of the type is reported at that step",
                   "[events]", float, double) {
  using S = TestType;
  // c0 the smallest subnormal, falling at 27.6 a second: the root, near 1.8e-325 s in double, lies below
  // the smallest positive value. Apart at t = 0, the bodies meet at the first step after it, never at
  // t = 0 (whether the horizon keeps p finite or, at the largest finite value, overflows it).
  const S tiny = std::numeric_limits<S>::denorm_min();
  for (const S horizon : {S(1), std::numeric_limits<S>::max()}) {
    const std::optional<S> t = billiards::earliest_contact(std::array<S, 2>{tiny, S(-27.6)}, horizon);
    REQUIRE(t);
    CHECK(*t == tiny);
  }
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

TEMPLATE_TEST_CASE("sign_change: a quadratic's root closed on in closed form keeps p above 0 as evaluated",
                   "[events]", float, double) {
  using S = TestType;
  // Balls decelerating toward a cushion from 0.05 to 2 m away at 0.5 to 6 m/s (the cushion polynomial):
  // the root the search returns is where p, as evaluated, still has its sign at the bracket's left end,
  // a value or two before the exact root (the quadratic formula in long double).
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  int checked = 0;
  for (int k = 0; k < 2000; ++k) {
    const S radius = S(0.028575), gap = S(0.05 + 2 * unit(random)), speed = S(-0.5 - 5.5 * unit(random));
    const S acceleration = S(0.1 + 2 * unit(random));
    const std::array<S, 3> c = billiards::cushion_polynomial(gap, speed, acceleration, radius);
    const long double a = c[2], b = c[1], q = c[0], disc = b * b - 4 * a * q;
    if (disc <= 0) continue;
    const long double root = (-b - std::sqrt(disc)) / (2 * a);
    const billiards::detail::EventPolynomial<S> p{{c[0], c[1], c[2], 0, 0}, 2};
    const S vertex = -c[1] / (2 * c[2]);
    const S t = billiards::detail::sign_change(p, billiards::detail::derivative(p), S(0), vertex, c[0],
                                               billiards::detail::evaluate(p, vertex));
    if (!(billiards::detail::evaluate(p, vertex) < 0)) continue;
    ++checked;
    CHECK(billiards::detail::evaluate(p, t) > 0);
    CHECK(std::fabs((long double)t - root) <= 16 * (long double)std::numeric_limits<S>::epsilon() * root);
  }
  CHECK(checked > 1500);
}

TEMPLATE_TEST_CASE("earliest_contact: a ball approaching a cushion has its root placed exactly from the closed form",
                   "[events]", float, double) {
  using S = TestType;
  // Balls decelerating toward a cushion, or pushed towards it, from 0.05 to 2 m away at 0.5 to 6 m/s:
  // where the closed form lands within a value of the root, earliest_contact returns the root placed
  // exactly — the last value of the type before the root of the coefficients exactly as given, as exact
  // arithmetic (dyadic rationals) finds it — and it does so for almost every such ball.
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0, 1);
  int contacts = 0, placed = 0;
  for (int k = 0; k < 4000; ++k) {
    const S radius = S(0.028575), gap = S(0.05 + 2 * unit(random)), speed = S(-0.5 - 5.5 * unit(random));
    const S acceleration = S(k % 4 == 0 ? -0.5 * unit(random) : 0.1 + 2 * unit(random));
    const S horizon = S(0.1 + 4 * unit(random));
    const std::array<S, 3> c = billiards::cushion_polynomial(gap, speed, acceleration, radius);
    const std::optional<S> t = billiards::earliest_contact(c, horizon);
    const billiards::detail::EventPolynomial<S> p{{c[0], c[1], c[2], 0, 0}, 2};
    const S fast = billiards::detail::placed_quadratic_root(p, horizon);
    if (!t) {
      CHECK(std::isnan(fast));
      continue;
    }
    ++contacts;
    if (std::isnan(fast)) continue;
    ++placed;
    CHECK(*t == fast);
    const std::array<S, 5> exact{c[0], c[1], c[2], 0, 0};
    CHECK(billiards::detail::exact::sign_of_polynomial(exact, *t) > 0);
    CHECK(billiards::detail::exact::sign_of_polynomial(exact, std::nextafter(*t, horizon)) < 0);
  }
  CHECK(contacts > 1000);
  CHECK(placed > contacts * 9 / 10);
}

TEST_CASE("earliest_contact: a quadratic whose rounding band spans many values of the type ends at once",
          "[events]") {
  // p = 2 d − 1.35e5 t² with d the smallest subnormal (found by the fuzzer): its root, near 2^-546, lies
  // in a closed bracket 2^22 times as wide as itself, too wide for steps of one value from the closed
  // form; the type's search finishes it, within a few ulps of the exact root.
  const double d = std::numeric_limits<double>::denorm_min();
  const std::array<double, 3> c{2 * d, 0, -0x1.4b4b4b4b4b4b5p+17};
  const std::optional<double> t = billiards::earliest_contact(c, 1.0);
  REQUIRE(t);
  const long double root = std::sqrt(2.0L * d / 0x1.4b4b4b4b4b4b5p+17L);
  CHECK(*t > 0);
  CHECK(std::fabs(*t - root) <= 4 * std::numeric_limits<double>::epsilon() * root);
}
