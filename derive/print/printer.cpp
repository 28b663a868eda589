#include "print/printer.hpp"

#include "core/named_constants.hpp"
#include "core/powers_of_two.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace billiards::derive {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

std::string ginac_print(const ex& e, Notation notation) {
  std::ostringstream out;
  if (notation == Notation::latex) {
    e.print(GiNaC::print_latex(out));
  } else {
    e.print(GiNaC::print_dflt(out));
  }
  return out.str();
}

std::string scalar_literal(const numeric& n) { return "Scalar(" + ginac_print(n, Notation::text) + ")"; }

// A term of a sum or a product, written as coefficient × factors.
struct Factor {
  ex base;
  numeric exponent;
};

struct Product {
  numeric coefficient = 1;
  std::vector<Factor> factors;
};

bool is_odd_integer(const numeric& n) { return n.is_integer() && n.is_odd(); }

Product as_product(const ex& e);

// The terms of a sum in print order: constants first, then by the text of their non-numeric part.
std::vector<Product> sorted_terms(const ex& sum);

// True when `sum` reads better negated: more negative terms than positive ones, or as many and the
// first term in print order negative. Either way the choice depends on the sum alone, not the run.
bool leads_negative(const ex& sum) {
  const std::vector<Product> terms = sorted_terms(sum);
  const auto negative =
      std::count_if(terms.begin(), terms.end(), [](const Product& p) { return p.coefficient.is_negative(); });
  const auto positive = static_cast<std::ptrdiff_t>(terms.size()) - negative;
  if (negative != positive) return negative > positive;
  return !terms.empty() && terms.front().coefficient.is_negative();
}

Product as_product(const ex& e) {
  Product product;
  const auto add_factor = [&](const ex& factor) {
    if (GiNaC::is_a<numeric>(factor)) {
      product.coefficient *= GiNaC::ex_to<numeric>(factor);
      return;
    }
    Factor f{factor, 1};
    if (GiNaC::is_a<GiNaC::power>(factor) && GiNaC::is_a<numeric>(factor.op(1))) {
      f = {factor.op(0), GiNaC::ex_to<numeric>(factor.op(1))};
    }
    // Orient every sum so that its first term is positive: (a − b)² and (b − a)² print alike.
    if (GiNaC::is_a<GiNaC::add>(f.base) && f.exponent.is_integer() && leads_negative(f.base)) {
      f.base = -f.base;  // a number times a sum distributes over its terms, nothing else changes
      if (is_odd_integer(f.exponent)) product.coefficient = -product.coefficient;
    }
    product.factors.push_back(f);
  };
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    for (const ex& factor : e) add_factor(factor);
  } else {
    add_factor(e);
  }
  return product;
}

std::string print_factor(const Factor& f, Notation notation);
std::string print_magnitude(const Product& p, Notation notation);

std::string key_of(const Product& p) {
  Product unit = p;
  unit.coefficient = 1;
  return print_magnitude(unit, Notation::text);
}

std::vector<Product> sorted_terms(const ex& sum) {
  std::vector<std::pair<std::string, Product>> keyed;
  for (const ex& term : sum) {
    Product p = as_product(term);
    keyed.emplace_back(p.factors.empty() ? std::string() : key_of(p), p);
  }
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Product> terms;
  for (auto& [key, p] : keyed) terms.push_back(p);
  return terms;
}

std::string print_sum(const ex& sum, Notation notation);

// In C++ a sum whose terms share a denominator q prints as (q × sum) / Scalar(q): (s - |s|) / 2
// rather than s / 2 - |s| / 2, one division instead of one per term.
std::string print_sum_over_common_denominator(const ex& sum) {
  numeric q = 1;
  for (const ex& term : sum) q = GiNaC::lcm(q, as_product(term).coefficient.denom());
  if (q == 1) return "";
  return "(" + print_sum((sum * q).expand(), Notation::cpp) + ") / " + scalar_literal(q);
}

std::string print_sum(const ex& sum, Notation notation) {
  if (notation == Notation::cpp) {
    const std::string over = print_sum_over_common_denominator(sum);
    if (!over.empty()) return over;
  }
  std::string out;
  bool first = true;
  std::vector<Product> terms = sorted_terms(sum);
  if (notation == Notation::cpp) {
    // In code, v2n - v1n reads better than -v1n + v2n: positive terms first, order otherwise kept.
    std::stable_partition(terms.begin(), terms.end(),
                          [](const Product& p) { return !p.coefficient.is_negative(); });
  }
  for (const Product& term : terms) {
    const bool negative = term.coefficient.is_negative();
    Product magnitude = term;
    magnitude.coefficient = GiNaC::abs(term.coefficient);
    const std::string body = print_magnitude(magnitude, notation);
    if (first) {
      out += negative ? "-" : "";
    } else if (notation != Notation::text) {
      out += negative ? " - " : " + ";
    } else {
      out += negative ? "-" : "+";
    }
    out += body;
    first = false;
  }
  return out;
}

std::string parenthesized(const std::string& inner, Notation notation) {
  return notation == Notation::latex ? "\\left(" + inner + "\\right)" : "(" + inner + ")";
}

std::string print_any(const ex& e, Notation notation);
std::string print_base(const ex& base, Notation notation, bool will_take_power);

std::string print_base(const ex& base, Notation notation, bool will_take_power) {
  const std::string inner = print_any(base, notation);
  const bool compound =
      GiNaC::is_a<GiNaC::add>(base) || GiNaC::is_a<GiNaC::mul>(base) || GiNaC::is_a<GiNaC::power>(base) ||
      (GiNaC::is_a<numeric>(base) && GiNaC::ex_to<numeric>(base).is_negative()) ||
      (will_take_power && GiNaC::is_a<numeric>(base) && !GiNaC::ex_to<numeric>(base).is_integer());
  return compound ? parenthesized(inner, notation) : inner;
}

std::string print_factor(const Factor& f, Notation notation) {
  if (f.exponent == 1) return print_base(f.base, notation, false);
  if (notation == Notation::cpp) {
    if (f.exponent == numeric(1, 2)) return "std::sqrt(" + print_any(f.base, notation) + ")";
    if (!f.exponent.is_pos_integer()) {
      throw std::invalid_argument("cannot emit the power " + print(pow(f.base, f.exponent), Notation::text) +
                                  " as C++: expected a positive integer exponent or 1/2");
    }
    // x² as x * x: no pow() in emitted code.
    const std::string base = print_base(f.base, notation, false);
    std::string product = base;
    for (numeric k = 1; k < f.exponent; k += 1) product += " * " + base;
    return product;
  }
  if (f.exponent == numeric(1, 2)) {
    const std::string inner = print_any(f.base, notation);
    return notation == Notation::latex ? "\\sqrt{" + inner + "}" : "sqrt(" + inner + ")";
  }
  const std::string base = print_base(f.base, notation, true);
  const std::string exponent = ginac_print(f.exponent, Notation::text);
  if (notation == Notation::latex) return base + "^{" + exponent + "}";
  return base + "^" + (f.exponent.is_integer() && f.exponent.is_positive() ? exponent : "(" + exponent + ")");
}

// True when `code` is one token or one parenthesised group, so that "/ code" divides by all of it.
bool is_one_group(const std::string& code) {
  if (code.find(' ') == std::string::npos) return true;
  if (code.front() != '(') return false;
  int depth = 0;
  for (std::size_t i = 0; i < code.size(); ++i) {
    depth += code[i] == '(' ? 1 : code[i] == ')' ? -1 : 0;
    if (depth == 0) return i + 1 == code.size();
  }
  return false;
}

// Whether n is 2^k for an integer k ≥ 1.
bool is_power_of_two_above_one(const numeric& n) { return exact_binary_logarithm(n).value_or(0) >= 1; }

// A positive p/2^k (k ≥ 0) as an exact decimal literal: 7/2 → Scalar(3.5), 1/4 → Scalar(0.25).
std::string dyadic_literal(const numeric& n) {
  numeric denominator = n.denom(), digits = n.numer();
  int places = 0;
  for (; denominator > 1; denominator /= 2, ++places) digits *= 5;
  std::string text = ginac_print(digits, Notation::text);
  if (places == 0) return "Scalar(" + text + ")";
  if (static_cast<int>(text.size()) <= places)
    text.insert(0, static_cast<std::size_t>(places + 1) - text.size(), '0');
  text.insert(text.size() - static_cast<std::size_t>(places), ".");
  return "Scalar(" + text + ")";
}

// A coefficient whose digits fit every Scalar (float's 24 bits), so that its literal is exact.
bool fits_float(const numeric& n) { return n.numer() < numeric(1 << 24) && n.denom() < numeric(1 << 24); }

// |p| in C++: coefficient and numerator factors, then one division per denominator factor, so that
// 2 m2 / (m1 + m2) is computed as written. A coefficient p/2^k prints as one exact literal, 7/2 as
// Scalar(3.5), and 2^k/q as a division by one, 2/7 as / Scalar(3.5): one rounding, and no product
// 7 x that overflows where 3.5 x would not. A factor 2^k whose k is not a number (a scaling by a
// power of two) wraps the rest: times_power_of_two(rest, k).
std::string print_magnitude_cpp(const Product& p) {
  ex scale = 0;
  Product rest;
  rest.coefficient = p.coefficient;
  for (const Factor& f : p.factors) {
    if (is_power_of_two_with_symbolic_exponent(f.base)) {
      scale += f.exponent * f.base.op(1);
    } else {
      rest.factors.push_back(f);
    }
  }
  if (!scale.is_zero())
    return "times_power_of_two(" + print_magnitude_cpp(rest) + ", " + print_any(scale, Notation::cpp) + ")";
  std::vector<std::string> numerator, denominator;
  for (const Factor& f : p.factors) {
    if (f.exponent.is_negative()) {
      const std::string factor = print_factor({f.base, -f.exponent}, Notation::cpp);
      denominator.push_back(is_one_group(factor) ? factor : "(" + factor + ")");
    } else {
      numerator.push_back(print_factor(f, Notation::cpp));
    }
  }
  std::sort(numerator.begin(), numerator.end());
  std::sort(denominator.begin(), denominator.end());
  const numeric top = GiNaC::abs(p.coefficient.numer()), bottom = p.coefficient.denom();
  if (bottom != 1 && is_power_of_two_above_one(bottom) && fits_float(top / bottom)) {
    numerator.insert(numerator.begin(), dyadic_literal(top / bottom));
  } else if (bottom != 1 && is_power_of_two_above_one(top) && fits_float(bottom / top)) {
    if (numerator.empty()) numerator.push_back(scalar_literal(1));
    denominator.push_back(dyadic_literal(bottom / top));
  } else {
    if (top != 1 || numerator.empty()) numerator.insert(numerator.begin(), scalar_literal(top));
    if (bottom != 1) denominator.push_back(scalar_literal(bottom));
  }
  std::string out;
  for (const std::string& part : numerator) out += (out.empty() ? "" : " * ") + part;
  for (const std::string& part : denominator) out += " / " + part;
  return out;
}

// |p| with numerator and denominator separated; the sign is the caller's.
std::string print_magnitude(const Product& p, Notation notation) {
  if (notation == Notation::cpp) return print_magnitude_cpp(p);
  std::vector<std::string> numerator, denominator;
  for (const Factor& f : p.factors) {
    if (f.exponent.is_negative()) {
      denominator.push_back(print_factor({f.base, -f.exponent}, notation));
    } else {
      numerator.push_back(print_factor(f, notation));
    }
  }
  std::sort(numerator.begin(), numerator.end());
  std::sort(denominator.begin(), denominator.end());
  const numeric top = GiNaC::abs(p.coefficient.numer()), bottom = p.coefficient.denom();
  if (top != 1 || numerator.empty()) numerator.insert(numerator.begin(), ginac_print(top, Notation::text));
  if (bottom != 1) denominator.insert(denominator.begin(), ginac_print(bottom, Notation::text));
  const std::string separator = notation == Notation::latex ? " " : "*";
  const auto join = [&](const std::vector<std::string>& parts) {
    std::string joined;
    for (const std::string& part : parts) joined += (joined.empty() ? "" : separator) + part;
    return joined;
  };
  if (denominator.empty()) return join(numerator);
  if (notation == Notation::latex) {
    // Inside \frac a lone sum needs no parentheses of its own.
    const auto strip = [](std::vector<std::string>& parts) {
      const std::string open = "\\left(", close = "\\right)";
      if (parts.size() == 1 && parts[0].rfind(open, 0) == 0 && parts[0].size() > open.size() + close.size() &&
          parts[0].compare(parts[0].size() - close.size(), close.size(), close) == 0) {
        const std::string inner = parts[0].substr(open.size(), parts[0].size() - open.size() - close.size());
        // Only when the outer pair encloses everything: no "\right)...\left(" in between at depth 0.
        int depth = 0;
        bool encloses = true;
        for (std::size_t i = 0; i < inner.size(); ++i) {
          if (inner.compare(i, open.size(), open) == 0) ++depth;
          if (inner.compare(i, close.size(), close) == 0 && --depth < 0) encloses = false;
        }
        if (encloses) parts[0] = inner;
      }
    };
    strip(numerator);
    strip(denominator);
    return "\\frac{" + join(numerator) + "}{" + join(denominator) + "}";
  }
  const std::string below = denominator.size() == 1 ? denominator.front() : "(" + join(denominator) + ")";
  return join(numerator) + "/" + below;
}

// Whether `sum` has as many negative terms as positive ones, so that either orientation reads alike.
bool is_balanced(const ex& sum) {
  const std::vector<Product> terms = sorted_terms(sum);
  const auto negative =
      std::count_if(terms.begin(), terms.end(), [](const Product& p) { return p.coefficient.is_negative(); });
  return 2 * negative == static_cast<std::ptrdiff_t>(terms.size());
}

std::string print_signed_product(const ex& e, Notation notation) {
  Product p = as_product(e);
  if (notation == Notation::cpp && p.coefficient.is_negative()) {
    // In code (v2 - v1) / d reads better than -((v1 - v2) / d): turn one balanced sum of odd power.
    for (Factor& f : p.factors) {
      if (GiNaC::is_a<GiNaC::add>(f.base) && is_odd_integer(f.exponent) && is_balanced(f.base)) {
        f.base = -f.base;
        p.coefficient = -p.coefficient;
        break;
      }
    }
  }
  Product magnitude = p;
  magnitude.coefficient = GiNaC::abs(p.coefficient);
  const std::string body = print_magnitude(magnitude, notation);
  if (!p.coefficient.is_negative()) return body;
  if (notation == Notation::cpp && body.find(' ') != std::string::npos) return "-(" + body + ")";
  return "-" + body;
}

std::string print_list(const ex& list, Notation notation) {
  std::string out;
  for (const ex& element : list) {
    out += (out.empty() ? "" : notation == Notation::latex ? ", \\; " : ", ") + print_any(element, notation);
  }
  return notation == Notation::latex ? "\\left[" + out + "\\right]" : "[" + out + "]";
}

std::string print_cpp_leaf(const ex& e) {
  if (GiNaC::is_a<numeric>(e)) {
    const numeric n = GiNaC::ex_to<numeric>(e);
    if (!n.is_rational()) {
      throw std::invalid_argument("cannot emit the number " + ginac_print(e, Notation::text) +
                                  " as C++: expected a rational");
    }
    const std::string magnitude =
        n.is_integer() ? scalar_literal(GiNaC::abs(n))
                       : scalar_literal(GiNaC::abs(n.numer())) + " / " + scalar_literal(n.denom());
    return n.is_negative() ? "-(" + magnitude + ")" : magnitude;
  }
  // The named constants, by identity: their C++ spelling is the emitted header's device-safe helper.
  if (e.is_equal(smallest_normal())) return "smallest_normal<Scalar>()";
  if (e.is_equal(infinity())) return "infinity<Scalar>()";
  if (e.is_equal(plain_mass_low())) return "plain_mass_low<Scalar>()";
  if (e.is_equal(plain_mass_high())) return "plain_mass_high<Scalar>()";
  if (e.is_equal(moderate_low())) return "moderate_low<Scalar>()";
  if (e.is_equal(moderate_high())) return "moderate_high<Scalar>()";
  if (GiNaC::is_a<GiNaC::symbol>(e)) return GiNaC::ex_to<GiNaC::symbol>(e).get_name();
  if (GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "binary_exponent") {
    // The emitted header defines binary_exponent(): the exponent as a Scalar, for host and device.
    return "binary_exponent(" + print_any(e.op(0), Notation::cpp) + ")";
  }
  if (GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "fused_multiply_add") {
    // a b + c rounded once, on host and device.
    return "std::fma(" + print_any(e.op(0), Notation::cpp) + ", " + print_any(e.op(1), Notation::cpp) + ", " +
           print_any(e.op(2), Notation::cpp) + ")";
  }
  if (GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "abs") {
    // The emitted header defines absolute_value(): constexpr, unlike std::abs before C++23.
    return "absolute_value(" + print_any(e.op(0), Notation::cpp) + ")";
  }
  throw std::invalid_argument("cannot emit " + print_any(e, Notation::text) +
                              " as C++: expected numbers, symbols, sums, products and powers");
}

// A power whose exponent is not a number, b^k: in C++ 2^k alone is times_power_of_two(Scalar(1), k) (a
// product's factor 2^k is printed as its scaling, print_magnitude_cpp); elsewhere b^(k).
std::string print_symbolic_power(const ex& e, Notation notation) {
  if (notation == Notation::cpp) {
    if (!is_power_of_two_with_symbolic_exponent(e))
      throw std::invalid_argument("cannot emit the power " + print_any(e, Notation::text) +
                                  " as C++: expected a positive integer exponent or 1/2");
    return "times_power_of_two(" + scalar_literal(1) + ", " + print_any(e.op(1), notation) + ")";
  }
  const std::string base = print_base(e.op(0), notation, true), exponent = print_any(e.op(1), notation);
  if (notation == Notation::latex) return base + "^{" + exponent + "}";
  return base + "^" + (GiNaC::is_a<GiNaC::symbol>(e.op(1)) ? exponent : "(" + exponent + ")");
}

// How deep print_any may go before it elides the rest: far beyond any expression a model derives, so
// that a message about a malformed expression is written rather than the stack overflowed.
constexpr int deepest_print = 500;

std::string print_nested(const ex& e, Notation notation);

std::string print_any(const ex& e, Notation notation) {
  thread_local int depth = 0;
  if (depth >= deepest_print) {
    if (notation == Notation::cpp)
      throw std::invalid_argument("cannot emit an expression nested " + std::to_string(deepest_print) + " deep");
    return "…";
  }
  ++depth;
  struct Leave {
    int& depth;
    ~Leave() { --depth; }
  } leave{depth};
  return print_nested(e, notation);
}

std::string print_nested(const ex& e, Notation notation) {
  if (GiNaC::is_a<GiNaC::power>(e) && !GiNaC::is_a<numeric>(e.op(1))) return print_symbolic_power(e, notation);
  if (GiNaC::is_a<GiNaC::add>(e)) return print_sum(e, notation);
  if (GiNaC::is_a<GiNaC::mul>(e) || GiNaC::is_a<GiNaC::power>(e)) return print_signed_product(e, notation);
  // A relation, in C++ a condition: lhs op rhs.
  if (GiNaC::is_a<GiNaC::relational>(e)) {
    const bool latex = notation == Notation::latex;
    const char* op = latex ? " = " : " == ";
    if (e.info(GiNaC::info_flags::relation_not_equal)) op = latex ? " \\neq " : " != ";
    if (e.info(GiNaC::info_flags::relation_less)) op = " < ";
    if (e.info(GiNaC::info_flags::relation_less_or_equal)) op = latex ? " \\leq " : " <= ";
    if (e.info(GiNaC::info_flags::relation_greater)) op = " > ";
    if (e.info(GiNaC::info_flags::relation_greater_or_equal)) op = latex ? " \\geq " : " >= ";
    return print_any(e.lhs(), notation) + op + print_any(e.rhs(), notation);
  }
  if (notation == Notation::cpp) return print_cpp_leaf(e);
  if (GiNaC::is_a<numeric>(e)) return ginac_print(e, notation);
  if (GiNaC::is_a<GiNaC::lst>(e)) return print_list(e, notation);
  if (GiNaC::is_a<GiNaC::function>(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    std::string arguments;
    for (const ex& argument : e) arguments += (arguments.empty() ? "" : ", ") + print_any(argument, notation);
    if (name == "abs") {
      // |−w| = |w|: orient the argument like any sum, so that it prints alike on every run.
      const ex w = GiNaC::is_a<GiNaC::add>(e.op(0)) && leads_negative(e.op(0)) ? ex(-e.op(0)) : e.op(0);
      const std::string inner = print_any(w, notation);
      return notation == Notation::latex ? "\\left|" + inner + "\\right|" : "abs(" + inner + ")";
    }
    if (name == "binary_exponent" && notation == Notation::latex)
      return "\\lfloor \\log_2 \\left|" + arguments + "\\right| \\rfloor";
    if (notation == Notation::latex) return "\\operatorname{" + name + "}\\left(" + arguments + "\\right)";
    return name + "(" + arguments + ")";
  }
  return ginac_print(e, notation);  // symbols: their name, or their TeX name
}

}  // namespace

std::string print(const ex& e, Notation notation) { return print_any(e, notation); }

bool prints_negative(const ex& e) {
  if (GiNaC::is_a<GiNaC::add>(e)) return sorted_terms(e).front().coefficient.is_negative();
  return as_product(e).coefficient.is_negative();
}

bool reads_negated(const ex& sum) { return GiNaC::is_a<GiNaC::add>(sum) && leads_negative(sum); }

ex expanded_form(const ex& e) {
  if (GiNaC::is_a<GiNaC::lst>(e)) {
    GiNaC::lst out;
    for (const ex& element : e) out.append(expanded_form(element));
    return out;
  }
  const ex numerator_denominator = GiNaC::normal(e).numer_denom();
  return numerator_denominator.op(0).expand() / numerator_denominator.op(1).expand();
}

ex factored_form(const ex& e) {
  if (GiNaC::is_a<GiNaC::lst>(e)) {
    GiNaC::lst out;
    for (const ex& element : e) out.append(factored_form(element));
    return out;
  }
  // factor() returns its irreducible factors in whatever collected form its algorithm produced, which
  // varies between runs; each factor expanded is unique up to sign, which print() fixes.
  const auto expanded_factors = [](const ex& polynomial) {
    const ex factored = GiNaC::factor(polynomial);
    if (!GiNaC::is_a<GiNaC::mul>(factored)) return factored.expand();
    ex product = 1;
    for (const ex& factor : factored) {
      if (GiNaC::is_a<GiNaC::power>(factor)) {
        product *= GiNaC::pow(factor.op(0).expand(), factor.op(1));
      } else {
        product *= factor.expand();
      }
    }
    return product;
  };
  const ex numerator_denominator = GiNaC::normal(e).numer_denom();
  return expanded_factors(numerator_denominator.op(0)) / expanded_factors(numerator_denominator.op(1));
}

}  // namespace billiards::derive
