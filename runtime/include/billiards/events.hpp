// Event times on the cloth (the spinning-ball model's audit, section "Event times on the cloth"): the
// polynomials in t whose roots are contacts while each ball moves as r0 + v0 t + ½ a t², built from the
// generated kernels of billiards/spin_kernels.hpp, and the earliest contact they hold.
#pragma once

#include <billiards/checked.hpp>
#include <billiards/detail/exact_roots.hpp>
#include <billiards/spin_kernels.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>

namespace billiards {

/// The contact polynomial c[0] + c[1] t + c[2] t² + c[3] t³ + c[4] t⁴ = |Δr + Δv t + ½ Δa t²|² − D² of
/// two balls (Δ: ball 2 less ball 1, D = R1 + R2), or of a ball and a circle (Δ: the ball less the
/// circle's centre; D = R + ρ for a rounded jaw of radius ρ, D = ρ for a pocket's capture circle that the
/// centre enters). Negative where they overlap, zero where they touch. Each coefficient is a generated
/// kernel (`events.contact_constant_term` … `events.contact_quartic_term`).
template <typename Scalar>
[[nodiscard]] std::array<Scalar, 5> contact_polynomial(const Eigen::Matrix<Scalar, 2, 1>& dr,
                                                       const Eigen::Matrix<Scalar, 2, 1>& dv,
                                                       const Eigen::Matrix<Scalar, 2, 1>& da,
                                                       Scalar distance) noexcept {
  namespace k = kernels::spin;
  return {k::contact_constant_term(dr.x(), dr.y(), distance), k::contact_linear_term(dr.x(), dr.y(), dv.x(), dv.y()),
          k::contact_quadratic_term(dr.x(), dr.y(), dv.x(), dv.y(), da.x(), da.y()),
          k::contact_cubic_term(dv.x(), dv.y(), da.x(), da.y()), k::contact_quartic_term(da.x(), da.y())};
}

/// The cushion polynomial c[0] + c[1] t + c[2] t² = s0 − R + v_n t + ½ a_n t² of a ball and a straight
/// cushion: `gap` s0 the distance of the ball's centre from the cushion's line (positive on the table's
/// side), `normal_speed` v_n and `normal_acceleration` a_n along the cushion's unit normal into the table.
/// Zero where the ball touches the cushion (`events.cushion_constant_term`, `events.cushion_linear_term`,
/// `events.cushion_quadratic_term`).
template <typename Scalar>
[[nodiscard]] std::array<Scalar, 3> cushion_polynomial(Scalar gap, Scalar normal_speed, Scalar normal_acceleration,
                                                       Scalar radius) noexcept {
  namespace k = kernels::spin;
  return {k::cushion_contact_constant_term(gap, radius), normal_speed,
          k::cushion_contact_quadratic_term(normal_acceleration)};
}

namespace detail {

/// A polynomial of degree at most 4 as the root finder holds it: coefficients by power, and its degree
/// (the highest power whose coefficient is not zero; −1 for the zero polynomial).
template <typename Scalar>
struct EventPolynomial {
  std::array<Scalar, 5> c{};
  int degree = -1;
};

template <typename Scalar>
[[nodiscard]] EventPolynomial<Scalar> trimmed(EventPolynomial<Scalar> p) noexcept {
  while (p.degree >= 0 && p.c[static_cast<std::size_t>(p.degree)] == 0) --p.degree;
  return p;
}

/// p'(t) up to a positive factor, which changes neither its roots nor its signs: coefficients k c_k,
/// exact, or (k/d) c_k where the k c_k would not all be finite or their sizes would overflow (d the
/// degree). Every lane is computed (the coefficients above the degree are zero), without a branch on the
/// degree.
template <typename Scalar>
[[nodiscard]] EventPolynomial<Scalar> derivative(const EventPolynomial<Scalar>& p) noexcept {
  EventPolynomial<Scalar> d;
  d.c = {p.c[1], 2 * p.c[2], 3 * p.c[3], 4 * p.c[4], Scalar(0)};
  using std::fabs;
  if (!(fabs(d.c[0]) + fabs(d.c[1]) + fabs(d.c[2]) + fabs(d.c[3]) <= std::numeric_limits<Scalar>::max())) {
    const Scalar degree = Scalar(p.degree > 0 ? p.degree : 1);
    for (int k = 1; k <= 4; ++k) d.c[static_cast<std::size_t>(k - 1)] = Scalar(k) / degree * p.c[static_cast<std::size_t>(k)];
  }
  // The leading k c_k of a trimmed p is not zero (no product by k ≥ 1 underflows to it).
  d.degree = p.degree - 1;
  return d;
}

/// p(t) by Horner's rule: for finite coefficients and a finite t ≥ 0 never NaN (an overflow gives the
/// sign of the terms that overflowed). The coefficients above the degree are zero, so that starting from
/// c[4] gives the same result as starting from the leading one, in straight-line code.
template <typename Scalar>
[[nodiscard]] Scalar evaluate(const EventPolynomial<Scalar>& p, Scalar t) noexcept {
  if (p.degree < 0) return Scalar(0);
  return (((p.c[4] * t + p.c[3]) * t + p.c[2]) * t + p.c[1]) * t + p.c[0];
}

/// A bound on the rounding error of evaluate(p, t): 2 d ε Σ |c_k| t^k (Horner's running error bound,
/// γ_2d ≤ 2 d ε for d ≤ 4), plus 2 d times the smallest subnormal for the products that underflow.
template <typename Scalar>
[[nodiscard]] Scalar evaluation_error(const EventPolynomial<Scalar>& p, Scalar t) noexcept {
  if (p.degree < 1) return Scalar(0);
  using std::fabs;
  const Scalar r = (((fabs(p.c[4]) * t + fabs(p.c[3])) * t + fabs(p.c[2])) * t + fabs(p.c[1])) * t + fabs(p.c[0]);
  return Scalar(2 * p.degree) *
         (std::numeric_limits<Scalar>::epsilon() * r + std::numeric_limits<Scalar>::denorm_min());
}

/// The next value of the type above x: for a finite x > 0 its bits plus one (no library call), else
/// std::nextafter's.
template <typename Scalar>
[[nodiscard]] Scalar next_up(Scalar x) noexcept {
  if (x > 0 && x < std::numeric_limits<Scalar>::max())
    return std::bit_cast<Scalar>(static_cast<kernels::BitsOf<Scalar>>(std::bit_cast<kernels::BitsOf<Scalar>>(x) + 1));
  return std::nextafter(x, std::numeric_limits<Scalar>::infinity());
}

/// A point strictly inside (a, b) for bisection: the midpoint, or the geometric mean where a > 0 and
/// b/a > 8, so that a root many decades below b is reached in few steps. Returns a or b once the interval
/// cannot be split.
template <typename Scalar>
[[nodiscard]] Scalar split(Scalar a, Scalar b) noexcept {
  if (a > 0 && b > 8 * a) return std::sqrt(a) * std::sqrt(b);
  return a + (b - a) / 2;
}

/// The point of (a, b] where p changes sign, given p(a) = `at_a` ≠ 0 and p(b) = `at_b` of the other
/// sign or 0 (as evaluated), p monotone on [a, b]. Each step shrinks a bracket [a, b] around the change by
/// evaluating p at a point inside it:
/// - Newton's step from the last point, where it lands inside and the bracket shrank in the last step;
///   a Newton step is followed by a probe twice the next Newton step's length beyond it (and beyond
///   rounding's reach), which closes the other end on the root: Newton alone converges from one side
///   and leaves the bracket wide;
/// - after a point where p evaluates to 0, a step back from it past rounding's reach (doubled each time
///   it lands on 0 again);
/// - otherwise the regula falsi between the ends, Illinois' variant (the value kept at an end that has
///   not moved for two steps is halved, so that both ends close in);
/// - and a split (the midpoint, or the geometric mean across decades) after three steps that did not
///   halve the bracket.
/// Returns the bracket's left end once it cannot shrink further (a width of 2 ε b), so that p at the
/// result still has the sign of `at_a` as evaluated (a point where p evaluates to 0 counts as past the
/// root); always within 300 evaluations.
template <typename Scalar>
[[nodiscard]] Scalar sign_change(const EventPolynomial<Scalar>& p, const EventPolynomial<Scalar>& slope, Scalar a,
                                 Scalar b, Scalar at_a, Scalar at_b) noexcept {
  const bool before = at_a > 0;
  // The regula falsi's values at the ends (Illinois-halved).
  Scalar falsi_a = at_a, falsi_b = at_b;
  const auto falsi = [&] {
    const Scalar x = a + (b - a) * (falsi_a / (falsi_a - falsi_b));
    return x > a && x < b ? x : split(a, b);
  };
  // The bracket closed on an estimate `root` of the root within rounding's reach of it (where p's slope
  // there is `gradient`): a probe on each side, past the width in which rounding may give p either sign;
  // taken where their signs confirm it. Returns whether it closed.
  const auto close_on = [&](Scalar root, Scalar gradient) {
    if (!(root > a && root < b && gradient > 0)) return false;
    const Scalar reach = 2 * std::numeric_limits<Scalar>::epsilon() * root + evaluation_error(p, root) / gradient;
    const Scalar low = root - reach, high = root + reach;
    if (!(low > a && high < b)) return false;
    const Scalar at_low = evaluate(p, low), at_high = evaluate(p, high);
    if (!(at_low != 0 && (at_low > 0) == before && (at_high == 0 || (at_high > 0) != before))) return false;
    a = low;
    b = high;
    falsi_a = at_low;
    falsi_b = at_high;
    return true;
  };
  // A quadratic's root in closed form (the stable pair q/c2, c0/q, q = −(c1 + sign(c1) √disc)/2) is
  // within a few ulps of the exact one: the bracket is closed on it at once.
  if (p.degree == 2) {
    const Scalar c0 = p.c[0], c1 = p.c[1], c2 = p.c[2];
    const Scalar discriminant = c1 * c1 - 4 * c0 * c2;
    if (discriminant >= 0 && std::isfinite(discriminant)) {
      const Scalar q = -(c1 + std::copysign(std::sqrt(discriminant), c1)) / 2;
      const Scalar first = q / c2, second = c0 / q;
      const Scalar root = first > a && first < b ? first : second;
      if (close_on(root, std::fabs(evaluate(slope, root)))) {
        // Closed on it (within a few ulps of the exact root, as a rule): the value of the type where p
        // changes sign as evaluated, found by at most 32 steps of one value from the root within the
        // closed bracket; where that many do not reach it (a bracket many values wide, where p is
        // nearly flat), the search below goes on from the closed bracket.
        Scalar t = root;
        const bool above = evaluate(p, t) > 0;
        for (int step = 0; step < 32; ++step) {
          if (above) {
            const Scalar up = next_up(t);
            if (!(up < b && evaluate(p, up) > 0)) return t;
            t = up;
          } else {
            t = std::nextafter(t, a);
            if (!(t > a)) break;
            if (evaluate(p, t) > 0) return t;
          }
        }
      }
    }
  }
  Scalar x = falsi();
  // Elsewhere the first point is the root of p's Taylor quadratic at the end where |p| is least, where it
  // lies inside: beside a turning point, where p is nearly a parabola, it is close to the root, and
  // Newton's steps from it converge at once.
  if (p.degree >= 3) {
    const Scalar end = std::fabs(falsi_a) <= std::fabs(falsi_b) ? a : b;
    const Scalar value = end == a ? falsi_a : falsi_b;
    Scalar first = p.c[1], second = 0, power = 1;  // p'(end), p''(end); power = end^(k − 2)
    for (int k = 2; k <= p.degree; ++k) {
      const Scalar c = p.c[static_cast<std::size_t>(k)];
      second += Scalar(k * (k - 1)) * c * power;
      power *= end;
      first += Scalar(k) * c * power;
    }
    // ½ p'' s² + p' s + p = 0 for the step s from the end into the bracket.
    const Scalar half = second / 2, discriminant = first * first - 4 * half * value;
    if (discriminant >= 0 && std::isfinite(discriminant) && half != 0) {
      const Scalar root = std::sqrt(discriminant);
      const Scalar s1 = (-first + root) / (2 * half), s2 = (-first - root) / (2 * half);
      const Scalar into = end == a ? std::min(s1 > 0 ? s1 : s2, s2 > 0 ? s2 : s1)
                                   : std::max(s1 < 0 ? s1 : s2, s2 < 0 ? s2 : s1);
      const Scalar guess = end + into;
      if (guess > a && guess < b) x = guess;
    }
  }
  Scalar previous_width = b - a;
  Scalar back = 0;            // the last step back from a zero
  bool after_newton = false;  // x was a Newton step's
  int slow = 0;               // steps in a row that did not halve the bracket
  int last_moved = 0;         // the end the last step moved: −1 a, +1 b
  Scalar newton_step = std::numeric_limits<Scalar>::infinity();  // the last Newton step's length
  for (int step = 0; step < 300; ++step) {
    if (!(x > a && x < b)) break;
    const Scalar value = evaluate(p, x);
    // A zero as evaluated closes the bracket from the right: the exact root may lie just before it.
    const bool moved_left_end = value != 0 && (value > 0) == before;
    if (moved_left_end) {
      a = x;
      falsi_a = value;
      if (last_moved < 0) falsi_b /= 2;
      last_moved = -1;
    } else {
      b = x;
      falsi_b = value;
      if (last_moved > 0) falsi_a /= 2;
      last_moved = 1;
    }
    const Scalar width = b - a;
    if (!(width > 2 * std::numeric_limits<Scalar>::epsilon() * b)) break;
    const Scalar gradient = evaluate(slope, x);
    // Within the width in which rounding may give p either sign the bracket shrinks no further that
    // means anything: the root lies in it, as near as p evaluated can tell.
    if (width <= Scalar(0x1p-20) * b && gradient != 0 &&
        4 * width * std::fabs(gradient) <= evaluation_error(p, x))
      break;
    slow = width <= previous_width / 2 ? 0 : slow + 1;
    previous_width = width;
    const Scalar newton = gradient != 0 ? x - value / gradient : x;
    const bool was_newton = after_newton;
    after_newton = false;
    if (value == 0) {
      back = std::max({2 * back, std::numeric_limits<Scalar>::epsilon() * b,
                       gradient != 0 ? evaluation_error(p, x) / std::fabs(gradient) : Scalar(0)});
      x = b - back;
      if (!(x > a && x < b)) x = split(a, b);
      continue;
    }
    back = 0;
    const Scalar step_length = std::fabs(newton - x);
    const bool converging = step_length < newton_step / 2;
    newton_step = step_length;
    if (was_newton && newton != x && converging && step_length <= Scalar(0x1p-26) * std::fabs(x) &&
        close_on(newton, std::fabs(gradient))) {
      // Newton's steps converged (the last below 2^-26 of x, so that this one lands within rounding of
      // the root): the bracket closed on it; bisection and the regula falsi finish within it.
      x = falsi();
    } else if (was_newton && newton != x && converging && 16 * step_length > width && newton > a && newton < b) {
      // Newton's steps shrinking but still long beside the bracket: one more, before the probe.
      x = newton;
      after_newton = true;
    } else if (was_newton && newton != x) {
      // The probe: twice the next Newton step from the end the last one moved, towards the other end, and
      // past the width within which rounding may give p either sign, so that it lands beyond the root.
      const Scalar reach = 2 * std::fabs(newton - x) + evaluation_error(p, x) / std::fabs(gradient);
      const Scalar beyond = moved_left_end ? a + reach : b - reach;
      x = beyond > a && beyond < b ? beyond : split(a, b);
    } else if (newton > a && newton < b && slow < 2) {
      x = newton;
      after_newton = true;
    } else {
      x = slow >= 3 ? split(a, b) : falsi();
    }
  }
  return a;
}

/// The points of (lo, hi) where p changes sign, in increasing order, written to `out` (at most
/// p.degree of them); returns how many. p is split into monotone pieces at the sign changes of p'
/// (found the same way, down to a linear p'), and each piece holds at most one.
template <typename Scalar>
int sign_changes(const EventPolynomial<Scalar>& p, Scalar lo, Scalar hi, Scalar* out) noexcept {
  if (p.degree < 1) return 0;
  if (p.degree == 1) {
    const Scalar root = -p.c[0] / p.c[1];
    if (root > lo && root < hi) {
      out[0] = root;
      return 1;
    }
    return 0;
  }
  const EventPolynomial<Scalar> slope = derivative(p);
  std::array<Scalar, 6> breaks{};
  breaks[0] = lo;
  const int turns = sign_changes(slope, lo, hi, breaks.data() + 1);
  breaks[static_cast<std::size_t>(turns + 1)] = hi;
  int found = 0;
  Scalar left = evaluate(p, lo);
  for (int i = 0; i <= turns; ++i) {
    const Scalar a = breaks[static_cast<std::size_t>(i)], b = breaks[static_cast<std::size_t>(i + 1)];
    const Scalar right = evaluate(p, b);
    if (left != 0 && right != 0 && (left > 0) != (right > 0)) out[found++] = sign_change(p, slope, a, b, left, right);
    left = right;
  }
  return found;
}

/// p(t) by compensated Horner (Graillat, Langlois and Louvet: each step's rounding errors, exact by
/// fused multiply-adds and Knuth's two-sum, summed beside it), as accurate as Horner's rule in twice the
/// precision: its error is at most ε |p(t)| + γ_2d² Σ |c_k| t^k (γ_2d ≤ 2 d ε (1 + ε) for d ≤ 4).
/// `sure` is set where that bound, with room for products that underflow, leaves the sign p's: the
/// result exceeds twice the bound's last term. t ≥ 0 finite. At several points at once (`Lanes`), each
/// the same arithmetic as at one, their chains independent, so that they run side by side.
template <typename Scalar, std::size_t Lanes>
void compensated_values(const EventPolynomial<Scalar>& p, const std::array<Scalar, Lanes>& t,
                        std::array<Scalar, Lanes>& result, std::array<bool, Lanes>& sure) noexcept {
  using std::fabs;
  // From the leading coefficient (those above it are zero: starting from c[4] gives the same values).
  const auto degree = static_cast<std::size_t>(std::max(p.degree, 0));
  std::array<Scalar, Lanes> value, correction, size;
  value.fill(p.c[degree]);
  correction.fill(Scalar(0));
  size.fill(fabs(p.c[degree]));
  for (int k = static_cast<int>(degree) - 1; k >= 0; --k) {
    const Scalar coefficient = p.c[static_cast<std::size_t>(k)];
    for (std::size_t i = 0; i < Lanes; ++i) {
      const Scalar product = value[i] * t[i], product_error = std::fma(value[i], t[i], -product);
      const Scalar sum = product + coefficient, back = sum - product;
      const Scalar sum_error = (product - (sum - back)) + (coefficient - back);
      correction[i] = correction[i] * t[i] + (product_error + sum_error);
      value[i] = sum;
      size[i] = size[i] * t[i] + fabs(coefficient);
    }
  }
  constexpr Scalar unit = std::numeric_limits<Scalar>::epsilon() / 2;  // the unit roundoff
  constexpr Scalar gamma = Scalar(2 * 4) * unit * Scalar(1.001);
  for (std::size_t i = 0; i < Lanes; ++i) {
    result[i] = value[i] + correction[i];
    const Scalar power = std::max(Scalar(1), t[i] * t[i] * t[i] * t[i]);
    const Scalar bound =
        2 * gamma * gamma * size[i] + Scalar(64) * std::numeric_limits<Scalar>::denorm_min() * power;
    sure[i] = std::isfinite(bound) && std::isfinite(result[i]) && fabs(result[i]) > bound;
  }
}

/// compensated_values at one point.
template <typename Scalar>
[[nodiscard]] Scalar compensated_value(const EventPolynomial<Scalar>& p, Scalar t, bool& sure) noexcept {
  std::array<Scalar, 1> result;
  std::array<bool, 1> sure_of;
  compensated_values<Scalar, 1>(p, {t}, result, sure_of);
  sure = sure_of[0];
  return result[0];
}

/// The sign of p(t) (−1, 0, +1) for the coefficients exactly as given: compensated_value's where it is
/// sure, else (within about ε² of 0 relative to the terms, or out of range) exact arithmetic's.
template <typename Scalar>
[[nodiscard]] int certified_sign(const EventPolynomial<Scalar>& p, Scalar t) {
  bool sure = false;
  const Scalar value = compensated_value(p, t, sure);
  if (sure) return value > 0 ? 1 : -1;
  std::array<Scalar, 5> c{};
  for (std::size_t k = 0; k < 5; ++k) c[k] = p.c[k];
  return exact::sign_of_polynomial(c, t);
}

/// The root of p in (a, b] placed exactly: given p(a) > 0 and p(b) ≤ 0 (certainly: their signs are
/// not for rounding to change) and `guess` in [a, b] near the root, the largest value t of the type
/// with p(t) > 0 whose next value up has p ≤ 0 — that next value itself where p is 0 there. Newton's
/// steps from the guess with p's compensated value (as accurate as in twice the precision, so that they
/// settle within a value or two of the root), kept inside the bracket of certified signs: a compensated
/// value sure of its sign moves the bracket's end, and a step that would leave the bracket splits it
/// instead. Then the signs at the last step and its two neighbours, evaluated together; then steps of
/// 1, 2, 4, … values from the last towards the root until the sign turns, then bisection: every sign
/// certified, so that the result depends on p and the bracket's root alone, not on the guess. 0 ≤ a < b;
/// `slope` is p' up to a positive factor (derivative()).
template <typename Scalar>
[[nodiscard]] Scalar placed_root(const EventPolynomial<Scalar>& p, const EventPolynomial<Scalar>& slope, Scalar a,
                                 Scalar b, Scalar guess) {
  using Bits = kernels::BitsOf<Scalar>;  // non-negative values order as their bits
  const auto bits = [](Scalar x) { return std::bit_cast<Bits>(x); };
  const auto value_of = [](Bits n) { return std::bit_cast<Scalar>(n); };
  Scalar lo = a, hi = b;  // certified: p(lo) > 0, p(hi) ≤ 0
  int at_hi = -1;         // the sign of p(hi), −1 or 0 (−1 stands for "≤ 0" until it is evaluated)
  bool hi_known = false;
  // x with p's certified sign `sign` there: an end of the bracket. Whether p is above 0 there.
  const auto take = [&](Scalar x, int sign) {
    if (sign > 0) {
      lo = x;
    } else {
      hi = x;
      at_hi = sign;
      hi_known = true;
    }
    return sign > 0;
  };
  const auto probe = [&](Scalar x) { return take(x, certified_sign(p, x)); };
  // slope is p' up to a positive factor: a Newton step with it is the same only where the factor is 1,
  // which derivative() keeps below overflow; the steps are guesses, only certified signs move the ends.
  Scalar x = std::clamp(guess, a, b);
  for (int step = 0; step < 32 && bits(hi) - bits(lo) > 1; ++step) {
    bool sure = false;
    const Scalar value = compensated_value(p, x, sure);
    if (sure && x > lo && x < hi) take(x, value > 0 ? 1 : -1);
    const Scalar gradient = evaluate(slope, x);
    const Scalar next = gradient != 0 ? x - value / gradient : split(lo, hi);
    // A step below the square root of the type's precision (relative to x), or within two values of it,
    // lands within rounding of the root (Newton's steps square the error): settled.
    constexpr Scalar settled = std::numeric_limits<Scalar>::digits > 24 ? Scalar(0x1p-26) : Scalar(0x1p-12);
    if (gradient != 0 && (std::fabs(next - x) <= settled * x || std::fabs(next - x) <= 2 * (next_up(x) - x))) {
      x = next;
      break;
    }
    x = next > lo && next < hi ? next : split(lo, hi);
  }
  // Settled within a value or two of the root, as a rule: p's compensated values at the last step and at
  // its two neighbours, together, move the ends where they are sure (at most one sign change lies in the
  // bracket, so that those above 0 lie before those below), often onto two neighbours at once.
  if (bits(hi) - bits(lo) > 2 && x > lo && x < hi) {
    const std::array<Scalar, 3> points{value_of(bits(x) - 1), x, value_of(bits(x) + 1)};
    std::array<Scalar, 3> values;
    std::array<bool, 3> sure;
    compensated_values(p, points, values, sure);
    for (std::size_t i = 0; i < 3; ++i) {
      if (sure[i] && points[i] > lo && points[i] < hi) take(points[i], values[i] > 0 ? 1 : -1);
    }
  }
  // From the last step (an end where it settled at or beyond one), steps towards the root.
  const bool above = x <= lo || (x < hi && probe(x));
  for (Bits step = 1; bits(hi) - bits(lo) > 1; step *= 2) {
    if (step >= bits(hi) - bits(lo)) break;
    if (probe(value_of(above ? bits(lo) + step : bits(hi) - step)) != above) break;
  }
  while (bits(hi) - bits(lo) > 1) probe(value_of(bits(lo) + (bits(hi) - bits(lo)) / 2));
  if (!hi_known) at_hi = certified_sign(p, hi);
  return at_hi == 0 ? hi : lo;
}

/// The first positive root of c0 + c1 t + c2 t² falling at 0 (c0 > 0, c1 < 0) in closed form,
/// 2 c0/(√(c1² − 4 c0 c2) − c1), without cancellation (−c1 > 0); NaN where the discriminant, as rounded,
/// is negative (or not a number).
template <typename Scalar>
[[nodiscard]] Scalar falling_quadratic_root(Scalar c0, Scalar c1, Scalar c2) noexcept {
  const Scalar discriminant = c1 * c1 - 4 * c0 * c2;
  return discriminant >= 0 ? 2 * c0 / (std::sqrt(discriminant) - c1) : std::numeric_limits<Scalar>::quiet_NaN();
}

/// The first root of a quadratic p falling at 0 (p(0) > 0, p'(0) < 0: a ball approaching a cushion) placed
/// exactly where its closed form (falling_quadratic_root) lands within a value of the type of it: the
/// value x in (0, horizon) beside it where p's compensated values at x and at the next value up are sure
/// of their signs, above 0 and below it. A quadratic falling at 0
/// changes so between two neighbours only at its first root, so that x is what placed_root returns. NaN
/// where that is not shown (no real root as rounded, a root at or beyond the horizon, signs not sure,
/// the closed form more than a value off): the general search decides.
template <typename Scalar>
[[nodiscard]] Scalar placed_quadratic_root(const EventPolynomial<Scalar>& p, Scalar horizon) noexcept {
  constexpr Scalar unknown = std::numeric_limits<Scalar>::quiet_NaN();
  const Scalar root = falling_quadratic_root(p.c[0], p.c[1], p.c[2]);
  if (!(root > 0 && root < horizon)) return unknown;  // also NaN, and 0 from an infinite discriminant
  using Bits = kernels::BitsOf<Scalar>;
  const Bits bits = std::bit_cast<Bits>(root);
  const std::array<Scalar, 3> points{std::bit_cast<Scalar>(static_cast<Bits>(bits - 1)), root,
                                     std::bit_cast<Scalar>(static_cast<Bits>(bits + 1))};
  std::array<Scalar, 3> values;
  std::array<bool, 3> sure;
  compensated_values(p, points, values, sure);
  for (std::size_t i = 0; i < 2; ++i) {
    if (sure[i] && sure[i + 1] && values[i] > 0 && values[i + 1] < 0 && points[i] > 0 && points[i + 1] <= horizon)
      return points[i];
  }
  return unknown;
}

/// Whether the Bernstein coefficients `b` (degree 4) of a polynomial on an interval all exceed `margin`,
/// or those of its halves (de Casteljau's subdivision), `depth` times over, do: each bounds the polynomial
/// from below on its interval. An end at or below the margin fails at once.
template <typename Scalar>
[[nodiscard]] bool bernstein_above(const std::array<Scalar, 5>& b, Scalar margin, int depth) noexcept {
  if (!(b[0] > margin && b[4] > margin)) return false;
  if (b[1] > margin && b[2] > margin && b[3] > margin) return true;
  if (depth == 0) return false;
  const Scalar l1 = (b[0] + b[1]) / 2, m1 = (b[1] + b[2]) / 2, n1 = (b[2] + b[3]) / 2, o1 = (b[3] + b[4]) / 2;
  const Scalar l2 = (l1 + m1) / 2, m2 = (m1 + n1) / 2, n2 = (n1 + o1) / 2;
  const Scalar l3 = (l2 + m2) / 2, m3 = (m2 + n2) / 2;
  const Scalar middle = (l3 + m3) / 2;
  return bernstein_above<Scalar>({b[0], l1, l2, l3, middle}, margin, depth - 1) &&
         bernstein_above<Scalar>({middle, m3, n2, o1, b[4]}, margin, depth - 1);
}

/// The sign p'' keeps on all of [0, horizon] for p of degree 3 or 4: +1 where p is convex there (p'' = 2 c2 +
/// 6 c3 t + 12 c4 t² > 0 by the bound c2's term less every negative term at the horizon), −1 where it is
/// concave (likewise), 0 where neither is shown. The margin, 16 ε times the terms' sizes, exceeds the
/// rounding of 6 c3 and 12 c4 and of the bound's sums, so that the sign is that of the exact second
/// derivative.
template <typename Scalar>
[[nodiscard]] int curvature_on(const EventPolynomial<Scalar>& p, Scalar horizon) noexcept {
  const Scalar quadratic = 2 * p.c[2], linear = 6 * p.c[3] * horizon,
               square = (p.degree == 4 ? 12 * p.c[4] : Scalar(0)) * horizon * horizon;
  const Scalar margin = 16 * std::numeric_limits<Scalar>::epsilon() *
                        (std::fabs(quadratic) + std::fabs(linear) + std::fabs(square));
  if (quadratic + std::min(linear, Scalar(0)) + std::min(square, Scalar(0)) > margin) return 1;
  if (quadratic + std::max(linear, Scalar(0)) + std::max(square, Scalar(0)) < -margin) return -1;
  return 0;
}

/// A bracket of a root: p above 0 at `low`, below 0 at `high`; `estimate`, in [low, high], the search's
/// nearest point to the root.
template <typename Scalar>
struct Bracket {
  Scalar low, high, at_low, at_high, estimate;
};

/// A bracket of the first root of p in (0, horizon), p convex there and falling at 0 (p(0) > 0, p'(0)
/// < 0): Newton's steps from 0, which on a convex falling p stay below the first root and rise to it,
/// until p is within its rounding of 0; the last step above that is the bracket's lower end, a probe
/// past the root (twice the rounding's reach, doubled while p is not below its rounding) its upper end,
/// and the step that came within rounding of 0 its estimate.
/// Between them p crosses 0 once. Empty where the steps pass p's minimum or the horizon, stall, or the
/// probe finds no certain sign: the general search decides.
template <typename Scalar>
[[nodiscard]] std::optional<Bracket<Scalar>> convex_first_root(const EventPolynomial<Scalar>& p,
                                                               const EventPolynomial<Scalar>& slope,
                                                               Scalar horizon) noexcept {
  Scalar t = 0, value = p.c[0];
  // A start nearer the root: the smaller root of the Taylor quadratic c0 + c1 t + c2 t², where p is
  // above 0 there beyond rounding and still falling (on a convex p it then falls all the way from 0, and
  // stays above 0 before it); below 0 there beyond rounding, it brackets the root with 0 at once.
  if (p.c[2] > 0) {
    const Scalar guess = falling_quadratic_root(p.c[0], p.c[1], p.c[2]);
    if (guess > 0 && guess < horizon) {
      const Scalar at_guess = evaluate(p, guess), error = evaluation_error(p, guess);
      if (at_guess < -2 * error) return Bracket<Scalar>{Scalar(0), guess, p.c[0], at_guess, guess};
      if (at_guess > 2 * error && evaluate(slope, guess) < 0) {
        t = guess;
        value = at_guess;
      }
    }
  }
  for (int step = 0; step < 64; ++step) {
    const Scalar gradient = evaluate(slope, t);
    if (!(gradient < 0)) return std::nullopt;
    const Scalar next = t - value / gradient;
    if (!(next > t) || !(next < horizon)) return std::nullopt;
    const Scalar at_next = evaluate(p, next);
    if (at_next > 2 * evaluation_error(p, next)) {
      t = next;
      value = at_next;
      continue;
    }
    // Within rounding of 0, or below it: the root lies after t, where p is certainly above 0.
    Scalar high = next, at_high = at_next;
    Scalar reach = 2 * std::numeric_limits<Scalar>::epsilon() * next +
                   2 * evaluation_error(p, next) / std::fabs(evaluate(slope, next));
    for (int probe = 0; probe < 8 && !(at_high < -2 * evaluation_error(p, high)); ++probe, reach *= 2) {
      high = next + reach;
      if (!(high < horizon)) return std::nullopt;
      at_high = evaluate(p, high);
    }
    if (!(at_high < -2 * evaluation_error(p, high))) return std::nullopt;
    return Bracket<Scalar>{t, high, value, at_high, next};
  }
  return std::nullopt;
}

/// Whether p stays above what rounding can tell from 0 on all of [0, horizon], shown by the Bernstein
/// coefficients of p(horizon s) on s in [0, 1] and, where those fall short, on its halves, quarters and
/// eighths. Rounding moves the coefficients and their halving by at most 11 ε S (S = Σ |c_k| horizon^k),
/// and p's evaluation by at most 8 ε S (evaluation_error); the margin, 64 (ε S + the smallest subnormal),
/// exceeds both, so that where this holds the exact p exceeds 16 ε S on [0, horizon], p as evaluated
/// stays above its evaluation error there, and earliest_contact's search would find no contact either.
template <typename Scalar>
[[nodiscard]] bool stays_above(const EventPolynomial<Scalar>& p, Scalar horizon) noexcept {
  std::array<Scalar, 5> a{};  // a_k = c_k horizon^k
  Scalar power = 1, size = 0;
  for (int k = 0; k <= p.degree; ++k) {
    a[static_cast<std::size_t>(k)] = p.c[static_cast<std::size_t>(k)] * power;
    size += std::fabs(a[static_cast<std::size_t>(k)]);
    power *= horizon;
  }
  // Sums of two coefficients must not overflow (and a NaN or an infinity fails every comparison).
  if (!(size <= std::numeric_limits<Scalar>::max() / 4)) return false;
  const Scalar margin =
      Scalar(64) * (std::numeric_limits<Scalar>::epsilon() * size + std::numeric_limits<Scalar>::denorm_min());
  // b_i = Σ_k C(i, k)/C(4, k) a_k.
  const std::array<Scalar, 5> b{a[0], a[0] + a[1] / 4, a[0] + a[1] / 2 + a[2] / 6,
                                a[0] + Scalar(0.75) * a[1] + a[2] / 2 + a[3] / 4, a[0] + a[1] + a[2] + a[3] + a[4]};
  return bernstein_above(b, margin, 3);
}

/// Whether p stays above its rounding on [0, horizon] by the plainest bound: c0 less every negative term
/// at the horizon exceeds (4 d + 4) ε Σ |c_k| horizon^k (each term c_k t^k on [0, horizon] is at least
/// its value at the horizon where negative, at least 0 elsewhere; the margin exceeds the bound's own
/// rounding).
template <typename Scalar>
[[nodiscard]] bool above_by_terms(const EventPolynomial<Scalar>& p, Scalar horizon) noexcept {
  Scalar lowest = p.c[0], size = std::fabs(p.c[0]), power = 1;
  for (int k = 1; k <= p.degree; ++k) {
    power *= horizon;
    const Scalar term = p.c[static_cast<std::size_t>(k)] * power;
    if (term < 0) lowest += term;
    size += std::fabs(term);
  }
  return lowest > Scalar(4 * p.degree + 4) * std::numeric_limits<Scalar>::epsilon() * size;
}

/// Whether bodies that touch at 0 (p.c[0] = 0) and separate (p.c[1] > 0) stay apart on (0, horizon]:
/// p = t q with q = c1 + c2 t + … exactly, and q stays above its rounding on [0, horizon]
/// (above_by_terms, else its Bernstein coefficients: stays_above), so that p has no root there.
template <typename Scalar>
[[nodiscard]] bool separates_for_good(const EventPolynomial<Scalar>& p, Scalar horizon) noexcept {
  if (!(p.c[0] == 0 && p.c[1] > 0 && horizon > 0)) return false;
  EventPolynomial<Scalar> q{{p.c[1], p.c[2], p.c[3], p.c[4], 0}, p.degree - 1};
  return above_by_terms(q, horizon) || stays_above(q, horizon);
}
}  // namespace detail

/// The earliest time t in [0, horizon] at which the bodies whose contact polynomial is `c` (c[k] the
/// coefficient of t^k: contact_polynomial, cushion_polynomial, or any polynomial of degree at most 4
/// that is negative where they overlap) come into contact while approaching; empty when they do not.
///
/// - At t = 0 a contact is reported only where the bodies touch or overlap (c[0] ≤ 0) and approach: the
///   first of c[1], c[2], … that is not zero is negative. Bodies that touch while separating, or at exact
///   tangency (c[0] = c[1] = 0, c[2] > 0), have none there. Bodies that touch and separate (c[0] = 0 <
///   c[1]: a pair just after its contact) are shown apart on all of (0, horizon] at once where the
///   polynomial over t stays above its rounding there (detail::separates_for_good).
/// - Later, a contact is the first t where the polynomial, with its coefficients exactly as given,
///   reaches 0 from above: a root where it decreases, or a graze, a root where it touches 0 and rises
///   again (likewise at the horizon). This is decided exactly: a contact is reported if and only if
///   that polynomial reaches 0 in (0, horizon]. Where rounding decides it (p at a turning point or at the
///   horizon farther from 0 than twice its rounding error, 2 d ε Σ |c_k| t^k, detail::evaluation_error),
///   the search runs in the type; where rounding leaves it open, it is decided in exact arithmetic
///   (detail::exact: Sturm's sequence with integer-mantissa coefficients), which returns the largest
///   value of the type at or before the exact root. A quadratic falling at 0 whose root in closed form
///   lands within a value of the type of the exact one has it placed exactly (detail::placed_quadratic_root).
///   The time returned is never after the bodies start to overlap by more than rounding can tell.
/// - The polynomial's degree is what its coefficients make it: a zero leading coefficient lowers it, and
///   nothing divides by one.
///
/// Expects finite coefficients and a finite horizon ≥ 0 (billiards::checked::earliest_contact checks
/// them). Always ends: in at most a few hundred evaluations in the type, and where the exact decision
/// runs, in a few hundred exact ones (each allocating at most a few kilobytes; failing to allocate
/// them terminates, as the function is noexcept).
template <typename Scalar, std::size_t N>
[[nodiscard]] std::optional<Scalar> earliest_contact(const std::array<Scalar, N>& c, Scalar horizon) noexcept {
  static_assert(N >= 1 && N <= 5, "earliest_contact: a polynomial of degree at most 4");
  static_assert(std::is_floating_point_v<Scalar>, "earliest_contact: float or double coefficients");
  detail::EventPolynomial<Scalar> p;
  for (std::size_t k = 0; k < N; ++k) p.c[k] = c[k];
  p.degree = static_cast<int>(N) - 1;
  p = detail::trimmed(p);
  if (p.degree < 1) return std::nullopt;  // a constant: nothing changes
  // Touching or overlapping now: a contact iff the first non-zero change is an approach; touching and
  // separating, none later where p / t stays above its rounding.
  if (p.c[0] <= 0) {
    for (int k = 1; k <= p.degree; ++k) {
      if (p.c[static_cast<std::size_t>(k)] != 0) {
        if (p.c[static_cast<std::size_t>(k)] < 0) return Scalar(0);
        break;
      }
    }
    if (detail::separates_for_good(p, horizon)) return std::nullopt;
  } else if (detail::above_by_terms(p, horizon)) {
    // No contact where the polynomial stays above its rounding on all of [0, horizon].
    return std::nullopt;
  }
  if (!(horizon > 0)) return std::nullopt;
  if (p.degree == 2 && p.c[0] > 0 && p.c[1] < 0) {
    // A quadratic falling at 0: its first root from the closed form, placed exactly where that is shown
    // at once.
    if (const Scalar t = detail::placed_quadratic_root(p, horizon); !std::isnan(t)) return t;
  }
  const detail::EventPolynomial<Scalar> slope = detail::derivative(p);
  // The root of p in (a, b) where p falls from left > 0 to right < 0, found by the type's search; one the
  // type places only to more than 16 ulps (the rounding of p over its slope there, as at a near graze
  // that touches) placed exactly; and not t = 0 where the bodies are apart at 0 (a root below the
  // smallest step of the type).
  const auto root_between = [&](Scalar a, Scalar b, Scalar left, Scalar right) {
    Scalar t = detail::sign_change(p, slope, a, b, left, right);
    const Scalar ulp = detail::next_up(t) - t;
    if (!(detail::evaluation_error(p, t) <= 16 * ulp * std::fabs(detail::evaluate(slope, t))))
      t = detail::placed_root(p, slope, a, b, t);
    return t > 0 ? t : std::numeric_limits<Scalar>::denorm_min();
  };
  if (p.c[0] > 0 && p.degree >= 3) {
    // Apart now and, by its Bernstein coefficients, all the way to the horizon: no contact to search for.
    if (detail::stays_above(p, horizon)) return std::nullopt;
    // Convex and falling at 0 (up to the horizon, or up to a point past the first root): Newton's steps
    // from 0 bracket the first root without the turning points. Concave and not rising at 0, below 0 at the horizon beyond rounding: it falls throughout, and its
    // one root lies in (0, horizon).
    int curvature = detail::curvature_on(p, horizon);
    Scalar convex_end = horizon;
    if (curvature <= 0 && p.c[1] < 0) {
      // Not shown convex all the way to the horizon (a long window, over which the relative motion turns):
      // convex up to twice its Taylor quadratic's root is enough, where the first root lies before that.
      if (p.c[2] > 0) {
        const Scalar near_end = 2 * detail::falling_quadratic_root(p.c[0], p.c[1], p.c[2]);
        if (near_end < horizon && detail::curvature_on(p, near_end) > 0) {
          convex_end = near_end;
          curvature = 1;
        }
      }
    }
    if (curvature > 0 && p.c[1] < 0) {
      if (const auto bracket = detail::convex_first_root(p, slope, convex_end)) {
        // Where p's rounding over its slope at the bracket's upper end spans more than 8 values of the
        // type (bodies far apart, whose polynomial's terms cancel at the root), the type's search could
        // not place the root closer than that: it is placed exactly from the bracket at once.
        const Scalar high = bracket->high;
        if (detail::evaluation_error(p, high) >
            8 * (detail::next_up(high) - high) * std::fabs(detail::evaluate(slope, high))) {
          const Scalar t = detail::placed_root(p, slope, bracket->low, high, bracket->estimate);
          return t > 0 ? t : std::numeric_limits<Scalar>::denorm_min();
        }
        return root_between(bracket->low, high, bracket->at_low, bracket->at_high);
      }
    } else if (curvature < 0 && p.c[1] <= 0) {
      const Scalar at_horizon = detail::evaluate(p, horizon);
      if (at_horizon < -2 * detail::evaluation_error(p, horizon))
        return root_between(Scalar(0), horizon, p.c[0], at_horizon);
    }
  }
  // The turning points of p in (0, horizon) split it into monotone pieces; walk them in order.
  std::array<Scalar, 6> breaks{};
  breaks[0] = 0;
  const int turns = detail::sign_changes(slope, Scalar(0), horizon, breaks.data() + 1);
  breaks[static_cast<std::size_t>(turns + 1)] = horizon;
  Scalar left = p.c[0];  // exact at t = 0; at each later break, beyond twice its rounding of 0
  for (int i = 0; i <= turns; ++i) {
    const Scalar a = breaks[static_cast<std::size_t>(i)], b = breaks[static_cast<std::size_t>(i + 1)];
    const Scalar right = detail::evaluate(p, b);
    if (std::fabs(right) <= 2 * detail::evaluation_error(p, b)) {
      // p at the turning point (or the horizon) within twice its rounding of 0: its sign there, certified,
      // says whether p reaches 0 by b where p falls into b from above 0.
      if (left > 0 && detail::certified_sign(p, b) <= 0) {
        const Scalar t = detail::placed_root(p, slope, a, b, b);
        return t > 0 ? t : std::numeric_limits<Scalar>::denorm_min();  // a root below the smallest step
      }
      // At the horizon, p falling to a value above 0: no contact by it.
      if (left > 0 && i == turns) return std::nullopt;
      // A turning point just above 0 (a graze or a near miss: the exact minimum lies beside it), or p
      // rising out of an overlap to within rounding of 0: Sturm's sequence in exact arithmetic decides.
      return detail::exact::earliest_contact_after_zero(c, horizon);
    }
    if (left > 0 && right < 0) return root_between(a, b, left, right);
    left = right;
  }
  return std::nullopt;
}

namespace checked {

/// billiards::earliest_contact with its arguments validated: every coefficient finite, the horizon
/// finite and ≥ 0. Throws billiards::invalid_argument naming the argument ("c[2]", "horizon").
template <typename Scalar, std::size_t N>
[[nodiscard]] std::optional<Scalar> earliest_contact(const std::array<Scalar, N>& c, Scalar horizon) {
  constexpr const char* function = "billiards::checked::earliest_contact";
  for (std::size_t k = 0; k < N; ++k) {
    if (!std::isfinite(c[k])) {
      throw invalid_argument(function, "c[" + std::to_string(k) + "]", detail::to_text(c[k]),
                             "a finite coefficient");
    }
  }
  if (!(horizon >= 0) || !std::isfinite(horizon))
    throw invalid_argument(function, "horizon", detail::to_text(horizon), "a time >= 0, finite");
  return billiards::earliest_contact(c, horizon);
}

}  // namespace checked

}  // namespace billiards
