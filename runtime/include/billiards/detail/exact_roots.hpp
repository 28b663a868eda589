// Exact root decisions for the event polynomials of billiards/events.hpp: numbers m 2^e with an integer m
// of any length (every float and double is one, and sums and products of them stay so), polynomials
// with such coefficients, Sturm sequences, and the earliest contact a polynomial holds, decided without
// rounding. billiards::earliest_contact calls it only where rounding leaves its answer open (a graze
// within the rounding of the polynomial, a sign change that rounding could undo), so that the answer is
// the one the coefficients, exactly as given, make. No dependency: integers as 32-bit limbs.
#pragma once

#include <billiards/kernel_support.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace billiards::detail::exact {

/// A natural number as 32-bit limbs, least significant first, without leading zero limbs (zero: none).
using Natural = std::vector<std::uint32_t>;

inline void trim(Natural& a) noexcept {
  while (!a.empty() && a.back() == 0) a.pop_back();
}

[[nodiscard]] inline int compare(const Natural& a, const Natural& b) noexcept {
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  for (std::size_t i = a.size(); i-- > 0;)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}

[[nodiscard]] inline Natural add(const Natural& a, const Natural& b) {
  const Natural& longer = a.size() >= b.size() ? a : b;
  const Natural& shorter = a.size() >= b.size() ? b : a;
  Natural sum(longer.size() + 1, 0);
  std::uint64_t carry = 0;
  for (std::size_t i = 0; i < longer.size(); ++i) {
    carry += std::uint64_t(longer[i]) + (i < shorter.size() ? shorter[i] : 0);
    sum[i] = static_cast<std::uint32_t>(carry);
    carry >>= 32;
  }
  sum[longer.size()] = static_cast<std::uint32_t>(carry);
  trim(sum);
  return sum;
}

/// a − b for a ≥ b.
[[nodiscard]] inline Natural subtract(const Natural& a, const Natural& b) {
  Natural difference(a.size(), 0);
  std::int64_t borrow = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::int64_t d = std::int64_t(a[i]) - (i < b.size() ? std::int64_t(b[i]) : 0) - borrow;
    borrow = d < 0 ? 1 : 0;
    if (d < 0) d += std::int64_t(1) << 32;
    difference[i] = static_cast<std::uint32_t>(d);
  }
  trim(difference);
  return difference;
}

[[nodiscard]] inline Natural multiply(const Natural& a, const Natural& b) {
  if (a.empty() || b.empty()) return {};
  Natural product(a.size() + b.size(), 0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::uint64_t carry = 0;
    for (std::size_t j = 0; j < b.size(); ++j) {
      carry += std::uint64_t(a[i]) * b[j] + product[i + j];
      product[i + j] = static_cast<std::uint32_t>(carry);
      carry >>= 32;
    }
    product[i + b.size()] = static_cast<std::uint32_t>(carry);
  }
  trim(product);
  return product;
}

/// a 2^bits.
[[nodiscard]] inline Natural shifted_left(const Natural& a, std::int64_t bits) {
  if (a.empty() || bits == 0) return a;
  const auto limbs = static_cast<std::size_t>(bits / 32);
  const int rest = static_cast<int>(bits % 32);
  Natural shifted(a.size() + limbs + 1, 0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::uint64_t wide = std::uint64_t(a[i]) << rest;
    shifted[i + limbs] |= static_cast<std::uint32_t>(wide);
    shifted[i + limbs + 1] |= static_cast<std::uint32_t>(wide >> 32);
  }
  trim(shifted);
  return shifted;
}

/// A number s m 2^e: s the sign (−1, 0, +1), m a natural number (odd unless the number is zero), e any
/// integer. Exact under +, − and ×.
class Dyadic {
 public:
  Dyadic() = default;

  /// The value of a finite float or double, exactly.
  template <typename Scalar>
  static Dyadic of(Scalar x) {
    static_assert(std::is_floating_point_v<Scalar>);
    Dyadic d;
    if (x == 0) return d;
    int exponent = 0;
    const Scalar fraction = std::frexp(std::fabs(x), &exponent);
    constexpr int digits = std::numeric_limits<Scalar>::digits;
    // fraction 2^digits is a whole number below 2^digits ≤ 2^64.
    const auto whole = static_cast<std::uint64_t>(std::ldexp(fraction, digits));
    d.sign_ = x < 0 ? -1 : 1;
    d.magnitude_ = {static_cast<std::uint32_t>(whole), static_cast<std::uint32_t>(whole >> 32)};
    trim(d.magnitude_);
    d.exponent_ = std::int64_t(exponent) - digits;
    d.normalise();
    return d;
  }

  /// The whole number n, exactly.
  static Dyadic of_integer(std::int64_t n) {
    Dyadic d;
    if (n == 0) return d;
    const std::uint64_t size = n < 0 ? std::uint64_t(0) - std::uint64_t(n) : std::uint64_t(n);
    d.sign_ = n < 0 ? -1 : 1;
    d.magnitude_ = {static_cast<std::uint32_t>(size), static_cast<std::uint32_t>(size >> 32)};
    trim(d.magnitude_);
    d.normalise();
    return d;
  }

  [[nodiscard]] int sign() const noexcept { return sign_; }
  [[nodiscard]] bool is_zero() const noexcept { return sign_ == 0; }

  [[nodiscard]] Dyadic operator-() const {
    Dyadic d = *this;
    d.sign_ = -d.sign_;
    return d;
  }

  friend Dyadic operator+(const Dyadic& a, const Dyadic& b) {
    if (a.is_zero()) return b;
    if (b.is_zero()) return a;
    const std::int64_t exponent = std::min(a.exponent_, b.exponent_);
    const Natural x = shifted_left(a.magnitude_, a.exponent_ - exponent);
    const Natural y = shifted_left(b.magnitude_, b.exponent_ - exponent);
    Dyadic sum;
    sum.exponent_ = exponent;
    if (a.sign_ == b.sign_) {
      sum.sign_ = a.sign_;
      sum.magnitude_ = add(x, y);
    } else {
      const int order = compare(x, y);
      if (order == 0) return Dyadic{};
      sum.sign_ = order > 0 ? a.sign_ : b.sign_;
      sum.magnitude_ = order > 0 ? subtract(x, y) : subtract(y, x);
    }
    sum.normalise();
    return sum;
  }

  friend Dyadic operator-(const Dyadic& a, const Dyadic& b) { return a + (-b); }

  friend Dyadic operator*(const Dyadic& a, const Dyadic& b) {
    if (a.is_zero() || b.is_zero()) return Dyadic{};
    Dyadic product;
    product.sign_ = a.sign_ * b.sign_;
    product.magnitude_ = multiply(a.magnitude_, b.magnitude_);
    product.exponent_ = a.exponent_ + b.exponent_;
    return product;  // odd times odd is odd: normal already
  }

 private:
  // Strips the factors of two from the magnitude into the exponent.
  void normalise() {
    trim(magnitude_);
    if (magnitude_.empty()) {
      sign_ = 0;
      exponent_ = 0;
      return;
    }
    std::size_t zero_limbs = 0;
    while (magnitude_[zero_limbs] == 0) ++zero_limbs;
    int zero_bits = 0;
    while (((magnitude_[zero_limbs] >> zero_bits) & 1u) == 0) ++zero_bits;
    if (zero_limbs == 0 && zero_bits == 0) return;
    Natural shifted(magnitude_.size() - zero_limbs, 0);
    for (std::size_t i = zero_limbs; i < magnitude_.size(); ++i) {
      std::uint64_t wide = magnitude_[i] >> zero_bits;
      if (zero_bits > 0 && i + 1 < magnitude_.size())
        wide |= std::uint64_t(magnitude_[i + 1]) << (32 - zero_bits);
      shifted[i - zero_limbs] = static_cast<std::uint32_t>(wide);
    }
    trim(shifted);
    magnitude_ = std::move(shifted);
    exponent_ += std::int64_t(zero_limbs) * 32 + zero_bits;
  }

  int sign_ = 0;
  Natural magnitude_;
  std::int64_t exponent_ = 0;
};

/// A polynomial with exact coefficients, by power, without zero leading coefficients (zero: none).
using Polynomial = std::vector<Dyadic>;

inline void trim(Polynomial& p) {
  while (!p.empty() && p.back().is_zero()) p.pop_back();
}

/// p(t), exactly.
[[nodiscard]] inline Dyadic evaluate(const Polynomial& p, const Dyadic& t) {
  Dyadic value;
  for (std::size_t k = p.size(); k-- > 0;) value = value * t + p[k];
  return value;
}

/// The sign of p(t): −1, 0 or +1.
[[nodiscard]] inline int sign_at(const Polynomial& p, const Dyadic& t) { return evaluate(p, t).sign(); }

[[nodiscard]] inline Polynomial derivative(const Polynomial& p) {
  Polynomial d;
  for (std::size_t k = 1; k < p.size(); ++k) d.push_back(Dyadic::of_integer(std::int64_t(k)) * p[k]);
  trim(d);
  return d;
}

/// A positive multiple of the remainder of a divided by b (b not zero): each step of the division
/// multiplies a by |lc(b)| > 0 before it subtracts a multiple of b, so that no fraction arises and every
/// sign of the true remainder is kept.
[[nodiscard]] inline Polynomial remainder(Polynomial a, const Polynomial& b) {
  const Dyadic& lead = b.back();
  const Dyadic size = lead.sign() < 0 ? -lead : lead;
  while (!a.empty() && a.size() >= b.size()) {
    const std::size_t shift = a.size() - b.size();
    const Dyadic factor = lead.sign() < 0 ? -a.back() : a.back();
    for (Dyadic& c : a) c = c * size;
    for (std::size_t k = 0; k < b.size(); ++k) a[k + shift] = a[k + shift] - factor * b[k];
    a.pop_back();  // the leading coefficient cancels exactly
    trim(a);
  }
  return a;
}

/// p's Sturm sequence p, p', −rem(p, p'), … (each a positive multiple of the textbook's, which keeps
/// every sign), ending at the last polynomial that is not zero.
[[nodiscard]] inline std::vector<Polynomial> sturm_sequence(const Polynomial& p) {
  std::vector<Polynomial> sequence{p, derivative(p)};
  while (!sequence.back().empty()) {
    Polynomial next = remainder(sequence[sequence.size() - 2], sequence.back());
    if (next.empty()) break;
    for (Dyadic& c : next) c = -c;
    sequence.push_back(std::move(next));
  }
  if (sequence.back().empty()) sequence.pop_back();
  return sequence;
}

/// The sign changes along the sequence at t, zeros skipped.
[[nodiscard]] inline int variations(const std::vector<Polynomial>& sequence, const Dyadic& t) {
  int count = 0, last = 0;
  for (const Polynomial& q : sequence) {
    const int sign = sign_at(q, t);
    if (sign == 0) continue;
    if (last != 0 && sign != last) ++count;
    last = sign;
  }
  return count;
}

/// The sign of Σ c_k t^k for the coefficients and t exactly as given (finite).
template <typename Scalar, std::size_t N>
[[nodiscard]] int sign_of_polynomial(const std::array<Scalar, N>& c, Scalar t) {
  Polynomial p;
  for (Scalar coefficient : c) p.push_back(Dyadic::of(coefficient));
  trim(p);
  return sign_at(p, Dyadic::of(t));
}

/// The value halfway between two non-negative finite floats or doubles a ≤ b by their bits (which order
/// as the values do for x ≥ 0): a or b once they are adjacent.
template <typename Scalar>
[[nodiscard]] Scalar bits_midpoint(Scalar a, Scalar b) noexcept {
  using Bits = kernels::BitsOf<Scalar>;
  const Bits x = std::bit_cast<Bits>(a), y = std::bit_cast<Bits>(b);
  return std::bit_cast<Scalar>(static_cast<Bits>(x + (y - x) / 2));
}

/// The earliest contact of billiards::earliest_contact after t = 0, for the polynomial with coefficients
/// `c` exactly as given (p = Σ c_k t^k, degree ≥ 1, not a contact at t = 0 by its rule): the first root
/// t_r in (0, horizon] that p reaches from above (p > 0 just before it), returned as the largest float or
/// double t ≤ t_r (p(t) ≥ 0 there, exactly; t_r itself where it is one), or the smallest positive one
/// where t_r lies below it; empty when there is none. Roots are counted with p's Sturm sequence at
/// floats or doubles, which isolates the first one to adjacent values.
template <typename Scalar, std::size_t N>
[[nodiscard]] std::optional<Scalar> earliest_contact_after_zero(const std::array<Scalar, N>& c,
                                                                Scalar horizon) {
  Polynomial p;
  for (Scalar coefficient : c) p.push_back(Dyadic::of(coefficient));
  trim(p);
  // Roots at 0 divided out: q has p's sign for t > 0 and q(0) ≠ 0.
  std::size_t zeros = 0;
  while (zeros < p.size() && p[zeros].is_zero()) ++zeros;
  Polynomial q(p.begin() + static_cast<std::ptrdiff_t>(zeros), p.end());
  if (q.size() < 2 || !(horizon > 0)) return std::nullopt;
  const std::vector<Polynomial> sequence = sturm_sequence(q);
  const auto point = [](Scalar t) { return Dyadic::of(t); };
  const int at_horizon = variations(sequence, point(horizon));
  const auto roots_up_to = [&](int variations_at_lo, Scalar t) {
    return variations_at_lo - (t == horizon ? at_horizon : variations(sequence, point(t)));
  };
  Scalar lo = 0;  // q(lo) ≠ 0, and no root in (0, lo] is a contact
  for (int root = 0; root < static_cast<int>(q.size()); ++root) {
    const int at_lo = variations(sequence, point(lo));
    if (at_lo - at_horizon <= 0) return std::nullopt;
    // The first root in (lo, horizon], isolated in (l, h] with l and h adjacent or h the root itself.
    Scalar l = lo, h = horizon;
    for (;;) {
      const Scalar middle = bits_midpoint(l, h);
      if (middle == l || middle == h) break;
      if (roots_up_to(at_lo, middle) >= 1) {
        h = middle;
      } else {
        l = middle;
      }
    }
    const int before = sign_at(q, point(l));
    const bool at_h = sign_at(q, point(h)) == 0;
    if (before > 0) {
      if (at_h) return h;
      return l > 0 ? l : std::numeric_limits<Scalar>::denorm_min();
    }
    // Reached from below (q < 0 before it): no contact; go on from past it.
    if (!at_h) {
      lo = h;
      continue;
    }
    // q(h) = 0: on from the next value up, unless a second root lies before it.
    const Scalar next = std::nextafter(h, std::numeric_limits<Scalar>::infinity());
    if (!(next <= horizon)) return std::nullopt;
    if (sign_at(q, point(next)) == 0 || roots_up_to(at_lo, next) > 1) {
      // Another root in (h, next): reached from above where q rises out of h (its first non-zero
      // derivative at h positive); h is then the largest value at or before it.
      Polynomial d = q;
      int after = 0;
      while (!d.empty() && after == 0) {
        d = derivative(d);
        after = d.empty() ? 0 : sign_at(d, point(h));
      }
      const bool second_at_next = sign_at(q, point(next)) == 0 && roots_up_to(at_lo, next) == 2;
      if (after > 0) return second_at_next ? next : h;
      // Below 0 after h: a root at next is reached from below too; on from the value after it.
      const Scalar past = std::nextafter(next, std::numeric_limits<Scalar>::infinity());
      if (!second_at_next || !(past <= horizon) || sign_at(q, point(past)) == 0 ||
          roots_up_to(at_lo, past) != 2)
        return std::nullopt;
      lo = past;
      continue;
    }
    lo = next;
  }
  return std::nullopt;
}

}  // namespace billiards::detail::exact
