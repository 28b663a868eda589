#include "prove/rounding.hpp"

#include "prove/gappa.hpp"

#include "core/output_files.hpp"
#include "core/powers_of_two.hpp"
#include "print/printer.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace billiards::derive {

using GiNaC::ex;

namespace {

// A proof that cannot be written: the reason.
struct NotProvable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string text(const GiNaC::numeric& n) {
  std::ostringstream out;
  out << n;
  return out.str();
}

// A number in Gappa's notation, exactly: an integer, p/q, or for a power of two 1bk.
std::string gappa_number(const GiNaC::numeric& n) {
  if (n.is_positive() && (n > 1024 || n < 1)) {
    if (const std::optional<int> k = exact_binary_logarithm(n)) return "1b" + std::to_string(*k);
  }
  if (n.is_integer() && GiNaC::abs(n) > 1024) {
    // A large multiple of a power of two as Gappa writes it, pbk: 3 · 2^1021 is 3b1021.
    GiNaC::numeric odd = n;
    int k = 0;
    while ((odd / 2).is_integer()) {
      odd /= 2;
      ++k;
    }
    const std::string dyadic = text(odd) + "b" + std::to_string(k);
    return n.is_negative() ? "(" + dyadic + ")" : dyadic;
  }
  if (n.is_integer()) return n.is_negative() ? "(" + text(n) + ")" : text(n);
  // A dyadic number p/2^k as Gappa writes it, pb-k.
  if (const std::optional<int> k = exact_binary_logarithm(n.denom())) {
    const std::string dyadic = text(n.numer()) + "b" + std::to_string(-*k);
    return n.is_negative() ? "(" + dyadic + ")" : dyadic;
  }
  return "(" + text(n.numer()) + "/" + text(n.denom()) + ")";
}

// An end of an interval, which Gappa wants as a bare number: -2, not (-2).
std::string interval_end(const std::string& number) {
  if (number.size() > 2 && number.front() == '(' && number.back() == ')' &&
      number.find('/') == std::string::npos)
    return number.substr(1, number.size() - 2);
  if (number.find('/') != std::string::npos)
    throw NotProvable("the bound " + number + " is not a dyadic number, which Gappa wants");
  return number;
}

// The largest finite number, (2^digits − 1) 2^(max_exponent − digits), exactly.
std::string largest_finite(const BinaryFormat& format) {
  return text(GiNaC::numeric(2).power(format.digits) - 1) + "b" +
         std::to_string(format.max_exponent - format.digits);
}
std::string smallest_normal_number(const BinaryFormat& format) {
  return "1b" + std::to_string(format.min_exponent - 1);
}
std::string smallest_subnormal(const BinaryFormat& format) {
  return "1b" + std::to_string(format.min_exponent - format.digits);
}

// A Gappa dyadic number as printed in its results (-864691128455134979b-110, 1b-53, 0) as a rational.
std::optional<GiNaC::numeric> dyadic_value(const std::string& word) {
  const std::size_t b = word.find('b');
  try {
    const GiNaC::numeric mantissa(word.substr(0, b).c_str());
    if (b == std::string::npos) return mantissa;
    return mantissa * GiNaC::numeric(2).power(std::stoi(word.substr(b + 1)));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// The ends of the interval in a result line of Gappa's, `… in [low {…}, high {…}]`.
std::optional<std::pair<GiNaC::numeric, GiNaC::numeric>> interval_ends(const std::string& line) {
  const std::size_t open = line.find(" in [");
  const std::size_t close = line.rfind(']');
  if (open == std::string::npos || close == std::string::npos || close < open) return std::nullopt;
  std::string inside;
  int braces = 0;
  for (const char c : line.substr(open + 5, close - open - 5)) {
    braces += c == '{' ? 1 : c == '}' ? -1 : 0;
    if (braces == 0 && c != '}' && c != ' ') inside += c;
  }
  const std::size_t comma = inside.find(',');
  if (comma == std::string::npos) return std::nullopt;
  const std::optional<GiNaC::numeric> low = dyadic_value(inside.substr(0, comma)),
                                      high = dyadic_value(inside.substr(comma + 1));
  if (!low || !high) return std::nullopt;
  return std::make_pair(*low, *high);
}

// The larger magnitude of the interval in a result line of Gappa's.
std::optional<GiNaC::numeric> interval_magnitude(const std::string& line) {
  const auto ends = interval_ends(line);
  if (!ends) return std::nullopt;
  return std::max(GiNaC::abs(ends->first), GiNaC::abs(ends->second));
}

// ⌊log2 x⌋ of a positive rational.
int floor_binary_logarithm(const GiNaC::numeric& x) {
  int k = static_cast<int>(x.numer().int_length()) - static_cast<int>(x.denom().int_length());
  const GiNaC::numeric two(2);
  while (two.power(k) > x) --k;
  while (two.power(k + 1) <= x) ++k;
  return k;
}

// The exponent k with every x of [low, high] in ±[2^k, 2^(k+1)): binary_exponent's value over it.
std::optional<int> one_binade(const GiNaC::numeric& low, const GiNaC::numeric& high) {
  if (!(low.is_positive() || high.is_negative())) return std::nullopt;
  const GiNaC::numeric small = low.is_positive() ? low : -high, large = low.is_positive() ? high : -low;
  const int k = floor_binary_logarithm(small);
  if (large >= GiNaC::numeric(2).power(k + 1)) return std::nullopt;
  return k;
}

// A positive rational's size as a power of two, for messages: about 2^k.
std::string interval_text(const GiNaC::numeric& n) {
  return "about 2^" + std::to_string(n.numer().int_length() - n.denom().int_length());
}

// ---- the kernel as Gappa reads it ------------------------------------------------------------------

// Names in the script: a parameter p_x, a step as computed c_x, the same step in exact arithmetic e_x.
class Script {
 public:
  Script(const CppFunction& printed, const Kernel& kernel, const BinaryFormat& format,
         const std::vector<ex>& case_ranges)
      : printed_(printed), kernel_(kernel), format_(format) {
    for (const auto& parameter : printed.parameters) parameters_.insert(parameter.second);
    hypotheses_ = intervals(kernel_.domain);
    const std::vector<std::string> more = intervals(case_ranges);
    hypotheses_.insert(hypotheses_.end(), more.begin(), more.end());
  }

  // The domain's and the case's hypotheses.
  const std::vector<std::string>& hypotheses() const { return hypotheses_; }
  // Each exact scaling by a power of two the definitions wrote, as computed.
  const std::set<std::string>& scalings() const { return scalings_; }

  // Whether `e` calls `callee` anywhere.
  static bool calls(const CppExpression& e, const std::string& callee) {
    if (e.kind == CppExpression::Kind::call && e.text == callee) return true;
    for (const CppExpression& operand : e.operands)
      if (calls(operand, callee)) return true;
    return false;
  }

  // An expression of the printed kernel, rounded (each operation, as `rnd=` does) or exact.
  std::string expression(const CppExpression& e, bool exact) const {
    using Kind = CppExpression::Kind;
    switch (e.kind) {
      case Kind::name:
        if (parameters_.count(e.text)) return "p_" + e.text;
        if (const auto integer = integer_steps_.find(e.text); integer != integer_steps_.end())
          return gappa_number(integer->second);
        if (steps_.count(e.text)) return (exact ? "e_" : "c_") + e.text;
        throw NotProvable("reads " + e.text + ", which is no parameter or earlier step");
      case Kind::unary:
        if (e.text == "-") return "-(" + expression(e.operands[0], exact) + ")";
        break;
      case Kind::binary:
        if (e.text == "+" || e.text == "-" || e.text == "*" || e.text == "/")
          return "(" + expression(e.operands[0], exact) + " " + e.text + " " +
                 expression(e.operands[1], exact) + ")";
        break;
      case Kind::call: {
        if (e.text == "Scalar" && e.operands.size() == 1 && e.operands[0].kind == Kind::literal)
          return e.operands[0].text;  // an exact decimal (the read-back has checked it)
        if (const std::optional<ex> constant = named_constant_spelled(e.text)) {
          const std::optional<GiNaC::numeric> value = value_in(*constant, format_);
          if (!value) throw NotProvable("reads " + spelled(e) + ", which is not a finite number");
          return gappa_number(*value);
        }
        if (e.text == "absolute_value" && e.operands.size() == 1) {
          const std::string argument = expression(e.operands[0], exact);
          absolutes_.insert(argument);
          return "|" + argument + "|";
        }
        // x = f 2^k split exactly: where x lies in one binade, ±[2^k, 2^(k+1)), its exponent is the
        // integer k, and the scaling by 2^k (correctly rounded) exact where its result is normal, which
        // the script then proves.
        if (e.text == "binary_exponent" && e.operands.size() == 1) return gappa_number(exponent_of(e));
        if (e.text == "times_power_of_two" && e.operands.size() == 2) {
          const std::optional<int> k = integer_value(e.operands[1]);
          if (!k) throw NotProvable(spelled(e) + " scales by an exponent the case does not fix");
          const std::string scaled = expression(e.operands[0], exact);
          if (*k == 0) return scaled;
          const std::string out = "(" + scaled + " * " + gappa_number(GiNaC::numeric(2).power(*k)) + ")";
          if (!exact) scalings_.insert(out);
          return out;
        }
        if (e.text == "std::sqrt" && e.operands.size() == 1)
          return "sqrt(" + expression(e.operands[0], exact) + ")";
        // a b + c rounded once: `rnd(...)` about the exact sum, which a `rnd=` line leaves as it is.
        if (e.text == "std::fma" && e.operands.size() == 3) {
          const CppExpression& addend = e.operands[2];
          const bool subtracted = addend.kind == Kind::unary && addend.text == "-";
          const std::string sum = expression(e.operands[0], exact) + " * " + expression(e.operands[1], exact) +
                                  (subtracted ? " - " + expression(addend.operands[0], exact)
                                              : " + " + expression(addend, exact));
          return exact ? "(" + sum + ")" : "rnd(" + sum + ")";
        }
        break;
      }
      default: break;
    }
    throw NotProvable(spelled(e) + " is outside the straight-line arithmetic Gappa proves");
  }

  // A relational of the case's ranges (in the parameters) as Gappa text.
  static std::string exact_text(const ex& e) {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return gappa_number(GiNaC::ex_to<GiNaC::numeric>(e));
    if (GiNaC::is_a<GiNaC::symbol>(e)) return "p_" + GiNaC::ex_to<GiNaC::symbol>(e).get_name();
    if (GiNaC::is_a<GiNaC::add>(e)) {
      // As C++ writes it, (a - b): the positive terms, then each negative one subtracted.
      std::vector<std::string> added, subtracted;
      for (const ex& term : e) {
        if (prints_negative(term)) {
          subtracted.push_back(exact_text(-term));
        } else {
          added.push_back(exact_text(term));
        }
      }
      std::sort(added.begin(), added.end());
      std::sort(subtracted.begin(), subtracted.end());
      std::string out = added.empty() ? "0" : "";
      for (const std::string& term : added) out += (out.empty() ? "" : " + ") + term;
      for (const std::string& term : subtracted) out += " - " + term;
      return "(" + out + ")";
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
      std::string out;
      for (const ex& factor : e) out += (out.empty() ? "" : " * ") + exact_text(factor);
      return "(" + out + ")";
    }
    if (GiNaC::is_a<GiNaC::power>(e) && e.op(1).info(GiNaC::info_flags::integer)) {
      const int n = GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_int();
      std::string base = exact_text(e.op(0)), out = base;
      for (int i = 1; i < std::abs(n); ++i) out += " * " + base;
      return n > 0 ? "(" + out + ")" : "(1 / (" + out + "))";
    }
    if (GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "abs")
      return "|" + exact_text(e.op(0)) + "|";
    throw NotProvable("the range of " + print(e, Notation::text) + " has no Gappa form");
  }

  // A bound of a range in the type: a number, or one made of named constants (their values in the
  // type); nothing when `bound` reads anything else.
  std::optional<GiNaC::numeric> constant_value(const ex& bound) const {
    if (GiNaC::is_a<GiNaC::numeric>(bound)) return GiNaC::ex_to<GiNaC::numeric>(bound);
    if (is_named_constant(bound)) {
      const std::optional<GiNaC::numeric> value = value_in(bound, format_);
      if (!value)
        throw NotProvable("the domain's bound " + print(bound, Notation::text) + " is not a finite number");
      return value;
    }
    if (GiNaC::is_a<GiNaC::add>(bound) || GiNaC::is_a<GiNaC::mul>(bound) ||
        (GiNaC::is_a<GiNaC::power>(bound) && bound.op(1).info(GiNaC::info_flags::integer))) {
      std::vector<GiNaC::numeric> values;
      for (const ex& operand : bound) {
        const std::optional<GiNaC::numeric> value = constant_value(operand);
        if (!value) return std::nullopt;
        values.push_back(*value);
      }
      if (GiNaC::is_a<GiNaC::power>(bound)) return values[0].power(values[1]);
      GiNaC::numeric out = GiNaC::is_a<GiNaC::add>(bound) ? 0 : 1;
      for (const GiNaC::numeric& value : values) out = GiNaC::is_a<GiNaC::add>(bound) ? out + value : out * value;
      return out;
    }
    return std::nullopt;
  }

  // `low ≤ x`, `x ≤ high` and `x < 2^k` (the largest number of the type below 2^k) in `relationals`,
  // paired by x, as `x in [low, high]`; a parameter's interval is kept for binary_exponent.
  std::vector<std::string> intervals(const std::vector<ex>& relationals) {
    std::vector<std::pair<ex, std::pair<std::optional<GiNaC::numeric>, std::optional<GiNaC::numeric>>>> pairs;
    for (const ex& r : relationals) {
      const bool strict = GiNaC::is_a<GiNaC::relational>(r) && r.info(GiNaC::info_flags::relation_less);
      if (!GiNaC::is_a<GiNaC::relational>(r) ||
          !(strict || r.info(GiNaC::info_flags::relation_less_or_equal)))
        throw NotProvable(print(r, Notation::text) +
                          " is not a bound `a <= x`, `x <= b`, `x < 2^k` or `-2^k < x`");
      const bool lower = constant_value(r.lhs()).has_value();
      const ex quantity = lower ? r.rhs() : r.lhs();
      const std::optional<GiNaC::numeric> value = constant_value(lower ? r.lhs() : r.rhs());
      if (!value) throw NotProvable(print(r, Notation::text) + " bounds nothing by a constant");
      GiNaC::numeric bound = *value;
      if (strict) {
        // x < 2^k: x is at most the number of the type just below 2^k; −2^k < x, at least the one above.
        if ((lower ? bound.is_positive() : !bound.is_positive()) || !exact_binary_logarithm(GiNaC::abs(bound)))
          throw NotProvable(print(r, Notation::text) + " is strict but not `x < 2^k` or `-2^k < x`");
        bound -= bound * GiNaC::numeric(2).power(-format_.digits);
      }
      auto at =
          std::find_if(pairs.begin(), pairs.end(), [&](const auto& p) { return p.first.is_equal(quantity); });
      if (at == pairs.end()) {
        pairs.push_back({quantity, {}});
        at = pairs.end() - 1;
      }
      (lower ? at->second.first : at->second.second) = bound;
    }
    std::vector<std::string> out;
    for (const auto& [quantity, ends] : pairs) {
      if (!ends.first || !ends.second)
        throw NotProvable(print(quantity, Notation::text) + " is bounded on one side only");
      if (GiNaC::is_a<GiNaC::symbol>(quantity))
        ranges_[GiNaC::ex_to<GiNaC::symbol>(quantity).get_name()] = {*ends.first, *ends.second};
      out.push_back(exact_text(quantity) + " in [" + interval_end(gappa_number(*ends.first)) + ", " +
                    interval_end(gappa_number(*ends.second)) + "]");
    }
    return out;
  }

  // The script's definitions: each parameter a number of the format, each step computed and exact, with
  // its guards taken as `taken` says; the outputs o_i and e_o_i. Collects the names to bound in `bounded`.
  // With `partial`, the script stops before the first step whose guards `taken` does not decide yet.
  std::string definitions(const std::vector<bool>& taken, std::vector<std::string>& bounded,
                          std::vector<std::pair<std::string, std::string>>& outputs, bool partial = false) {
    std::ostringstream out;
    out << "@rnd = " << gappa_rounding(format_.digits, format_.min_exponent) << ";\n";
    for (const auto& parameter : printed_.parameters)
      out << "p_" << parameter.second << " = rnd(input_" << parameter.second << ");\n";
    std::size_t guard = 0;
    using Kind = CppStatement::Kind;
    for (std::size_t i = 0; i < printed_.body.size(); ++i) {
      const CppStatement& s = printed_.body[i];
      if (s.kind == Kind::declaration) {
        CppExpression value = *s.value;
        // Its guards, each taken or not: the value is the last taken one's.
        for (std::size_t j = i + 1; j < printed_.body.size() && printed_.body[j].kind == Kind::if_;
             ++j, ++guard) {
          if (guard >= taken.size()) {
            if (partial) return out.str();
            throw NotProvable("a guard without a decision");
          }
          if (taken[guard]) value = *printed_.body[j].body.at(0).value;
        }
        fix_exponents(value, out.str());
        // An exponent is an integer the case fixes, not a number whose digits count.
        if (const std::optional<int> k = integer_value(value)) {
          integer_steps_[s.name] = *k;
          continue;
        }
        // A fused multiply-add is rounded once, as its own `rnd(…)` says: the whole step, never a part of one.
        const bool fused = value.kind == CppExpression::Kind::call && value.text == "std::fma";
        for (const CppExpression& operand : fused ? value.operands : std::vector<CppExpression>{value}) {
          if (calls(operand, "std::fma"))
            throw NotProvable("std::fma inside " + spelled(value) + ": only a whole step may be one");
        }
        out << "c_" << s.name << (fused ? " = " : " rnd= ") << expression(value, false) << ";\n";
        out << "e_" << s.name << " = " << expression(value, true) << ";\n";
        steps_.insert(s.name);
        bounded.push_back("c_" + s.name);
      } else if (s.kind == Kind::return_) {
        std::vector<CppExpression> values = s.value->kind == CppExpression::Kind::braced
                                                ? s.value->operands
                                                : std::vector<CppExpression>{*s.value};
        for (std::size_t k = 0; k < values.size(); ++k) {
          fix_exponents(values[k], out.str());
          // An output that is a step is that step (Gappa would rename a copy); any other, o_k.
          std::string name = values[k].kind == CppExpression::Kind::name ? values[k].text : "";
          if (calls(values[k], "std::fma")) throw NotProvable("an output that is a std::fma: make it a step");
          if (name.empty() || !steps_.count(name)) {
            name = "o_" + std::to_string(k);
            out << "c_" << name << " rnd= " << expression(values[k], false) << ";\n";
            out << "e_" << name << " = " << expression(values[k], true) << ";\n";
            bounded.push_back("c_" + name);
          }
          outputs.emplace_back(spelled(values[k]), name);
        }
      } else if (s.kind != Kind::if_) {
        throw NotProvable("a statement outside straight-line code");
      }
    }
    return out.str();
  }

  // The guards in order: their conditions' two sides as computed, and the operator.
  std::vector<const CppExpression*> guard_conditions() const {
    std::vector<const CppExpression*> out;
    for (const CppStatement& s : printed_.body) {
      if (s.kind == CppStatement::Kind::if_) out.push_back(&*s.condition);
    }
    return out;
  }

  // The goal that says guard `condition` is taken (or not), on the computed values: for floats a and b,
  // a < b exactly when b − a is at least the smallest subnormal number, and a ≤ b when b − a ≥ 0.
  // Each side is computed as the header computes it, rounded: `g_a rnd= …;`, `g_b rnd= …;` come first
  // (returned in `sides`).
  std::string decision_goal(const CppExpression& condition, bool taken, std::string& sides) const {
    if (condition.kind != CppExpression::Kind::binary) throw NotProvable("the guard " + spelled(condition));
    std::string op = condition.text;
    sides = "g_a rnd= " + expression(condition.operands[0], false) +
            ";\ng_b rnd= " + expression(condition.operands[1], false) + ";\n";
    std::string a = "g_a", b = "g_b";
    if (op == ">" || op == ">=") {
      std::swap(a, b);
      op = op == ">" ? "<" : "<=";
    }
    if (op != "<" && op != "<=") throw NotProvable("the guard " + spelled(condition));
    // taken: a < b (b − a ≥ tiny) or a ≤ b (b − a ≥ 0); not taken: a ≥ b (a − b ≥ 0) or a > b (a − b ≥ tiny).
    const bool strict = op == "<";
    if (taken) return b + " - " + a + " >= " + (strict ? smallest_subnormal(format_) : "0");
    return a + " - " + b + " >= " + (strict ? "0" : smallest_subnormal(format_));
  }

  // The integer an exponent expression is over the hypotheses: binary_exponent of a value in one binade
  // (fixed by fix_exponents), a step that is one, and sums, differences and negations of them; nothing
  // for any other expression.
  std::optional<int> integer_value(const CppExpression& e) const {
    using Kind = CppExpression::Kind;
    if (e.kind == Kind::call && e.text == "binary_exponent") return exponent_of(e);
    if (e.kind == Kind::name) {
      const auto integer = integer_steps_.find(e.text);
      if (integer == integer_steps_.end()) return std::nullopt;
      return integer->second;
    }
    if (e.kind == Kind::unary && e.text == "-") {
      const std::optional<int> k = integer_value(e.operands[0]);
      if (!k) return std::nullopt;
      return -*k;
    }
    if (e.kind == Kind::binary && (e.text == "+" || e.text == "-")) {
      const std::optional<int> a = integer_value(e.operands[0]), b = integer_value(e.operands[1]);
      if (!a || !b) return std::nullopt;
      return e.text == "+" ? *a + *b : *a - *b;
    }
    return std::nullopt;
  }

  // binary_exponent(x)'s value, fixed before by fix_exponents.
  int exponent_of(const CppExpression& call) const {
    const CppExpression& x = call.operands.at(0);
    const auto known = x.kind == CppExpression::Kind::name ? exponents_.find(x.text) : exponents_.end();
    if (known == exponents_.end())
      throw NotProvable("binary_exponent(" + spelled(x) + ") needs " + spelled(x) +
                        " a parameter or step in one binade, ±[2^k, 2^(k+1))");
    return known->second;
  }

  // Fixes the exponent of each name `e` takes binary_exponent of: for a parameter, from its range in the
  // hypotheses; for a step, from Gappa's enclosure of it as computed (`so_far` defines it). Either must
  // lie in one binade, or the exponent is left unknown (and exponent_of says so).
  void fix_exponents(const CppExpression& e, const std::string& so_far) {
    for (const CppExpression& operand : e.operands) fix_exponents(operand, so_far);
    if (e.kind != CppExpression::Kind::call || e.text != "binary_exponent" || e.operands.size() != 1 ||
        e.operands[0].kind != CppExpression::Kind::name || exponents_.count(e.operands[0].text))
      return;
    const std::string& x = e.operands[0].text;
    std::optional<std::pair<GiNaC::numeric, GiNaC::numeric>> range;
    if (const auto parameter = ranges_.find(x); parameter != ranges_.end()) {
      range = parameter->second;
    } else if (steps_.count(x)) {
      std::string hypotheses;
      for (const std::string& h : hypotheses_) hypotheses += (hypotheses.empty() ? "" : " /\\ ") + h;
      const GappaAnswer answer = run_gappa(so_far + "{ " + hypotheses + " -> c_" + x + " in ? }\n");
      const std::size_t at = answer.output.find("c_" + x + " in [");
      if (answer.proven && at != std::string::npos)
        range = interval_ends(answer.output.substr(at, answer.output.find('\n', at) - at));
    }
    if (!range) return;
    if (const std::optional<int> k = one_binade(range->first, range->second)) exponents_[x] = *k;
  }

  const CppFunction& printed_;
  const Kernel& kernel_;
  const BinaryFormat& format_;
  std::set<std::string> parameters_, steps_;
  std::map<std::string, int> integer_steps_;  ///< exponent steps: integers over the case
  std::map<std::string, int> exponents_;      ///< binary_exponent of each name, where fixed
  std::map<std::string, std::pair<GiNaC::numeric, GiNaC::numeric>> ranges_;  ///< each parameter's interval
  std::vector<std::string> hypotheses_;
  mutable std::set<std::string> absolutes_;  ///< the arguments of |…| in the definitions
  mutable std::set<std::string> scalings_;   ///< each exact scaling by 2^k (k ≠ 0) as computed
};

// The outputs of the script for `taken`: each as printed, and its name in the script.
std::vector<std::pair<std::string, std::string>> script_outputs(const CppFunction& printed,
                                                                const Kernel& kernel,
                                                                const BinaryFormat& format,
                                                                const std::vector<ex>& ranges,
                                                                const std::vector<bool>& taken) {
  Script script(printed, kernel, format, ranges);
  std::vector<std::string> bounded;
  std::vector<std::pair<std::string, std::string>> outputs;
  script.definitions(taken, bounded, outputs);
  return outputs;
}

}  // namespace

std::string gappa_script(const CppFunction& printed, const Kernel& kernel, const BinaryFormat& format,
                         const std::vector<ex>& case_ranges, const std::vector<bool>& guards_taken,
                         const std::vector<std::string>& hints) {
  Script script(printed, kernel, format, case_ranges);
  std::vector<std::string> bounded;
  std::vector<std::pair<std::string, std::string>> outputs;
  std::string out = script.definitions(guards_taken, bounded, outputs);
  // A plain form promises every digit over its domain: every intermediate a normal number. Elsewhere an
  // intermediate need only be finite (a fraction that leaves the normal range only chooses the form),
  // and each output, and each exact scaling, must be a normal number.
  std::vector<std::string> goals;
  const std::string normal = " in [" + smallest_normal_number(format) + ", " + largest_finite(format) + "]";
  std::set<std::string> must_be_normal;
  for (const auto& output : outputs) must_be_normal.insert("c_" + output.second);
  for (const std::string& name : bounded) {
    goals.push_back("|" + name + "|" +
                    (!kernel.domain.empty() || must_be_normal.count(name) ? normal
                                                                          : " <= " + largest_finite(format)));
  }
  for (const std::string& scaling : script.scalings()) goals.push_back("|" + scaling + "|" + normal);
  for (const auto& output : outputs)
    goals.push_back("(c_" + output.second + " - e_" + output.second + ") / e_" + output.second + " in ?");
  std::string hypotheses, wanted;
  for (const std::string& h : script.hypotheses()) hypotheses += (hypotheses.empty() ? "" : " /\\ ") + h;
  for (const std::string& g : goals) wanted += (wanted.empty() ? "" : "\n  /\\ ") + g;
  std::string hinted;
  for (const std::string& hint : hints) hinted += hint + "\n";
  return out + "{ " + hypotheses + "\n  -> " + wanted + " }\n" + hinted;
}

namespace {

// A bound for messages: ±2^k where it is a power of two, else the rational.
std::string bound_text(const GiNaC::numeric& n) {
  if (const std::optional<int> k = n.is_zero() ? std::nullopt : exact_binary_logarithm(GiNaC::abs(n)))
    return (n.is_negative() ? "-2^" : "2^") + std::to_string(*k);
  return text(n);
}

// The format a script's `@rnd` line rounds to, as (digits, exponent of the smallest subnormal number):
// Gappa's ieee_32 and ieee_64, or float<p, e, …>.
std::optional<std::pair<int, int>> stated_rounding(const std::string& script) {
  const std::size_t at = script.find("@rnd = float<");
  if (at == std::string::npos) return std::nullopt;
  const std::size_t end = script.find('>', at);
  const std::string inside = script.substr(at + 13, end == std::string::npos ? 0 : end - at - 13);
  if (inside == "ieee_32, ne") return std::make_pair(24, -149);
  if (inside == "ieee_64, ne") return std::make_pair(53, -1074);
  int digits = 0, exponent = 0;
  char mode[3] = {};
  if (std::sscanf(inside.c_str(), "%d, %d, %2s", &digits, &exponent, mode) == 3 && std::string(mode) == "ne")
    return std::make_pair(digits, exponent);
  return std::nullopt;
}

// The script's hypotheses `p_x in [a, b]`, by parameter (one may have more than one).
std::multimap<std::string, std::pair<GiNaC::numeric, GiNaC::numeric>> stated_ranges(const std::string& script) {
  std::multimap<std::string, std::pair<GiNaC::numeric, GiNaC::numeric>> out;
  const std::size_t open = script.rfind("\n{ "), arrow = script.find("\n  -> ", open);
  if (open == std::string::npos || arrow == std::string::npos) return out;
  const std::string hypotheses = script.substr(open + 3, arrow - open - 3);
  for (std::size_t at = 0; at < hypotheses.size();) {
    std::size_t end = hypotheses.find(" /\\ ", at);
    if (end == std::string::npos) end = hypotheses.size();
    const std::string h = hypotheses.substr(at, end - at);
    at = end + 4;
    const std::size_t in = h.find(" in [");
    if (h.rfind("p_", 0) != 0 || in == std::string::npos) continue;
    if (const auto ends = interval_ends(h)) out.emplace(h.substr(2, in - 2), *ends);
  }
  return out;
}

// What a script states, held against what the header prints: it rounds in the format of the kernel's
// Scalar instantiation (float or double, as the C++ implementation defines them: std::numeric_limits),
// and among its hypotheses is each interval `expected` gives a parameter.
void check_against_header(const std::string& script, const BinaryFormat& format,
                          const std::vector<std::pair<std::string, Intervals>>& expected) {
  const auto rounding = format.type == "float"
                            ? std::make_pair(std::numeric_limits<float>::digits,
                                             std::numeric_limits<float>::min_exponent -
                                                 std::numeric_limits<float>::digits)
                            : std::make_pair(std::numeric_limits<double>::digits,
                                             std::numeric_limits<double>::min_exponent -
                                                 std::numeric_limits<double>::digits);
  const std::optional<std::pair<int, int>> stated = stated_rounding(script);
  if (!stated || *stated != rounding)
    throw NotProvable("its " + format.type + " script rounds " +
                      (stated ? "to " + std::to_string(stated->first) + " digits down to 2^" +
                                    std::to_string(stated->second)
                              : std::string("in no format Gappa names")) +
                      ", not as " + format.type + " does: " + std::to_string(rounding.first) +
                      " digits down to 2^" + std::to_string(rounding.second));
  const auto ranges = stated_ranges(script);
  const auto shown = [](const std::pair<GiNaC::numeric, GiNaC::numeric>& interval) {
    return "[" + bound_text(interval.first) + ", " + bound_text(interval.second) + "]";
  };
  for (const auto& [source, intervals] : expected) {
    for (const auto& [parameter, interval] : intervals) {
      const auto [first, last] = ranges.equal_range(parameter);
      bool found = false;
      std::string states;
      for (auto at = first; at != last; ++at) {
        found = found || at->second == interval;
        states += (states.empty() ? "" : " and ") + shown(at->second);
      }
      if (!found)
        throw NotProvable("its " + format.type + " script states " +
                          (states.empty() ? "no range of " + parameter : parameter + " in " + states) + " where " +
                          source + " " + parameter + " in " + shown(interval));
    }
  }
}

// One format and one case: what Gappa proved (into `bounds`) or why not (into `problems`).
void prove_case(const CppFunction& printed, const Kernel& kernel, const BinaryFormat& format,
                const std::vector<ex>& ranges, const PrintedFacts& facts, std::vector<KernelProblem>& problems,
                std::vector<RoundingBound>& bounds) {
  const auto fail = [&](const std::string& reason) {
    problems.push_back({kernel.name, kernel.equals, "its rounding proof: " + reason});
  };
  do {
      try {
        // Each guard decided in turn: the domain and the case must say whether it is taken.
        Script probe(printed, kernel, format, ranges);
        std::vector<bool> taken;
        const std::vector<const CppExpression*> conditions = probe.guard_conditions();
        std::string hypotheses;
        for (const std::string& h : probe.hypotheses()) hypotheses += (hypotheses.empty() ? "" : " /\\ ") + h;
        for (const CppExpression* condition : conditions) {
          std::optional<bool> decided;
          for (const bool branch : {false, true}) {
            // The steps before the guarded one, as the guards decided so far make them.
            Script attempt(printed, kernel, format, ranges);
            std::vector<std::string> unused;
            std::vector<std::pair<std::string, std::string>> no_outputs;
            const std::string definitions = attempt.definitions(taken, unused, no_outputs, true);
            std::string sides;
            const std::string goal = attempt.decision_goal(*condition, branch, sides);
            if (run_gappa(definitions + sides + "{ " + hypotheses + " -> " + goal + " }\n").proven) {
              decided = branch;
              break;
            }
          }
          if (!decided)
            throw NotProvable("in " + format.type + ", the domain neither rules out nor in the guard " +
                              spelled(*condition));
          taken.push_back(*decided);
        }
        // |x| where the domain and the case fix x's sign, told to Gappa as x or −x.
        std::vector<std::string> hints;
        {
          Script signs(printed, kernel, format, ranges);
          std::vector<std::string> unused;
          std::vector<std::pair<std::string, std::string>> no_outputs;
          const std::string definitions = signs.definitions(taken, unused, no_outputs);
          for (const std::string& x : signs.absolutes_) {
            for (const bool negative : {true, false}) {
              const std::string goal = (negative ? "-" : "") + x + " >= 0";
              if (!run_gappa(definitions + "{ " + hypotheses + " -> " + goal + " }\n").proven) continue;
              hints.push_back("|" + x + "| -> " + (negative ? "-" : "") + x + " { " + goal + " };");
              break;
            }
          }
        }
        // The kernel's own: rewritings that tell Gappa how its steps' errors cancel.
        hints.insert(hints.end(), kernel.gappa_hints.begin(), kernel.gappa_hints.end());
        const std::string script = gappa_script(printed, kernel, format, ranges, taken, hints);
        std::vector<std::pair<std::string, Intervals>> expected;
        if (const auto guard = facts.guard.find(format.type); guard != facts.guard.end())
          expected.emplace_back("the printed guard admits", guard->second);
        if (const auto constants = facts.constants.find(format.type); constants != facts.constants.end())
          expected.emplace_back("the case's ranges, with the constants as printed, give",
                                intervals_of(ranges, constants->second, format));
        check_against_header(script, format, expected);
        const GappaAnswer answer = run_gappa(script);
        const std::string& output = answer.output;
        if (!answer.proven) {
          fail("in " + format.type + " over " + hypotheses +
               ", Gappa does not prove every intermediate and output finite and normal with a bounded "
               "error: " +
               gappa_failure(output));
          break;
        }
        RoundingBound bound{kernel.name, format.type, hypotheses, {}, {}, {}};
        const GiNaC::numeric epsilon = GiNaC::numeric(2).power(1 - format.digits);
        for (const auto& [spelling, name] : script_outputs(printed, kernel, format, ranges, taken)) {
          const std::string goal = "(c_" + name + " - e_" + name + ") / e_" + name + " in [";
          const std::size_t at = output.find(goal);
          const std::optional<GiNaC::numeric> largest =
              at == std::string::npos ? std::nullopt
                                      : interval_magnitude(output.substr(at, output.find('\n', at) - at));
          if (!largest) {
            fail("cannot read Gappa's bound of " + spelling + " in: " + output);
            break;
          }
          // Gappa answers `in ?` with what it can show, however wide: a bound of a digit or more is none.
          if (*largest >= GiNaC::numeric(1, 1024)) {
            fail("in " + format.type + " over " + hypotheses + ", Gappa bounds the relative error of " +
                 spelling + " only by " + interval_text(*largest) + ": it may lose every digit");
            break;
          }
          // A kernel that promises a bound must be proven within it.
          if (kernel.promised_error && *largest > epsilon * GiNaC::numeric(*kernel.promised_error)) {
            fail("in " + format.type + " over " + hypotheses + ", Gappa bounds the relative error of " + spelling +
                 " by " + interval_text(*largest) + ", above the " + std::to_string(*kernel.promised_error) +
                 " ε the kernel promises");
            break;
          }
          bound.outputs.push_back(spelling);
          bound.relative.push_back(*largest);
          bound.in_epsilons.push_back(std::ceil((*largest / epsilon).to_double() * 100) / 100);
        }
        if (bound.relative.size() != bound.outputs.size() || bound.outputs.empty()) break;
        bounds.push_back(std::move(bound));
      } catch (const std::exception& error) {
        fail(error.what());
      }
  } while (false);
}

// What a proof found, as text through a pipe: fields apart by 0x1f, records by 0x1e.
constexpr char field_end = '\x1f', record_end = '\x1e';

std::string serialized(const std::vector<KernelProblem>& problems, const std::vector<RoundingBound>& bounds) {
  std::ostringstream out;
  for (const KernelProblem& p : problems) out << 'P' << field_end << p.reason << record_end;
  for (const RoundingBound& b : bounds) {
    out << 'B' << field_end << b.hypotheses;
    for (std::size_t i = 0; i < b.outputs.size(); ++i)
      out << field_end << b.outputs[i] << field_end << b.relative[i] << field_end << b.in_epsilons[i];
    out << record_end;
  }
  return out.str();
}

void deserialize(const std::string& text, const Kernel& kernel, const BinaryFormat& format,
                 std::vector<KernelProblem>& problems, std::vector<RoundingBound>& bounds) {
  std::istringstream records(text);
  std::string record;
  while (std::getline(records, record, record_end)) {
    std::vector<std::string> fields;
    std::istringstream in(record);
    for (std::string field; std::getline(in, field, field_end);) fields.push_back(field);
    if (fields.size() == 2 && fields[0] == "P") {
      problems.push_back({kernel.name, kernel.equals, fields[1]});
    } else if (fields.size() >= 2 && fields[0] == "B" && (fields.size() - 2) % 3 == 0) {
      RoundingBound bound{kernel.name, format.type, fields[1], {}, {}, {}};
      for (std::size_t i = 2; i < fields.size(); i += 3) {
        bound.outputs.push_back(fields[i]);
        bound.relative.push_back(GiNaC::numeric(fields[i + 1].c_str()));
        bound.in_epsilons.push_back(std::stod(fields[i + 2]));
      }
      bounds.push_back(std::move(bound));
    }
  }
}

}  // namespace

Intervals intervals_of(const std::vector<ex>& relationals, const GiNaC::exmap& constants,
                       const BinaryFormat& format) {
  std::map<std::string, std::pair<std::optional<GiNaC::numeric>, std::optional<GiNaC::numeric>>> ends;
  for (ex relation : relationals) {
    if (!GiNaC::is_a<GiNaC::relational>(relation)) continue;
    using GiNaC::relational;
    if (relation.info(GiNaC::info_flags::relation_greater))
      relation = relational(relation.rhs(), relation.lhs(), relational::less);
    if (relation.info(GiNaC::info_flags::relation_greater_or_equal))
      relation = relational(relation.rhs(), relation.lhs(), relational::less_or_equal);
    const bool strict = relation.info(GiNaC::info_flags::relation_less);
    if (!strict && !relation.info(GiNaC::info_flags::relation_less_or_equal)) continue;
    const bool lower = GiNaC::is_a<GiNaC::symbol>(relation.rhs()) && !is_named_constant(relation.rhs());
    const ex parameter = lower ? relation.rhs() : relation.lhs();
    const ex bound = (lower ? relation.lhs() : relation.rhs()).subs(constants);
    if (!GiNaC::is_a<GiNaC::symbol>(parameter) || is_named_constant(parameter) || !GiNaC::is_a<GiNaC::numeric>(bound))
      continue;
    GiNaC::numeric value = GiNaC::ex_to<GiNaC::numeric>(bound);
    // x < c holds up to the largest number of the format below c (a power of two): c (1 − 2^−digits).
    if (strict) value -= value * GiNaC::numeric(2).power(-format.digits);
    auto& interval = ends[GiNaC::ex_to<GiNaC::symbol>(parameter).get_name()];
    (lower ? interval.first : interval.second) = value;
  }
  // Only a parameter bounded on both sides has an interval.
  Intervals out;
  for (const auto& [parameter, interval] : ends) {
    if (interval.first && interval.second) out[parameter] = {*interval.first, *interval.second};
  }
  return out;
}

std::vector<KernelProblem> prove_rounding_in(const CppFunction& printed, const Kernel& kernel,
                                             const BinaryFormat& format, std::vector<RoundingBound>& bounds) {
  std::vector<std::vector<ex>> cases = kernel.rounding_cases;
  if (cases.empty()) cases.push_back({});
  std::vector<KernelProblem> problems;
  for (const std::vector<ex>& ranges : cases) prove_case(printed, kernel, format, ranges, {}, problems, bounds);
  return problems;
}

std::vector<KernelProblem> prove_rounding(const CppFunction& printed, const Kernel& kernel,
                                          std::vector<RoundingBound>& bounds, const PrintedFacts& facts) {
  struct Job {
    const BinaryFormat* format;
    std::vector<ex> ranges;
    pid_t child = -1;
    int pipe = -1;
    std::string found;
  };
  ProofCache::instance();  // opened here, once, not in each process below
  std::vector<std::vector<ex>> cases = kernel.rounding_cases;
  if (cases.empty()) cases.push_back({});
  std::vector<Job> jobs;
  for (const BinaryFormat& format : emitted_formats()) {
    for (const std::vector<ex>& ranges : cases) jobs.push_back({&format, ranges, -1, -1, {}});
  }
  // Each format and case in a process of its own (GiNaC is not thread-safe; the work is Gappa's),
  // as many at once as there are processors; the results gathered in the order of the jobs.
  const long processors = std::max(1L, sysconf(_SC_NPROCESSORS_ONLN));
  std::vector<KernelProblem> problems;
  std::vector<RoundingBound> found;
  const auto finish = [&](Job& job) {
    char buffer[4096];
    for (ssize_t n; (n = read(job.pipe, buffer, sizeof buffer)) > 0;) job.found.append(buffer, static_cast<std::size_t>(n));
    close(job.pipe);
    int status = 0;
    waitpid(job.child, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
      job.found = std::string("P") + field_end + "its rounding proof: the proof's process failed" + record_end;
  };
  std::size_t next_to_finish = 0;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    Job& job = jobs[i];
    int ends[2];
    if (jobs.size() > 1 && pipe(ends) == 0) {
      std::fflush(nullptr);
      job.child = fork();
      if (job.child == 0) {
        close(ends[0]);
        std::vector<KernelProblem> p;
        std::vector<RoundingBound> b;
        prove_case(printed, kernel, *job.format, job.ranges, facts, p, b);
        const std::string text = serialized(p, b);
        for (std::size_t at = 0; at < text.size();) {
          const ssize_t n = write(ends[1], text.data() + at, text.size() - at);
          if (n <= 0) _exit(1);
          at += static_cast<std::size_t>(n);
        }
        _exit(0);
      }
      close(ends[1]);
      if (job.child > 0) {
        job.pipe = ends[0];
      } else {
        close(ends[0]);
      }
    }
    if (job.pipe < 0) {
      // No process to spare: proven here.
      std::vector<KernelProblem> p;
      std::vector<RoundingBound> b;
      prove_case(printed, kernel, *job.format, job.ranges, facts, p, b);
      job.found = serialized(p, b);
    }
    while (static_cast<long>(i + 1 - next_to_finish) >= processors) {
      if (jobs[next_to_finish].pipe >= 0) finish(jobs[next_to_finish]);
      ++next_to_finish;
    }
  }
  for (; next_to_finish < jobs.size(); ++next_to_finish) {
    if (jobs[next_to_finish].pipe >= 0) finish(jobs[next_to_finish]);
  }
  for (const Job& job : jobs) deserialize(job.found, kernel, *job.format, problems, found);
  bounds.insert(bounds.end(), found.begin(), found.end());
  return problems;
}

}  // namespace billiards::derive
