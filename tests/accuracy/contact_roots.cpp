// billiards-contact-roots: billiards::earliest_contact against exact root isolation. Each polynomial's
// coefficients (float or double) are converted exactly to rationals; its roots in (0, T] are isolated
// with a Sturm sequence in exact rational arithmetic (GiNaC's CLN numbers) and the first one reached
// from above found exactly, then compared with what earliest_contact returns in double and float.
//
// Usage: billiards-contact-roots [--polynomials N (1 to 10^7, default 20000)] [--seed S]
//   prints a Markdown table per family of polynomials: how many, how many contacts, misses (an exact
//   contact in [0, T] that the finder does not report, or reports where the exact polynomial is below
//   minus its rounding bound), false contacts (reported where the polynomial does not reach 0, or
//   more than 18 ulps before it does), wrong roots (a time more than 18 ulps after the exact root: the
//   finder places a root in the type within 16 ulps by its rounding bound, or else exactly), wrong calls at
//   t = 0, how many the finder's Bernstein bound proved apart (detail::stays_above) and how many of those
//   unsoundly (the exact p within 16 ε Σ |c_k| T^k of 0 somewhere on [0, T]), and the worst error of the
//   time, relative and in ulps. Exit status 0 when there is no miss, no false contact, no wrong root, no
//   wrong call at t = 0 and no unsound proof; 1 otherwise; 2 on a usage error.
#include "exact.hpp"

#include <billiards/events.hpp>

#include <CLI/CLI.hpp>
#include <billiards_support/cli_checks.hpp>
#include <ginac/ginac.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace {

using GiNaC::numeric;
using Rational = std::vector<numeric>;  // coefficients by power, trimmed

Rational trimmed(Rational p) {
  while (!p.empty() && p.back().is_zero()) p.pop_back();
  return p;
}

numeric evaluate(const Rational& p, const numeric& t) {
  numeric r = 0;
  for (std::size_t k = p.size(); k-- > 0;) r = r * t + p[k];
  return r;
}

Rational derivative(const Rational& p) {
  Rational d;
  for (std::size_t k = 1; k < p.size(); ++k) d.push_back(numeric(static_cast<int>(k)) * p[k]);
  return trimmed(d);
}

// The remainder of a divided by b (b not zero).
Rational remainder(Rational a, const Rational& b) {
  while (a.size() >= b.size() && !a.empty()) {
    const numeric factor = a.back() / b.back();
    const std::size_t shift = a.size() - b.size();
    for (std::size_t k = 0; k < b.size(); ++k) a[k + shift] -= factor * b[k];
    a.pop_back();
    a = trimmed(a);
  }
  return a;
}

// The Sturm sequence p, p', −rem(p, p'), …
std::vector<Rational> sturm(const Rational& p) {
  std::vector<Rational> sequence{p, derivative(p)};
  while (!sequence.back().empty()) {
    Rational next = remainder(sequence[sequence.size() - 2], sequence.back());
    for (numeric& c : next) c = -c;
    if (next.empty()) break;
    sequence.push_back(next);
  }
  if (sequence.back().empty()) sequence.pop_back();
  return sequence;
}

int variations(const std::vector<Rational>& sequence, const numeric& t) {
  int count = 0, last = 0;
  for (const Rational& q : sequence) {
    const numeric v = evaluate(q, t);
    const int sign = v.is_zero() ? 0 : (v > 0 ? 1 : -1);
    if (sign == 0) continue;
    if (last != 0 && sign != last) ++count;
    last = sign;
  }
  return count;
}

// Distinct roots in (a, b], a not a root.
int roots_in(const std::vector<Rational>& sequence, const numeric& a, const numeric& b) {
  return variations(sequence, a) - variations(sequence, b);
}

// The exact earliest contact: t = 0 by the rule of earliest_contact, else the first root in (0, T]
// reached from above. Returned as an interval [low, high] of relative width below 2^-64 (or a point).
struct ExactContact {
  bool found = false;
  numeric low, high;
};

ExactContact exact_earliest(Rational p, const numeric& horizon) {
  p = trimmed(p);
  if (p.size() < 2) return {};
  if (p[0] <= 0) {
    for (std::size_t k = 1; k < p.size(); ++k) {
      if (!p[k].is_zero()) {
        if (p[k] < 0) return {true, 0, 0};
        break;
      }
    }
  }
  if (horizon <= 0) return {};
  // Roots at 0 divided out: the roots in (0, T] are q's, q(0) ≠ 0, and q has p's sign for t > 0.
  Rational q = p;
  while (q.size() > 1 && q[0].is_zero()) q.erase(q.begin());
  if (q.size() < 2) return {};
  const std::vector<Rational> sequence = sturm(q);
  const numeric fine = numeric(1) / numeric(2).power(64);
  numeric lo = 0;  // q(lo) ≠ 0, and every root in (0, lo] is no contact
  while (roots_in(sequence, lo, horizon) > 0) {
    // The leftmost root in (lo, T], isolated in (l, h]: one root there, none in (lo, l], q(l) ≠ 0.
    numeric l = lo, h = horizon;
    while (!(roots_in(sequence, l, h) == 1 && (evaluate(q, h).is_zero() || h - l <= h * fine))) {
      const numeric mid = (l + h) / 2;
      if (evaluate(q, mid).is_zero() && roots_in(sequence, l, mid) == 1) {
        h = mid;  // the root itself
        break;
      }
      if (roots_in(sequence, l, mid) >= 1) {
        h = mid;
      } else {
        l = mid;
      }
    }
    // Reached from above: q > 0 just before it. A root found exactly (q(h) = 0: a root at the horizon,
    // or at a point of the bisection) is the point h.
    if (evaluate(q, l) > 0) return evaluate(q, h).is_zero() ? ExactContact{true, h, h} : ExactContact{true, l, h};
    // No contact: continue after it, from a point where q is not zero and no other root lies between.
    numeric next = h;
    if (evaluate(q, h).is_zero()) {
      next = horizon;
      while (next > h && (evaluate(q, next).is_zero() || roots_in(sequence, l, next) > 1)) next = (h + next) / 2;
      if (next == h || roots_in(sequence, l, next) > 1) return {};
    }
    if (next >= horizon) return {};
    lo = next;
  }
  return {};
}

struct Row {
  long polynomials = 0, contacts = 0, misses = 0, false_contacts = 0, wrong_roots = 0, wrong_at_zero = 0;
  long proven_apart = 0, unsound_proofs = 0;
  double worst = 0, worst_ulps = 0;
  std::string first_failure;
};

template <typename Scalar>
std::string describe(const std::array<Scalar, 5>& c, Scalar horizon) {
  std::string text = "c = (";
  for (std::size_t k = 0; k < 5; ++k) text += (k ? ", " : "") + billiards::detail::to_text(c[k]);
  return text + "), T = " + billiards::detail::to_text(horizon);
}

// Whether the exact p stays above `multiple` ε Σ |c_k| T^k on [0, T], as detail::stays_above claims
// (16) where it holds: p less that bound is positive at 0 and has no root in (0, T] (its Sturm sequence).
template <typename Scalar>
bool exceeds_rounding_bound(const Rational& p, Scalar horizon, int multiple = 16) {
  const numeric T = billiards::accuracy::exact_rational(horizon);
  numeric size = 0, power = 1;
  for (const numeric& c : p) {
    size += GiNaC::abs(c) * power;
    power *= T;
  }
  Rational q = p;
  q[0] -= multiple * billiards::accuracy::exact_rational(std::numeric_limits<Scalar>::epsilon()) * size;
  q = trimmed(q);
  if (q.empty() || !(q[0] > 0)) return false;
  return q.size() < 2 || roots_in(sturm(q), 0, T) == 0;
}

template <typename Scalar>
void check(const std::array<Scalar, 5>& c, Scalar horizon, Row& row) {
  Rational p;
  for (Scalar coefficient : c) p.push_back(billiards::accuracy::exact_rational(coefficient));
  const ExactContact exact = exact_earliest(p, billiards::accuracy::exact_rational(horizon));
  const std::optional<Scalar> found = billiards::earliest_contact(c, horizon);
  ++row.polynomials;
  const auto fail = [&](long& counter, const std::string& what) {
    ++counter;
    if (row.first_failure.empty()) row.first_failure = what + ": " + describe(c, horizon);
  };
  // The polynomial as earliest_contact holds it, for its rounding bound (detail::evaluation_error) and
  // its proof of staying apart (detail::stays_above, applied wherever earliest_contact may apply it).
  billiards::detail::EventPolynomial<Scalar> as_held;
  for (std::size_t k = 0; k < 5; ++k) as_held.c[k] = c[k];
  as_held.degree = 4;
  as_held = billiards::detail::trimmed(as_held);
  if (as_held.c[0] > 0 && as_held.degree >= 2 && horizon > 0 && billiards::detail::stays_above(as_held, horizon)) {
    ++row.proven_apart;
    if (!exceeds_rounding_bound(trimmed(p), horizon))
      fail(row.unsound_proofs, "proven apart by its Bernstein coefficients, but within 16 ε Σ|c_k| T^k of 0");
  }
  // Touching at 0 and separating, proven apart on (0, T] by p / t (detail::separates_for_good): the
  // exact p / t positive on all of [0, T].
  if (billiards::detail::separates_for_good(as_held, horizon)) {
    ++row.proven_apart;
    const Rational held = trimmed(p), over_t(held.begin() + 1, held.end());
    if (!exceeds_rounding_bound(over_t, horizon, 0))
      fail(row.unsound_proofs, "touching and separating, proven apart, but p / t reaches 0 on [0, T]");
  }
  if (exact.found) ++row.contacts;
  if (exact.found && exact.low.is_zero() && exact.high.is_zero()) {
    if (!found || *found != 0) fail(row.wrong_at_zero, "a contact at t = 0 not reported");
    return;
  }
  if (found && *found == 0) {
    fail(row.wrong_at_zero, "a contact at t = 0 reported where there is none");
    return;
  }
  if (exact.found && !found) {
    fail(row.misses, "a contact missed");
    return;
  }
  if (!exact.found && found) {
    fail(row.false_contacts, "a contact reported where the polynomial does not reach 0");
    return;
  }
  if (!exact.found) return;
  const Rational trimmed_p = trimmed(p);
  const numeric t = billiards::accuracy::exact_rational(*found);
  // Before the exact contact, p is positive at t: a time within the root's condition (below) is the
  // contact found early by rounding; farther, a contact where there is none (yet).
  // After it, p at t below minus its rounding bound: the bodies overlap there, a miss.
  const numeric rounding = billiards::accuracy::exact_rational(billiards::detail::evaluation_error(as_held, *found));
  if (t > exact.high && evaluate(trimmed_p, t) < -rounding) {
    fail(row.misses, "a contact reported later than it is");
    return;
  }
  // The time's error: within 16 ulps of the root (what earliest_contact places in the type; it places the
  // rest exactly), beyond the width of the exact root's interval.
  const numeric middle = (exact.low + exact.high) / 2;
  const numeric error = GiNaC::abs(t - middle);
  const numeric ulp = billiards::accuracy::exact_rational(
      std::nextafter(*found, std::numeric_limits<Scalar>::infinity()) - *found);
  if (error > 18 * ulp + (exact.high - exact.low)) {
    fail(t < exact.low ? row.false_contacts : row.wrong_roots,
         t < exact.low ? "a contact reported more than 18 ulps before the polynomial reaches 0"
                       : "a contact time more than 18 ulps from the root");
    return;
  }
  if (middle > 0) row.worst = std::max(row.worst, (error / middle).to_double());
  row.worst_ulps = std::max(row.worst_ulps, (error / ulp).to_double());
}

// Two balls whose gap at t = 0 is g R, g from 1e-15 (double; 1e-6 in float) to 1e-3, approaching nearly
// head on (within 0.1 rad) under a sliding or a rolling ball's relative acceleration: the time
// earliest_contact finds from the coefficients that contact_polynomial forms in the type, against the
// exact first root of the polynomial of the inputs as given (Δr, Δv, Δa and D, each exact): what the
// coefficients' own rounding costs. c0's error is a few ε of c0 plus ε² of the squares, so that ulp-level
// times hold down to gaps of about ε R (a float gap of 1e-11 R would be 1e4 ulps off). A time more
// than 8 ulps off is a wrong root.
template <typename Scalar>
void check_tiny_gap(std::mt19937_64& random, Row& row) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double R = 0.028575, D = 2 * R;
  const double decades = std::is_same_v<Scalar, float> ? 3 : 12;
  const double angle = 2 * M_PI * unit(random), gap = std::pow(10.0, -3 - decades * unit(random)) * R;
  const Eigen::Vector2d n(std::cos(angle), std::sin(angle));
  using V = Eigen::Matrix<Scalar, 2, 1>;
  const V dr = ((D + gap) * n).template cast<Scalar>();
  const double aim = angle + M_PI + 0.2 * (unit(random) - 0.5), speed = 0.01 + 5 * unit(random);
  const V dv = (speed * Eigen::Vector2d(std::cos(aim), std::sin(aim))).template cast<Scalar>();
  const double slip = 2 * M_PI * unit(random);
  const V da = (unit(random) < 0.5 ? 0.2 * 9.81 : 0.01 * 9.81) *
               Eigen::Vector2d(std::cos(slip), std::sin(slip)).template cast<Scalar>();
  const Scalar distance = static_cast<Scalar>(D), horizon = Scalar(1);
  const std::array<Scalar, 5> c = billiards::contact_polynomial<Scalar>(dr, dv, da, distance);
  using billiards::accuracy::exact_rational;
  const numeric x = exact_rational(dr.x()), y = exact_rational(dr.y()), vx = exact_rational(dv.x()),
                vy = exact_rational(dv.y()), ax = exact_rational(da.x()), ay = exact_rational(da.y()),
                d = exact_rational(distance);
  const Rational p = trimmed({x * x + y * y - d * d, 2 * (x * vx + y * vy), vx * vx + vy * vy + x * ax + y * ay,
                              vx * ax + vy * ay, (ax * ax + ay * ay) / 4});
  ++row.polynomials;
  const ExactContact exact = exact_earliest(p, exact_rational(horizon));
  const std::optional<Scalar> found = billiards::earliest_contact(c, horizon);
  const auto fail = [&](long& counter, const std::string& what) {
    ++counter;
    if (row.first_failure.empty()) row.first_failure = what + ": " + describe(c, horizon);
  };
  if (!exact.found) {
    if (found) fail(row.false_contacts, "a contact reported where the inputs' polynomial has none");
    return;
  }
  ++row.contacts;
  if (!found) {
    fail(row.misses, "a contact missed");
    return;
  }
  const numeric middle = (exact.low + exact.high) / 2;
  const numeric ulp = exact_rational(std::nextafter(*found, std::numeric_limits<Scalar>::infinity()) - *found);
  const numeric error = GiNaC::abs(exact_rational(*found) - middle);
  if (error > 8 * ulp + (exact.high - exact.low)) fail(row.wrong_roots, "a time more than 8 ulps from the inputs' root");
  if (middle > 0) row.worst = std::max(row.worst, (error / middle).to_double());
  row.worst_ulps = std::max(row.worst_ulps, (error / ulp).to_double());
}

// The families of polynomials, each drawn in double (and rounded to float for the float runs).
class Families {
 public:
  explicit Families(std::uint64_t seed) : random_(seed) {}
  static constexpr int count = 12;
  static const char* name(int family) {
    if (family == count) return "tiny gaps at t = 0, 1e-15 (float: 1e-6) to 1e-3 R, against the inputs' exact root";
    static const char* names[count] = {"two balls on the cloth (phases' accelerations)",
                                       "a ball and a straight cushion",
                                       "double roots (grazes), rounded",
                                       "root clusters (relative gaps 1e-1 to 1e-15)",
                                       "roots spread over 18 decades",
                                       "a leading coefficient near zero",
                                       "touching or overlapping at t = 0",
                                       "lower degrees (c4 = 0, c3 = 0, …)",
                                       "the horizon within a few ulps of a root",
                                       "near grazes, 1e-15 to 1e-9 R either way, in 0.1 to 4 s",
                                       "near grazes, 1e-15 to 1e-9 R either way, at 60 to 100 s",
                                       "touching at t = 0 and separating, then a graze or a miss by 1e-15 to 1"};
    return names[family];
  }

  // Coefficients and the horizon of one polynomial of the family.
  std::pair<std::array<double, 5>, double> operator()(int family) {
    switch (family) {
      case 0: return pair();
      case 1: return cushion();
      case 2: return from_roots({root(), root()}, positive_quadratic(), 1);
      case 3: {
        const double r = root(), gap = std::pow(10.0, -uniform(1, 15));
        return from_roots({r, r * (1 + gap), root()}, {sign() * 1.0, 0.0, 0.0}, 0);
      }
      case 4: {
        std::vector<double> roots;
        for (int i = 0; i < 4; ++i) roots.push_back(std::pow(10.0, uniform(-12, 6)));
        auto [c, horizon] = from_roots(roots, {}, 2);
        return {c, std::pow(10.0, uniform(-12, 7))};
      }
      case 5: {
        auto [c, horizon] = pair();
        c[4] = sign() * std::pow(10.0, -uniform(15, 300));
        if (unit_(random_) < 0.5) c[3] = sign() * std::pow(10.0, -uniform(15, 300));
        return {c, horizon};
      }
      case 6: {
        std::array<double, 5> c{};
        const int pattern = static_cast<int>(unit_(random_) * 6);
        c[0] = pattern < 2 ? 0.0 : pattern < 4 ? -std::pow(10.0, -uniform(0, 20)) : std::pow(10.0, -uniform(10, 300));
        c[1] = pattern % 2 == 0 ? 0.0 : sign() * uniform(0, 2);
        c[2] = sign() * uniform(0, 2);
        c[3] = unit_(random_) < 0.5 ? 0.0 : sign() * uniform(0, 2);
        c[4] = unit_(random_) < 0.5 ? 0.0 : uniform(0, 2);
        return {c, uniform(0, 5)};
      }
      case 8: {
        // Two roots and a quadratic without any, rounded (one time in four a line, whose least value on
        // the window is at the horizon: there only the margin of the test of no contact by its terms
        // tells the two apart); the horizon at the first root, moved by up to 4 ulps either way: p at the
        // horizon is within rounding of 0, from either side.
        const double r1 = uniform(0.01, 2), r2 = r1 + uniform(0, 2);
        auto [c, horizon] = unit_(random_) < 0.25 ? from_roots({r1}, {}, 1)
                                                  : from_roots({r1, r2}, positive_quadratic(), 1);
        return {c, near(r1)};
      }
      case 9: return graze(false);
      case 10: return graze(true);
      case 11: return touching_then_graze();
      default: {
        auto [c, horizon] = pair();
        const int degree = static_cast<int>(unit_(random_) * 3);  // 0, 1 or 2 coefficients kept above c2
        for (int k = 4; k > 2 + degree && k >= 1; --k) c[static_cast<std::size_t>(k)] = 0;
        if (unit_(random_) < 0.3) c[2] = 0;
        return {c, horizon};
      }
    }
  }

 private:
  double uniform(double a, double b) { return a + (b - a) * unit_(random_); }
  double sign() { return unit_(random_) < 0.5 ? -1.0 : 1.0; }
  double root() { return uniform(0, 4); }
  // `x` moved by up to 4 ulps either way.
  double near(double x) {
    const int ulps = static_cast<int>(unit_(random_) * 9) - 4;
    for (int k = 0; k < std::abs(ulps); ++k) x = std::nextafter(x, ulps < 0 ? 0.0 : 10.0);
    return x;
  }
  std::array<double, 3> positive_quadratic() {
    // a (t² + b t + c) with b² < 4c: no real root.
    const double b = uniform(-2, 2), c = b * b / 4 + uniform(0.01, 2);
    return {c, b, 1};
  }

  // Two balls of radius 0.028575 on a 2.54 × 1.27 table, each sliding, rolling or still: accelerations of
  // −μ_s g û (μ_s = 0.2), −μ_r g v̂ (μ_r = 0.01) or 0; aimed at each other half the time.
  std::pair<std::array<double, 5>, double> pair() {
    const double g = 9.81, radius = 0.028575;
    Eigen::Vector2d dr(uniform(-2.54, 2.54), uniform(-1.27, 1.27));
    if (unit_(random_) < 0.5) dr = dr.normalized() * uniform(2 * radius, 4 * radius);
    const auto motion = [&](Eigen::Vector2d& v, Eigen::Vector2d& a) {
      const int phase = static_cast<int>(unit_(random_) * 3);
      const double angle = uniform(0, 2 * M_PI), speed = phase == 2 ? 0.0 : uniform(0, 6);
      v = speed * Eigen::Vector2d(std::cos(angle), std::sin(angle));
      const double slip = uniform(0, 2 * M_PI);
      a = phase == 0   ? -0.2 * g * Eigen::Vector2d(std::cos(slip), std::sin(slip))
          : phase == 1 ? -0.01 * g * Eigen::Vector2d(std::cos(angle), std::sin(angle))
                       : Eigen::Vector2d(0, 0);
    };
    Eigen::Vector2d v1, a1, v2, a2;
    motion(v1, a1);
    motion(v2, a2);
    Eigen::Vector2d dv = v2 - v1, da = a2 - a1;
    if (unit_(random_) < 0.5 && dv.norm() > 0) dv = -dr.normalized() * dv.norm();  // head on
    const std::array<double, 5> c = billiards::contact_polynomial<double>(dr, dv, da, 2 * radius);
    return {c, uniform(0, 4)};
  }

  // Two balls of radius 0.028575 whose centres pass at (1 ± δ) D at the time t1, δ from 1e-15 to 1e-9
  // (a miss or a touch): Δr(t) = n + û f(t), |n| = (1 ± δ) D, n ⊥ û, f(t) = s (t − t1) + ½ a (t² − t1²)
  // with a rolling ball's deceleration (or none, far out), s + a t1 > 0 so that f rises through 0 at t1.
  // The window ends after t1 (or, one time in four, just before the second root of a touch).
  std::pair<std::array<double, 5>, double> graze(bool far) {
    const double radius = 0.028575, distance = 2 * radius;
    const double delta = std::pow(10.0, -uniform(9, 15)) * sign();
    const double t1 = far ? uniform(60, 100) : uniform(0.1, 4);
    const double a = far ? 0.0 : -uniform(0, 0.01 * 9.81), s = far ? uniform(0.005, 0.05) : -a * t1 + uniform(0.05, 3);
    const double angle = uniform(0, 2 * M_PI);
    const Eigen::Vector2d u(std::cos(angle), std::sin(angle)), normal(-u.y(), u.x());
    const Eigen::Vector2d n = normal * (distance * (1 + delta));
    const Eigen::Vector2d dr = n - u * (s * t1 + 0.5 * a * t1 * t1), dv = u * s, da = u * a;
    const std::array<double, 5> c = billiards::contact_polynomial<double>(dr, dv, da, distance);
    return {c, unit_(random_) < 0.25 ? t1 : t1 * uniform(1, 1.5)};
  }

  // Bodies touching at t = 0 and separating (c0 = 0 < c1): p = t ((t − t1)² + σ)(α + β t), α > 0, β ≥ 0
  // (β = 0 one time in three: a cubic), σ = ±δ t1², δ from 1e-15 to 1 (the pair meets again in a graze
  // where σ ≤ 0, and misses by δ where σ > 0), rounded; the window ends after t1 (or, one time in four,
  // at it). One time in four instead p = t (α − β t) with the window's end within 4 ulps of α/β.
  std::pair<std::array<double, 5>, double> touching_then_graze() {
    if (unit_(random_) < 0.25) {
      // One time in four p = t (α − β t), the horizon within 4 ulps of its root α/β, either way.
      const double alpha = uniform(0.1, 10), beta = uniform(0.1, 10);
      return {{0, alpha, -beta, 0, 0}, near(alpha / beta)};
    }
    const double t1 = uniform(0.01, 4), sigma = sign() * std::pow(10.0, -uniform(0, 15)) * t1 * t1;
    const double alpha = uniform(0.1, 10), beta = unit_(random_) < 1.0 / 3 ? 0.0 : uniform(0, 10);
    // (t² − 2 t1 t + t1² + σ)(α + β t), times t.
    const double a0 = t1 * t1 + sigma, a1 = -2 * t1;
    const std::array<double, 5> c{0, a0 * alpha, a0 * beta + a1 * alpha, a1 * beta + alpha, beta};
    return {c, unit_(random_) < 0.25 ? t1 : t1 * uniform(1, 1.5)};
  }

  std::pair<std::array<double, 5>, double> cushion() {
    const double radius = 0.028575;
    const double gap = uniform(radius * 0.999, 1.27), speed = uniform(-6, 2), acceleration = uniform(-2, 2);
    const std::array<double, 3> q = billiards::cushion_polynomial(gap, speed, acceleration, radius);
    return {{q[0], q[1], q[2], 0, 0}, uniform(0, 4)};
  }

  // The product of (t − r) over `roots` and of the quadratic `rest` (c0, c1, c2; all zero for none), times
  // a random positive scale over 20 decades where `scaling` is 2 (else 1); negated, mostly, where it is
  // negative at t = 0.
  std::pair<std::array<double, 5>, double> from_roots(const std::vector<double>& roots, std::array<double, 3> rest,
                                                      int scaling) {
    std::vector<double> p{1.0};
    const auto times = [&](const std::vector<double>& q) {
      std::vector<double> out(p.size() + q.size() - 1, 0.0);
      for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = 0; j < q.size(); ++j) out[i + j] += p[i] * q[j];
      p = out;
    };
    for (double r : roots) times({-r, 1.0});
    if (rest[0] != 0 || rest[1] != 0 || rest[2] != 0) {
      std::vector<double> q{rest[0], rest[1], rest[2]};
      while (!q.empty() && q.back() == 0) q.pop_back();
      times(q);
    }
    const double scale = scaling == 2 ? std::pow(10.0, uniform(-10, 10)) : 1.0;
    std::array<double, 5> c{};
    for (std::size_t k = 0; k < p.size() && k < 5; ++k) c[k] = scale * p[k];
    if (c[0] < 0 && unit_(random_) < 0.8)
      for (double& x : c) x = -x;  // mostly apart at t = 0
    return {c, uniform(0, 5)};
  }

  std::mt19937_64 random_;
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Checks billiards::earliest_contact against exact root isolation.", "billiards-contact-roots"};
  long polynomials = 20000;
  std::uint64_t seed = 1;
  app.add_option("--polynomials", polynomials, "Polynomials in all, over the families (1 to 10^7)")
      ->check(billiards_support::count_at_least(1, 10'000'000));
  app.add_option("--seed", seed, "The random generator's seed")->check(billiards_support::count_at_least(0));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::cerr << "billiards-contact-roots: " << error.what() << " (run with --help for usage)\n";
    return 2;
  }

  Families families(seed);
  std::mt19937_64 tiny_gaps(seed + 1);
  std::map<std::pair<int, std::string>, Row> rows;
  for (long i = 0; i < polynomials; ++i) {
    const int family = static_cast<int>(i % Families::count);
    const auto [c, horizon] = families(family);
    check<double>(c, horizon, rows[{family, "double"}]);
    std::array<float, 5> single{};
    for (std::size_t k = 0; k < 5; ++k) single[k] = static_cast<float>(c[k]);
    check<float>(single, static_cast<float>(horizon), rows[{family, "float"}]);
    if (i % Families::count == 0) {
      check_tiny_gap<double>(tiny_gaps, rows[{Families::count, "double"}]);
      check_tiny_gap<float>(tiny_gaps, rows[{Families::count, "float"}]);
    }
  }
  bool failed = false;
  std::cout << "| polynomials | type | count | contacts | misses | false contacts | wrong roots | wrong at t = 0 | "
               "proven apart (unsound) | worst relative error of t | worst error of t in ulps |\n"
               "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& [key, row] : rows) {
    std::cout << "| " << Families::name(key.first) << " | " << key.second << " | " << row.polynomials << " | "
              << row.contacts << " | " << row.misses << " | " << row.false_contacts << " | " << row.wrong_roots
              << " | " << row.wrong_at_zero << " | " << row.proven_apart << " (" << row.unsound_proofs << ") | "
              << row.worst << " | " << row.worst_ulps << " |\n";
    if (row.misses + row.false_contacts + row.wrong_roots + row.wrong_at_zero + row.unsound_proofs > 0) {
      failed = true;
      std::cerr << "billiards-contact-roots: " << Families::name(key.first) << " (" << key.second
                << "): " << row.first_failure << "\n";
    }
  }
  return failed ? 1 : 0;
}
