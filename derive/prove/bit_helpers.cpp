#include "prove/bit_helpers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace billiards::derive {

const std::vector<std::string>& bit_helper_names() {
  static const std::vector<std::string> names = {"orders_as_bits", "bits_above", "larger", "binary_exponent",
                                                 "times_power_of_two"};
  return names;
}

namespace {

// Text the evaluator cannot run.
struct Unreadable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The printed functions run for one Scalar type, as C++ runs them: int arithmetic, unsigned arithmetic
// of Scalar's width (Bits), Scalar arithmetic rounded in Scalar, with C++'s usual conversions.
template <typename Scalar>
class Evaluator {
 public:
  using Bits = std::conditional_t<sizeof(Scalar) == 4, std::uint32_t, std::uint64_t>;
  struct Value {
    enum class Kind { integer, bits, scalar, boolean } kind = Kind::integer;
    long long integer = 0;
    Bits bits = 0;
    Scalar scalar = 0;
    bool boolean = false;
  };
  static Value of(Scalar x) { return {Value::Kind::scalar, 0, 0, x, false}; }
  static Value of_bits(Bits u) { return {Value::Kind::bits, 0, u, 0, false}; }
  static Value of_integer(long long i) { return {Value::Kind::integer, i, 0, 0, false}; }
  static Value of_boolean(bool b) { return {Value::Kind::boolean, 0, 0, 0, b}; }

  Evaluator(const std::vector<CppFunction>& functions, bool device) : device_(device) {
    for (const CppFunction& f : functions) by_name_[{f.name, f.specialization}] = &f;
  }

  Value call(const std::string& name, const std::vector<Value>& arguments) {
    const std::string type = sizeof(Scalar) == 4 ? "float" : "double";
    auto found = by_name_.find({name, type});
    if (found == by_name_.end()) found = by_name_.find({name, ""});
    if (found == by_name_.end()) throw Unreadable("calls " + name + ", which the header does not define");
    const CppFunction& f = *found->second;
    if (f.parameters.size() != arguments.size()) throw Unreadable(name + " called with another arity");
    if (++depth_ > 64) throw Unreadable(name + " calls itself without end");
    std::map<std::string, Value> frame;
    for (std::size_t i = 0; i < arguments.size(); ++i) frame[f.parameters[i].second] = arguments[i];
    const std::optional<Value> result = run(f.body, frame);
    --depth_;
    if (!result) throw Unreadable(name + " ends without a return");
    return *result;
  }

 private:
  static Scalar scalar_of(const Value& v) {
    switch (v.kind) {
      case Value::Kind::scalar: return v.scalar;
      case Value::Kind::integer: return static_cast<Scalar>(v.integer);
      case Value::Kind::bits: return static_cast<Scalar>(v.bits);
      case Value::Kind::boolean: return v.boolean ? Scalar(1) : Scalar(0);
    }
    return 0;
  }
  static long long integer_of(const Value& v) {
    switch (v.kind) {
      case Value::Kind::scalar:
        if (!(std::fabs(v.scalar) < Scalar(1e9))) throw Unreadable("an int from a Scalar out of int's range");
        return static_cast<long long>(v.scalar);
      case Value::Kind::integer: return v.integer;
      case Value::Kind::bits: return static_cast<long long>(v.bits);
      case Value::Kind::boolean: return v.boolean ? 1 : 0;
    }
    return 0;
  }
  static Bits bits_of(const Value& v) {
    if (v.kind == Value::Kind::scalar) throw Unreadable("static_cast of a Scalar to Bits");
    return v.kind == Value::Kind::bits ? v.bits : static_cast<Bits>(integer_of(v));
  }
  static bool truth(const Value& v) {
    switch (v.kind) {
      case Value::Kind::scalar: return v.scalar != 0;
      case Value::Kind::integer: return v.integer != 0;
      case Value::Kind::bits: return v.bits != 0;
      case Value::Kind::boolean: return v.boolean;
    }
    return false;
  }

  Value as_declared(const std::string& type, const Value& v) const {
    if (type.find("Scalar") != std::string::npos) return of(scalar_of(v));
    if (type.find("Bits") != std::string::npos) return of_bits(bits_of(v));
    if (type.find("int") != std::string::npos) return of_integer(integer_of(v));
    if (type.find("bool") != std::string::npos) return of_boolean(truth(v));
    if (type == "auto" || type == "const auto") return v;
    throw Unreadable("a declaration of type " + type);
  }

  // Runs statements; the returned value, or nothing when they end without a return.
  std::optional<Value> run(const std::vector<CppStatement>& body, std::map<std::string, Value>& frame) {
    std::vector<bool> skipping;  // the #if regions entered, and whether each is left out
    for (const CppStatement& s : body) {
      using Kind = CppStatement::Kind;
      if (s.kind == Kind::directive) {
        if (s.text == "if !defined(__CUDA_ARCH__)") {
          skipping.push_back(device_);
        } else if (s.text == "endif" && !skipping.empty()) {
          skipping.pop_back();
        } else {
          throw Unreadable("the directive #" + s.text);
        }
        continue;
      }
      if (std::find(skipping.begin(), skipping.end(), true) != skipping.end()) continue;
      switch (s.kind) {
        case Kind::declaration: frame[s.name] = as_declared(s.type, evaluate(*s.value, frame)); break;
        case Kind::alias:
          if (s.name != "Bits" || s.text != "BitsOf < Scalar >")
            throw Unreadable("the alias " + s.name + " = " + s.text);
          break;
        case Kind::assignment: {
          auto target = frame.find(s.name);
          if (target == frame.end() || s.op != "=") throw Unreadable("the assignment " + printed_again(s));
          target->second = evaluate(*s.value, frame);
          break;
        }
        case Kind::if_:
          if (truth(evaluate(*s.condition, frame))) {
            if (auto result = run(s.body, frame)) return result;
          }
          break;
        case Kind::block:
          if (auto result = run(s.body, frame)) return result;
          break;
        case Kind::return_: return evaluate(*s.value, frame);
        default: throw Unreadable("the statement " + printed_again(s));
      }
    }
    return std::nullopt;
  }

  Value evaluate(const CppExpression& e, std::map<std::string, Value>& frame) {
    using Kind = CppExpression::Kind;
    using limits = std::numeric_limits<Scalar>;
    switch (e.kind) {
      case Kind::literal:
        if (e.text.find_first_not_of("0123456789") != std::string::npos)
          throw Unreadable("the literal " + e.text);
        return of_integer(std::stoll(e.text));
      case Kind::name: {
        if (const auto found = frame.find(e.text); found != frame.end()) return found->second;
        if (e.text == "std::numeric_limits<Scalar>::digits") return of_integer(limits::digits);
        if (e.text == "std::numeric_limits<Scalar>::max_exponent") return of_integer(limits::max_exponent);
        if (e.text == "std::numeric_limits<Scalar>::min_exponent") return of_integer(limits::min_exponent);
        if (e.text == "std::numeric_limits<Scalar>::is_iec559") return of_boolean(limits::is_iec559);
        throw Unreadable("the name " + e.text);
      }
      case Kind::unary: {
        const Value v = evaluate(e.operands.at(0), frame);
        if (e.text == "!") return of_boolean(!truth(v));
        if (v.kind == Value::Kind::scalar) return of(-v.scalar);
        if (v.kind == Value::Kind::bits) return of_bits(static_cast<Bits>(-v.bits));
        return of_integer(-integer_of(v));
      }
      case Kind::conditional:
        return truth(evaluate(e.operands.at(0), frame)) ? evaluate(e.operands.at(1), frame)
                                                        : evaluate(e.operands.at(2), frame);
      case Kind::binary: return binary(e, frame);
      case Kind::call: return call_expression(e, frame);
      default: throw Unreadable(spelled(e));
    }
  }

  Value binary(const CppExpression& e, std::map<std::string, Value>& frame) {
    const std::string& op = e.text;
    if (op == "&&")
      return of_boolean(truth(evaluate(e.operands[0], frame)) && truth(evaluate(e.operands[1], frame)));
    if (op == "||")
      return of_boolean(truth(evaluate(e.operands[0], frame)) || truth(evaluate(e.operands[1], frame)));
    const Value a = evaluate(e.operands[0], frame), b = evaluate(e.operands[1], frame);
    if (op == "<<" || op == ">>") {
      const long long count = integer_of(b);
      if (count < 0 || count >= static_cast<long long>(8 * sizeof(Bits)))
        throw Unreadable("a shift by " + std::to_string(count));
      if (a.kind != Value::Kind::bits) throw Unreadable("a shift of a signed or Scalar value");
      return of_bits(static_cast<Bits>(op == "<<" ? a.bits << count : a.bits >> count));
    }
    const auto compare = [&](auto x, auto y) -> std::optional<Value> {
      if (op == "<") return of_boolean(x < y);
      if (op == "<=") return of_boolean(x <= y);
      if (op == ">") return of_boolean(x > y);
      if (op == ">=") return of_boolean(x >= y);
      if (op == "==") return of_boolean(x == y);
      if (op == "!=") return of_boolean(x != y);
      return std::nullopt;
    };
    if (a.kind == Value::Kind::scalar || b.kind == Value::Kind::scalar) {
      const Scalar x = scalar_of(a), y = scalar_of(b);
      if (auto c = compare(x, y)) return *c;
      if (op == "+") return of(x + y);
      if (op == "-") return of(x - y);
      if (op == "*") return of(x * y);
      if (op == "/") return of(x / y);
    } else if (a.kind == Value::Kind::bits || b.kind == Value::Kind::bits) {
      const Bits x = bits_of(a), y = bits_of(b);
      if (auto c = compare(x, y)) return *c;
      if (op == "+") return of_bits(static_cast<Bits>(x + y));
      if (op == "-") return of_bits(static_cast<Bits>(x - y));
      if (op == "*") return of_bits(static_cast<Bits>(x * y));
      if (op == "&") return of_bits(x & y);
      if (op == "|") return of_bits(x | y);
    } else {
      const long long x = integer_of(a), y = integer_of(b);
      if (auto c = compare(x, y)) return *c;
      if (op == "+") return of_integer(x + y);
      if (op == "-") return of_integer(x - y);
      if (op == "*") return of_integer(x * y);
      if (op == "/" && y != 0) return of_integer(x / y);
      if (op == "&") return of_integer(x & y);
    }
    throw Unreadable("the operator " + op + " in " + spelled(e));
  }

  Value call_expression(const CppExpression& e, std::map<std::string, Value>& frame) {
    const std::string& f = e.text;
    if (f == "sizeof" && e.operands.size() == 1 && e.operands[0].text == "Scalar")
      return of_integer(sizeof(Scalar));
    std::vector<Value> arguments;
    for (const CppExpression& operand : e.operands) arguments.push_back(evaluate(operand, frame));
    const auto one = [&]() -> const Value& {
      if (arguments.size() != 1) throw Unreadable(spelled(e) + ": expected one argument");
      return arguments[0];
    };
    if (f == "Scalar") return of(scalar_of(one()));
    if (f == "static_cast<Bits>") return of_bits(bits_of(one()));
    if (f == "static_cast<int>") return of_integer(integer_of(one()));
    if (f == "std::bit_cast<Bits>" || f == "std::bit_cast<Scalar>") {
      const Value& v = one();
      if (f == "std::bit_cast<Bits>" && v.kind == Value::Kind::scalar) {
        Bits u;
        std::memcpy(&u, &v.scalar, sizeof u);
        return of_bits(u);
      }
      if (f == "std::bit_cast<Scalar>" && v.kind == Value::Kind::bits) {
        Scalar x;
        std::memcpy(&x, &v.bits, sizeof x);
        return of(x);
      }
      throw Unreadable(spelled(e) + " of a value of another width");
    }
    if (f == "std::ilogb") return of_integer(std::ilogb(scalar_of(one())));
    if (f == "std::ldexp" && arguments.size() == 2)
      return of(std::ldexp(scalar_of(arguments[0]), static_cast<int>(integer_of(arguments[1]))));
    if ((f == "__builtin_huge_valf" && sizeof(Scalar) == 4) ||
        (f == "__builtin_huge_val" && sizeof(Scalar) == 8) || f == "std::numeric_limits<Scalar>::infinity")
      return of(std::numeric_limits<Scalar>::infinity());
    if (f == "std::numeric_limits<Scalar>::min") return of(std::numeric_limits<Scalar>::min());
    const std::string name =
        f.size() > 8 && f.compare(f.size() - 8, 8, "<Scalar>") == 0 ? f.substr(0, f.size() - 8) : f;
    return call(name, arguments);
  }

  bool device_;
  int depth_ = 0;
  std::map<std::pair<std::string, std::string>, const CppFunction*> by_name_;
};

template <typename Scalar>
std::string shown(Scalar x) {
  std::ostringstream out;
  out.precision(std::numeric_limits<Scalar>::max_digits10);
  out << x;
  return out.str();
}

template <typename Scalar>
bool same_bits(Scalar a, Scalar b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// ±s · 2^k for every exponent k of the format's finite numbers, subnormals included, for s = 1 and
// 2 − ε where the format holds them, and ±0, ±∞ and NaN.
template <typename Scalar>
std::vector<Scalar> every_exponent() {
  using limits = std::numeric_limits<Scalar>;
  std::vector<Scalar> values = {Scalar(0), -Scalar(0), limits::infinity(), -limits::infinity(),
                                limits::quiet_NaN()};
  for (int k = limits::min_exponent - limits::digits; k < limits::max_exponent; ++k) {
    for (const long double s : {1.0L, 2.0L - static_cast<long double>(limits::epsilon())}) {
      const long double exact = std::ldexp(s, k);
      const auto x = static_cast<Scalar>(exact);
      if (static_cast<long double>(x) != exact || !std::isfinite(x)) continue;
      values.push_back(x);
      values.push_back(-x);
    }
  }
  return values;
}

// The first wrong answer of each helper in one format and path: (helper, what it answered wrongly).
template <typename Scalar>
std::vector<std::pair<std::string, std::string>> wrong_answers(const std::vector<CppFunction>& functions,
                                                               const std::set<std::string>& helpers,
                                                               bool device) {
  using E = Evaluator<Scalar>;
  using limits = std::numeric_limits<Scalar>;
  E run(functions, device);
  std::vector<std::pair<std::string, std::string>> wrong;
  const auto attempt = [&](const std::string& helper, const auto& check) {
    if (!helpers.count(helper)) return;
    try {
      const std::string answer = check();
      if (!answer.empty()) wrong.emplace_back(helper, answer);
    } catch (const std::exception& error) {
      wrong.emplace_back(helper, std::string("cannot be run: ") + error.what());
    }
  };
  const std::vector<Scalar> xs = every_exponent<Scalar>();
  attempt("binary_exponent", [&]() -> std::string {
    for (const Scalar x : xs) {
      int exponent = 0;
      std::frexp(static_cast<long double>(x), &exponent);  // x = f 2^e, f in [1/2, 1): ⌊log2 |x|⌋ = e − 1
      const Scalar expected = x == 0 || !std::isfinite(x) ? Scalar(0) : Scalar(exponent - 1);
      const auto got = run.call("binary_exponent", {E::of(x)});
      if (got.kind != E::Value::Kind::scalar || !same_bits(got.scalar, expected))
        return "binary_exponent(" + shown(x) + ") is " + shown(got.scalar) + ", not " + shown(expected);
    }
    return "";
  });
  attempt("times_power_of_two", [&]() -> std::string {
    const int span = limits::max_exponent - limits::min_exponent + limits::digits + 2;
    std::vector<Scalar> ks;
    for (int k = -span; k <= span; ++k) ks.push_back(Scalar(k));
    for (const Scalar k :
         {limits::quiet_NaN(), limits::infinity(), -limits::infinity(), Scalar(1e6), Scalar(-1e6)})
      ks.push_back(k);
    for (const Scalar x : {Scalar(1), Scalar(-1.5), limits::denorm_min()}) {
      for (const Scalar k : ks) {
        // k clamped to [−4096, 4096], a NaN to −4096; x · 2^k in long double is exact, rounded once to
        // Scalar.
        const int clamped = !(k >= Scalar(-4096)) ? -4096 : k > Scalar(4096) ? 4096 : static_cast<int>(k);
        const auto expected = static_cast<Scalar>(std::ldexp(static_cast<long double>(x), clamped));
        const auto got = run.call("times_power_of_two", {E::of(x), E::of(k)});
        if (got.kind != E::Value::Kind::scalar || !same_bits(got.scalar, expected))
          return "times_power_of_two(" + shown(x) + ", " + shown(k) + ") is " + shown(got.scalar) + ", not " +
                 shown(expected);
      }
    }
    return "";
  });
  if (device) return wrong;  // the rest is host code
  attempt("orders_as_bits", [&]() -> std::string {
    const auto got = run.call("orders_as_bits", {});
    return got.kind == E::Value::Kind::boolean && got.boolean ? ""
                                                              : "orders_as_bits is false for an IEEE type";
  });
  attempt("larger", [&]() -> std::string {
    using Bits = typename E::Bits;
    const Bits top = std::numeric_limits<Bits>::max();
    const std::vector<Bits> us = {0, 1, 2, 3, top / 2, top / 2 + 1, top - 1, top, 0x7f800000U, 12345};
    for (const Bits a : us) {
      for (const Bits b : us) {
        const auto got = run.call("larger", {E::of_bits(a), E::of_bits(b)});
        if (got.kind != E::Value::Kind::bits || got.bits != (a > b ? a : b))
          return "larger(" + std::to_string(a) + ", " + std::to_string(b) + ") is " +
                 std::to_string(got.bits);
      }
    }
    return "";
  });
  attempt("bits_above", [&]() -> std::string {
    const int k = limits::max_exponent / 2 - 3;
    const std::vector<std::pair<Scalar, Scalar>> ranges = {
        {Scalar(1), Scalar(2)},
        {limits::min(), limits::max()},
        {std::ldexp(Scalar(1), -k), std::ldexp(Scalar(1), k)}};
    for (const auto& [low, high] : ranges) {
      std::vector<Scalar> tried = xs;
      for (const Scalar edge : {low, high}) {
        tried.push_back(edge);
        tried.push_back(std::nextafter(edge, Scalar(0)));
        tried.push_back(std::nextafter(edge, limits::infinity()));
      }
      const auto top = run.call("bits_above", {E::of(high), E::of(low)});
      for (const Scalar x : tried) {
        const auto got = run.call("bits_above", {E::of(x), E::of(low)});
        const bool inside = low <= x && x <= high;
        if (got.kind != E::Value::Kind::bits || top.kind != E::Value::Kind::bits ||
            (got.bits <= top.bits) != inside)
          return "bits_above(" + shown(x) + ", " + shown(low) + ") <= bits_above(" + shown(high) + ", " +
                 shown(low) + ") is " + (inside ? "false" : "true") + ", but " + shown(x) + " lies " +
                 (inside ? "inside" : "outside") + " [" + shown(low) + ", " + shown(high) + "]";
      }
    }
    return "";
  });
  return wrong;
}

}  // namespace

namespace {

void calls_in(const CppExpression& e, std::set<std::string>& out) {
  if (e.kind == CppExpression::Kind::call) {
    const std::size_t template_arguments = e.text.find('<');
    out.insert(e.text.substr(0, template_arguments));
  }
  for (const CppExpression& operand : e.operands) calls_in(operand, out);
}

void calls_in(const CppStatement& s, std::set<std::string>& out) {
  if (s.value) calls_in(*s.value, out);
  if (s.condition) calls_in(*s.condition, out);
  for (const CppStatement& inner : s.body) calls_in(inner, out);
}

// The text of `name`'s definitions (every specialisation) and of those of each function they call, in
// the order `functions` holds them: what a helper's answers depend on.
std::string text_of(const std::string& name, const std::vector<CppFunction>& functions) {
  std::set<std::string> wanted = {name};
  for (bool grew = true; grew;) {
    grew = false;
    for (const CppFunction& f : functions) {
      if (!wanted.count(f.name)) continue;
      std::set<std::string> calls;
      for (const CppStatement& s : f.body) calls_in(s, calls);
      for (const std::string& call : calls) grew = wanted.insert(call).second || grew;
    }
  }
  std::string text;
  for (const CppFunction& f : functions) {
    if (!wanted.count(f.name)) continue;
    text += f.result + " " + f.name + "<" + f.specialization + ">(";
    for (const auto& [type, parameter] : f.parameters) text += type + " " + parameter + ",";
    text += ")";
    for (const CppStatement& s : f.body)
      for (const std::string& token : s.tokens) text += token + " ";
    text += "\n";
  }
  return text;
}

}  // namespace

std::vector<KernelProblem> prove_bit_helpers(const std::vector<CppFunction>& functions) {
  // Each helper proven once a run for the same text (its own and its callees'), whichever header holds it.
  static std::map<std::string, std::vector<KernelProblem>> proven;
  std::vector<KernelProblem> problems;
  for (const std::string& helper : bit_helper_names()) {
    if (std::none_of(functions.begin(), functions.end(),
                     [&](const CppFunction& f) { return f.name == helper; }))
      continue;
    const std::string key = text_of(helper, functions);
    auto known = proven.find(key);
    if (known == proven.end()) {
      std::vector<KernelProblem> found;
      for (const bool device : {false, true}) {
        const auto add = [&](const std::string& type, const auto& wrong) {
          for (const auto& [name, answer] : wrong)
            found.push_back({name, "",
                             "as printed, in " + type + " (" + (device ? "the device path" : "on the host") +
                                 "): " + answer});
        };
        add("float", wrong_answers<float>(functions, {helper}, device));
        add("double", wrong_answers<double>(functions, {helper}, device));
      }
      known = proven.emplace(key, std::move(found)).first;
    }
    problems.insert(problems.end(), known->second.begin(), known->second.end());
  }
  return problems;
}

}  // namespace billiards::derive
