#include "prove/read_back.hpp"

#include "core/named_constants.hpp"
#include "core/powers_of_two.hpp"
#include "prove/bit_helpers.hpp"
#include "prove/cpp_reader.hpp"
#include "print/printer.hpp"

#include <algorithm>
#include <exception>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

namespace billiards::derive {

using GiNaC::ex;

namespace {

std::string symbol_name(const ex& e) { return GiNaC::ex_to<GiNaC::symbol>(e).get_name(); }

// A decimal literal d (digits, at most one point; no exponent, no suffix) as an exact rational.
std::optional<GiNaC::numeric> decimal_value(const std::string& text) {
  if (text.empty() || std::count(text.begin(), text.end(), '.') > 1) return std::nullopt;
  GiNaC::numeric value = 0, scale = 1;
  bool after_point = false;
  for (const char c : text) {
    if (c == '.') {
      after_point = true;
      continue;
    }
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + (c - '0');
    if (after_point) scale *= 10;
  }
  return value / scale;
}

// Whether a rational is exactly a float: an odd part below 2^24 and a power of two beside it.
bool exact_in_float(const GiNaC::numeric& n) {
  if (n.is_zero()) return true;
  GiNaC::numeric numerator = GiNaC::abs(n.numer()), denominator = n.denom();
  while (GiNaC::irem(numerator, 2).is_zero()) numerator /= 2;
  return numerator < GiNaC::numeric(1 << 24) && exact_binary_logarithm(denominator).has_value();
}

// A kernel expression read back into GiNaC: names from `names`, every number Scalar(d).
ex to_expression(const CppExpression& e, const std::map<std::string, ex>& names) {
  using Kind = CppExpression::Kind;
  const auto operand = [&](std::size_t i) { return to_expression(e.operands.at(i), names); };
  switch (e.kind) {
    case Kind::literal:
      throw CppReadError(e.line, "the bare literal " + e.text + ": every number in a kernel is Scalar(d)");
    case Kind::name: {
      const auto found = names.find(e.text);
      if (found == names.end())
        throw CppReadError(e.line, "reads " + e.text + ", which is no parameter or earlier step");
      return found->second;
    }
    case Kind::unary:
      if (e.text != "-") throw CppReadError(e.line, "the operator " + e.text + " in a kernel expression");
      return -operand(0);
    case Kind::binary: {
      const std::string& op = e.text;
      if (op == "+") return operand(0) + operand(1);
      if (op == "-") return operand(0) - operand(1);
      if (op == "*") return operand(0) * operand(1);
      if (op == "/") return operand(0) / operand(1);
      using GiNaC::relational;
      if (op == "<") return relational(operand(0), operand(1), relational::less);
      if (op == "<=") return relational(operand(0), operand(1), relational::less_or_equal);
      if (op == ">") return relational(operand(0), operand(1), relational::greater);
      if (op == ">=") return relational(operand(0), operand(1), relational::greater_or_equal);
      if (op == "==") return relational(operand(0), operand(1), relational::equal);
      if (op == "!=") return relational(operand(0), operand(1), relational::not_equal);
      throw CppReadError(e.line, "the operator " + op + " in a kernel expression");
    }
    case Kind::call: {
      const std::size_t arity = e.operands.size();
      if (e.text == "Scalar" && arity == 1 && e.operands[0].kind == Kind::literal) {
        const std::optional<GiNaC::numeric> value = decimal_value(e.operands[0].text);
        if (!value)
          throw CppReadError(e.line, "Scalar(" + e.operands[0].text + "): expected a decimal number");
        if (!exact_in_float(*value))
          throw CppReadError(e.line, "Scalar(" + e.operands[0].text + ") is not exact in float");
        return *value;
      }
      if (const std::optional<ex> constant = named_constant_spelled(e.text); constant && arity == 0)
        return *constant;
      if (e.text == "binary_exponent" && arity == 1) return binary_exponent(operand(0));
      if (e.text == "times_power_of_two" && arity == 2) return times_power_of_two(operand(0), operand(1));
      if (e.text == "absolute_value" && arity == 1) return GiNaC::abs(operand(0));
      if (e.text == "std::sqrt" && arity == 1) return GiNaC::sqrt(operand(0));
      // Its value: the product and the sum, exactly (rounding is for the proof of the bound to see).
      if (e.text == "std::fma" && arity == 3) return operand(0) * operand(1) + operand(2);
      throw CppReadError(e.line, "the call " + spelled(e) + " in a kernel expression");
    }
    case Kind::conditional:
    case Kind::braced:
    case Kind::index: break;
  }
  throw CppReadError(e.line, spelled(e) + " in a kernel expression");
}

bool same_expression(const ex& a, const ex& b) {
  try {
    return a.is_equal(b) || GiNaC::normal(a - b).is_zero();
  } catch (const std::exception&) {
    return false;
  }
}

// The same relational: the same operator and the same two sides.
bool same_relational(const ex& a, const ex& b) {
  if (!GiNaC::is_a<GiNaC::relational>(a) || !GiNaC::is_a<GiNaC::relational>(b)) return false;
  using GiNaC::info_flags;
  for (const unsigned op : {info_flags::relation_equal, info_flags::relation_not_equal,
                            info_flags::relation_less, info_flags::relation_less_or_equal,
                            info_flags::relation_greater, info_flags::relation_greater_or_equal}) {
    if (a.info(op) != b.info(op)) return false;
  }
  return same_expression(a.lhs(), b.lhs()) && same_expression(a.rhs(), b.rhs());
}

class ReadBack {
 public:
  ReadBack(const std::vector<CppFunction>& functions, const std::vector<Kernel>& kernels,
           const std::vector<Claim>& claims, std::vector<RoundingBound>& bounds,
           const std::function<bool(const std::string&)>& proves_rounding_of)
      : functions_(functions),
        kernels_(kernels),
        claims_(claims),
        bounds_(bounds),
        proves_rounding_of_(proves_rounding_of) {}

  std::vector<KernelProblem> run() {
    // The round trip: every statement printed again from what was read is the text it was read from,
    // so each expression proven below, and given to Gappa, groups and rounds as the header does.
    for (const CppFunction& f : functions_) {
      for (const CppStatement& s : f.body) {
        if (!reads_as_printed(s)) {
          std::string read;
          for (const std::string& token : s.tokens) read += (read.empty() ? "" : " ") + token;
          fail(f.name, "",
               "line " + std::to_string(s.line) + " `" + read + "` reads back as `" + printed_again(s) +
                   "`: the reader did not keep its grouping");
        }
      }
    }
    for (const Kernel& kernel : kernels_) {
      prove_kernel(kernel);
      if (kernel.fast_path) {
        prove_dispatch(kernel);
        prove_predicate(kernel);
      }
    }
    prove_constants();
    prove_absolute_value();
    // The bit helpers, run from their text over every exponent (bit_helpers.hpp).
    for (const std::string& helper : bit_helper_names()) {
      if (find(helper) != nullptr) proven(helper);
    }
    const std::vector<KernelProblem> helpers = prove_bit_helpers(functions_);
    problems_.insert(problems_.end(), helpers.begin(), helpers.end());
    for (const CppFunction& f : functions_) {
      const std::string key = f.name + (f.specialization.empty() ? "" : "<" + f.specialization + ">");
      if (!proven_.count(key))
        fail(f.name, "", "is printed but nothing reads it back and proves it");
    }
    return problems_;
  }

 private:
  void fail(const std::string& function, const std::string& claim, const std::string& reason) {
    problems_.push_back({function, claim, "as printed: " + reason});
  }

  const CppFunction* find(const std::string& name, const std::string& specialization = "") const {
    for (const CppFunction& f : functions_) {
      if (f.name == name && f.specialization == specialization) return &f;
    }
    return nullptr;
  }

  void proven(const std::string& name, const std::string& specialization = "") {
    proven_.insert(name + (specialization.empty() ? "" : "<" + specialization + ">"));
  }

  static std::vector<std::string> parameter_names(const Kernel& kernel) {
    std::vector<std::string> names;
    for (const ex& p : kernel.parameters) names.push_back(symbol_name(p));
    return names;
  }

  // The printed function's parameters are the kernel's, each a Scalar, in order.
  bool same_signature(const CppFunction& f, const Kernel& kernel, const std::vector<std::string>& names) {
    std::vector<std::string> printed;
    for (const auto& [type, name] : f.parameters) {
      if (type != "Scalar") {
        fail(f.name, kernel.equals, "its parameter " + name + " is a " + type + ", not a Scalar");
        return false;
      }
      printed.push_back(name);
    }
    if (printed != names) {
      std::string list;
      for (const std::string& n : printed) list += (list.empty() ? "" : ", ") + n;
      fail(f.name, kernel.equals, "takes (" + list + "), not the kernel's parameters in order");
      return false;
    }
    return true;
  }

  // ---- a kernel's steps ---------------------------------------------------------------------------
  void prove_kernel(const Kernel& kernel) {
    const std::string name = kernel.fast_path ? full_form_name(kernel) : kernel.name;
    const CppFunction* f = find(name);
    if (f == nullptr) {
      fail(name, kernel.equals, "the function is not in the header");
      return;
    }
    proven(name);
    if (!same_signature(*f, kernel, parameter_names(kernel))) return;
    Kernel printed;
    try {
      printed = kernel_from_text(*f, kernel);
    } catch (const std::exception& error) {
      fail(name, kernel.equals, error.what());
      return;
    }
    compare_with_form(name, printed, kernel);
    for (KernelProblem problem : validate_kernel(printed, claims_)) {
      problem.kernel = name;
      problem.reason = "as printed: " + problem.reason;
      problems_.push_back(problem);
    }
    // Where the kernel is a fast path's plain form, its domain proven safe from the same text.
    if ((!kernel.domain.empty() || !kernel.rounding_cases.empty()) &&
        (!proves_rounding_of_ || proves_rounding_of_(kernel.name) || proves_rounding_of_(name))) {
      const std::vector<KernelProblem> rounding = prove_rounding(*f, kernel, bounds_, printed_facts(kernel));
      problems_.insert(problems_.end(), rounding.begin(), rounding.end());
    }
  }

  // What the header prints that the proofs of `kernel` must state (rounding.hpp): where it is a fast
  // path's plain form, the intervals the printed range test admits, from its comparisons as printed; and
  // each named constant's value as the header prints it for the type.
  PrintedFacts printed_facts(const Kernel& kernel) {
    // The constants as printed are the header's, the same for every kernel: read once.
    if (printed_constants_.empty()) {
      for (const BinaryFormat& format : emitted_formats()) {
        GiNaC::exmap& values = printed_constants_[format.type];
        for (const auto& [spelling, constant] : named_constant_spellings()) {
          if (const std::optional<GiNaC::numeric> v =
                  printed_constant(spelling.substr(0, spelling.find('<')), format))
            values[constant] = *v;
        }
      }
    }
    PrintedFacts out;
    out.constants = printed_constants_;
    const auto guarded = std::find_if(kernels_.begin(), kernels_.end(), [&](const Kernel& k) {
      return k.fast_path && k.fast_path->kernel == kernel.name;
    });
    if (kernel.domain.empty() || guarded == kernels_.end()) return out;
    // A test that cannot be read so is left to prove_predicate, which refuses it.
    const CppFunction* predicate = find(guarded->fast_path->predicate);
    if (predicate == nullptr || predicate->body.empty() || !predicate->body.back().value) return out;
    std::map<std::string, ex> names;
    for (const ex& p : guarded->parameters) names[symbol_name(p)] = p;
    std::vector<const CppExpression*> terms;
    conjuncts(*predicate->body.back().value, terms);
    std::vector<ex> relationals;
    try {
      for (const CppExpression* term : terms) relationals.push_back(to_expression(*term, names));
    } catch (const std::exception&) {
      return out;
    }
    for (const BinaryFormat& format : emitted_formats())
      out.guard[format.type] = intervals_of(relationals, out.constants[format.type], format);
    return out;
  }

  // A named constant's value in `format` as the header prints it: its specialisation's literal for the
  // type, else its generic form's value; nothing when neither is printed or readable.
  std::optional<GiNaC::numeric> printed_constant(const std::string& name, const BinaryFormat& format) const {
    if (const CppFunction* special = find(name, format.type)) {
      if (special->body.size() == 1 && special->body[0].value &&
          special->body[0].value->kind == CppExpression::Kind::literal)
        return power_of_two_literal(special->body[0].value->text, format.type);
      return std::nullopt;
    }
    const CppFunction* generic = find(name);
    if (generic == nullptr) return std::nullopt;
    try {
      return generic_value(*generic, format);
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }

  // The kernel the text of `f` prints: the form's parameters, the printed steps and guards (each
  // guard's kind and claim from the form's step of the same name), the printed outputs.
  static Kernel kernel_from_text(const CppFunction& f, const Kernel& form) {
    Kernel printed = form;
    printed.steps.clear();
    printed.outputs.clear();
    printed.fast_path.reset();
    std::map<std::string, ex> names;
    for (const ex& p : form.parameters) names[symbol_name(p)] = p;
    bool returned = false;
    for (const CppStatement& s : f.body) {
      if (returned) throw CppReadError(s.line, "a statement after the return");
      using Kind = CppStatement::Kind;
      if (s.kind == Kind::declaration && (s.type == "const Scalar" || s.type == "Scalar")) {
        if (names.count(s.name)) throw CppReadError(s.line, "the name " + s.name + " is defined twice");
        const GiNaC::symbol step(s.name);
        printed.steps.push_back({step, to_expression(*s.value, names)});
        names[s.name] = step;
      } else if (s.kind == Kind::if_ && s.type.empty() && s.body.size() == 1 &&
                 s.body[0].kind == Kind::assignment && s.body[0].op == "=") {
        const std::string& target = s.body[0].name;
        if (printed.steps.empty() || printed.steps.back().name.get_name() != target)
          throw CppReadError(s.line,
                             "an `if` that assigns " + target + ", which is not the step just declared");
        KernelStep& step = printed.steps.back();
        const auto in_form = std::find_if(form.steps.begin(), form.steps.end(),
                                          [&](const KernelStep& k) { return k.name.get_name() == target; });
        const std::size_t index = step.guards.size();
        if (in_form == form.steps.end() || index >= in_form->guards.size())
          throw CppReadError(s.line, "a guard on " + target + " that the kernel's form does not have");
        const Guard& guard = in_form->guards[index];
        step.guards.push_back({to_expression(*s.condition, names), to_expression(*s.body[0].value, names),
                               guard.kind, guard.claim});
      } else if (s.kind == Kind::return_) {
        if (s.value->kind == CppExpression::Kind::braced) {
          for (const CppExpression& e : s.value->operands) printed.outputs.push_back(to_expression(e, names));
        } else {
          printed.outputs.push_back(to_expression(*s.value, names));
        }
        returned = true;
      } else {
        throw CppReadError(s.line, "a statement outside what a kernel prints");
      }
    }
    if (!returned) throw CppReadError(f.line, "no return");
    // A guarded step printed `Scalar x = …` and an unguarded one `const Scalar x = …`: the reader takes
    // both; the comparison with the form checks every guard is there.
    return printed;
  }

  // The printed kernel is the form: hoisted steps put back, the same steps in order with the same
  // expressions, guards (operator for operator) and outputs.
  void compare_with_form(const std::string& name, const Kernel& printed, const Kernel& form) {
    std::set<std::string> form_steps;
    for (const KernelStep& step : form.steps) form_steps.insert(step.name.get_name());
    GiNaC::exmap put_back;  // hoisted steps → their expressions; printed step symbols → the form's
    for (const KernelStep& step : form.steps) {
      for (const KernelStep& p : printed.steps) {
        if (p.name.get_name() == step.name.get_name()) put_back[p.name] = step.name;
      }
    }
    std::vector<const KernelStep*> kept;
    for (const KernelStep& step : printed.steps) {
      if (form_steps.count(step.name.get_name())) {
        kept.push_back(&step);
        continue;
      }
      if (!step.guards.empty()) {
        fail(name, form.equals,
             "the step " + step.name.get_name() + " has guards but is no step of the form");
        return;
      }
      put_back[step.name] = step.expression.subs(put_back);
    }
    const auto back = [&](const ex& e) { return e.subs(put_back); };
    if (kept.size() != form.steps.size()) {
      fail(name, form.equals,
           "prints " + std::to_string(kept.size()) + " of the form's " + std::to_string(form.steps.size()) +
               " steps");
      return;
    }
    for (std::size_t i = 0; i < kept.size(); ++i) {
      const KernelStep &p = *kept[i], &f = form.steps[i];
      const std::string step = "the step " + f.name.get_name();
      if (p.name.get_name() != f.name.get_name()) {
        fail(name, form.equals, "prints " + p.name.get_name() + " where the form has " + f.name.get_name());
        return;
      }
      if (!same_expression(back(p.expression), f.expression))
        fail(name, form.equals,
             step + " is " + print(back(p.expression), Notation::text) + ", not the form's " +
                 print(f.expression, Notation::text));
      if (p.guards.size() != f.guards.size()) {
        fail(name, form.equals,
             step + " has " + std::to_string(p.guards.size()) + " guards, the form " +
                 std::to_string(f.guards.size()));
        continue;
      }
      for (std::size_t j = 0; j < f.guards.size(); ++j) {
        const Guard &pg = p.guards[j], &fg = f.guards[j];
        if (!same_relational(back(pg.condition), fg.condition))
          fail(name, fg.claim,
               step + "'s guard tests " + print(back(pg.condition), Notation::text) + ", not the form's " +
                   print(fg.condition, Notation::text));
        if (!same_expression(back(pg.alternative), fg.alternative))
          fail(name, fg.claim,
               step + "'s guard takes " + print(back(pg.alternative), Notation::text) + ", not the form's " +
                   print(fg.alternative, Notation::text));
      }
    }
    if (printed.outputs.size() != form.outputs.size()) {
      fail(name, form.equals,
           "returns " + std::to_string(printed.outputs.size()) + " values, the form " +
               std::to_string(form.outputs.size()));
      return;
    }
    for (std::size_t i = 0; i < form.outputs.size(); ++i) {
      if (!same_expression(back(printed.outputs[i]), form.outputs[i]))
        fail(name, form.equals,
             "returns " + print(back(printed.outputs[i]), Notation::text) + " where the form returns " +
                 print(form.outputs[i], Notation::text));
    }
  }

  // ---- a fast path's dispatch and predicate --------------------------------------------------------
  static std::vector<std::string> predicate_parameters(const Kernel& kernel) {
    std::vector<std::string> names;
    for (const ex& p : kernel.parameters) {
      const auto& conditions = kernel.fast_path->conditions;
      if (std::any_of(conditions.begin(), conditions.end(), [&](const ex& c) { return c.has(p); }))
        names.push_back(symbol_name(p));
    }
    return names;
  }

  // `callee(arguments)` whose arguments are exactly `expected`, by name and in order.
  bool is_call(const CppExpression& e, const std::string& callee, const std::vector<std::string>& expected,
               const std::string& function, const std::string& claim, const std::string& what) {
    if (e.kind != CppExpression::Kind::call || e.text != callee) {
      fail(function, claim, what + " is " + spelled(e) + ", not a call of " + callee);
      return false;
    }
    std::vector<std::string> arguments;
    for (const CppExpression& a : e.operands)
      arguments.push_back(a.kind == CppExpression::Kind::name ? a.text : spelled(a));
    if (arguments != expected) {
      std::string want;
      for (const std::string& n : expected) want += (want.empty() ? "" : ", ") + n;
      fail(function, claim,
           what + " " + spelled(e) + " does not pass " + callee + "'s parameters (" + want + ") in order");
      return false;
    }
    return true;
  }

  void prove_dispatch(const Kernel& kernel) {
    const FastPath& path = *kernel.fast_path;
    const CppFunction* f = find(kernel.name);
    if (f == nullptr) {
      fail(kernel.name, kernel.equals, "the function is not in the header");
      return;
    }
    proven(kernel.name);
    if (!same_signature(*f, kernel, parameter_names(kernel))) return;
    using Kind = CppStatement::Kind;
    const bool shaped = f->body.size() == 2 && f->body[0].kind == Kind::if_ && f->body[0].type.empty() &&
                        f->body[0].body.size() == 1 && f->body[0].body[0].kind == Kind::return_ &&
                        f->body[1].kind == Kind::return_;
    if (!shaped) {
      fail(kernel.name, path.claim, "is not `if (predicate(…)) return fast(…); return full(…);`");
      return;
    }
    // The fast kernel's parameters are the kernel's (validate_kernels), so each call passes them all.
    const std::vector<std::string> all = parameter_names(kernel);
    is_call(*f->body[0].condition, path.predicate, predicate_parameters(kernel), kernel.name, path.claim,
            "its test");
    is_call(*f->body[0].body[0].value, path.kernel, all, kernel.name, path.claim, "its fast call");
    is_call(*f->body[1].value, full_form_name(kernel), all, kernel.name, kernel.equals, "its full call");
  }

  // Splits `a && b && …` into its terms.
  static void conjuncts(const CppExpression& e, std::vector<const CppExpression*>& out) {
    if (e.kind == CppExpression::Kind::binary && e.text == "&&") {
      conjuncts(e.operands[0], out);
      conjuncts(e.operands[1], out);
    } else {
      out.push_back(&e);
    }
  }

  void prove_predicate(const Kernel& kernel) {
    const FastPath& path = *kernel.fast_path;
    if (predicates_done_.count(path.predicate)) return;
    predicates_done_.insert(path.predicate);
    const CppFunction* f = find(path.predicate);
    if (f == nullptr) {
      fail(path.predicate, path.claim, "the predicate is not in the header");
      return;
    }
    proven(path.predicate);
    std::map<std::string, ex> names;
    for (const ex& p : kernel.parameters) names[symbol_name(p)] = p;
    std::vector<std::string> printed_parameters;
    for (const auto& parameter : f->parameters) printed_parameters.push_back(parameter.second);
    if (printed_parameters != predicate_parameters(kernel)) {
      fail(path.predicate, path.claim, "does not take the parameters its conditions read, in order");
      return;
    }
    try {
      using Kind = CppStatement::Kind;
      const CppStatement& last = f->body.back();
      if (last.kind != Kind::return_)
        throw CppReadError(last.line, "the predicate does not end in its comparisons");
      std::vector<const CppExpression*> terms;
      conjuncts(*last.value, terms);
      std::vector<ex> conditions;
      for (const CppExpression* term : terms) conditions.push_back(to_expression(*term, names));
      const auto listed = [](const std::vector<ex>& list) {
        std::string out;
        for (const ex& c : list) out += (out.empty() ? "" : ", ") + print(c, Notation::text);
        return out;
      };
      const bool same =
          conditions.size() == path.conditions.size() &&
          std::equal(conditions.begin(), conditions.end(), path.conditions.begin(), same_relational);
      if (!same)
        fail(path.predicate, path.claim,
             "tests " + listed(conditions) + ", not the fast path's " + listed(path.conditions));
      if (f->body.size() == 1) return;
      // The bit comparison: `#if !defined(__CUDA_ARCH__)`, `if constexpr (orders_as_bits<Scalar>()) {…}`,
      // `#endif`, then the comparisons.
      const bool shaped = f->body.size() == 4 && f->body[0].kind == Kind::directive &&
                          f->body[0].text == "if !defined(__CUDA_ARCH__)" && f->body[1].kind == Kind::if_ &&
                          f->body[1].type == "constexpr" &&
                          spelled(*f->body[1].condition) == "orders_as_bits<Scalar>()" &&
                          f->body[1].body.size() == 1 && f->body[1].body[0].kind == Kind::block &&
                          f->body[2].kind == Kind::directive && f->body[2].text == "endif";
      if (!shaped) throw CppReadError(f->line, "the predicate's host branch is not the bit comparison");
      const std::vector<ex> tested = interval_of_bits(f->body[1].body[0].body, names);
      bool same_set = tested.size() == path.conditions.size();
      for (const ex& c : path.conditions) {
        same_set = same_set && std::any_of(tested.begin(), tested.end(),
                                           [&](const ex& t) { return same_relational(t, c); });
      }
      if (!same_set)
        fail(path.predicate, path.claim,
             "compares bits for " + listed(tested) + ", not the fast path's " + listed(path.conditions));
    } catch (const std::exception& error) {
      fail(path.predicate, path.claim, error.what());
    }
  }

  // The conditions a bit comparison tests: `const Scalar low = L;`, the running largest bits_above of
  // the parameters (in one expression or `auto largest` and its updates), `return … <= bits_above(H,
  // low);` — low ≤ p and p ≤ high for each parameter p.
  static std::vector<ex> interval_of_bits(const std::vector<CppStatement>& body,
                                          const std::map<std::string, ex>& names) {
    using Kind = CppStatement::Kind;
    if (body.size() < 2 || body.front().kind != Kind::declaration || body.front().type != "const Scalar" ||
        body.front().name != "low" || body.back().kind != Kind::return_)
      throw CppReadError(body.empty() ? 0 : body.front().line,
                         "the bit comparison is not `low`, the largest, the test");
    const ex low = to_expression(*body.front().value, names);
    std::vector<std::string> read;
    // bits_above(p, low) → p; larger(a, b) → both; `largest` → what it has held.
    std::vector<std::string> largest;
    std::function<void(const CppExpression&)> collect = [&](const CppExpression& e) {
      if (e.kind == CppExpression::Kind::call && e.text == "bits_above" && e.operands.size() == 2 &&
          e.operands[0].kind == CppExpression::Kind::name &&
          e.operands[1].kind == CppExpression::Kind::name && e.operands[1].text == "low") {
        read.push_back(e.operands[0].text);
      } else if (e.kind == CppExpression::Kind::call && e.text == "larger" && e.operands.size() == 2) {
        collect(e.operands[0]);
        collect(e.operands[1]);
      } else if (e.kind == CppExpression::Kind::name && e.text == "largest") {
        read.insert(read.end(), largest.begin(), largest.end());
      } else {
        throw CppReadError(e.line, spelled(e) + " in the bit comparison");
      }
    };
    for (std::size_t i = 1; i + 1 < body.size(); ++i) {
      const CppStatement& s = body[i];
      const bool declares = s.kind == Kind::declaration && s.type == "auto" && s.name == "largest";
      const bool updates = s.kind == Kind::assignment && s.name == "largest" && s.op == "=";
      if (!declares && !updates) throw CppReadError(s.line, "a statement outside the bit comparison");
      read.clear();
      collect(*s.value);
      largest = read;
    }
    const CppExpression& test = *body.back().value;
    if (test.kind != CppExpression::Kind::binary || test.text != "<=" ||
        test.operands[1].kind != CppExpression::Kind::call || test.operands[1].text != "bits_above" ||
        test.operands[1].operands.size() != 2 || spelled(test.operands[1].operands[1]) != "low")
      throw CppReadError(test.line, "the bit comparison's test is not `largest <= bits_above(high, low)`");
    read.clear();
    collect(test.operands[0]);
    const ex high = to_expression(test.operands[1].operands[0], names);
    std::vector<ex> conditions;
    for (const std::string& p : read) {
      const auto found = names.find(p);
      if (found == names.end()) throw CppReadError(test.line, "the bit comparison reads " + p);
      conditions.push_back(low <= found->second);
      conditions.push_back(found->second <= high);
    }
    return conditions;
  }

  // ---- named constants ------------------------------------------------------------------------------
  // A literal of the float or double specialisation: a hexadecimal 0x1pN (with `f` for float), exactly
  // 2^N.
  static std::optional<GiNaC::numeric> power_of_two_literal(const std::string& text,
                                                            const std::string& type) {
    std::string digits = text;
    if (type == "float") {
      if (digits.empty() || digits.back() != 'f') return std::nullopt;
      digits.pop_back();
    }
    if (digits.rfind("0x1p", 0) != 0) return std::nullopt;
    const std::string exponent = digits.substr(4);
    if (exponent.empty() || exponent.find_first_not_of("-0123456789") != std::string::npos ||
        exponent.find('-', 1) != std::string::npos)
      return std::nullopt;
    return GiNaC::numeric(2).power(std::stoi(exponent));
  }

  // The value a generic constant's body computes for `format`: `return std::numeric_limits<Scalar>::min();`,
  // or `Scalar low = Scalar(a); for (int k = 0; k < n; ++k) low /= Scalar(2); return low;`, or
  // `return Scalar(1) / x_low<Scalar>();`.
  std::optional<GiNaC::numeric> generic_value(const CppFunction& f, const BinaryFormat& format) const {
    using Kind = CppStatement::Kind;
    const std::map<std::string, int> limits = {
        {"std::numeric_limits<Scalar>::min_exponent", format.min_exponent},
        {"std::numeric_limits<Scalar>::max_exponent", format.max_exponent},
        {"std::numeric_limits<Scalar>::digits", format.digits}};
    // An integer expression of the loop's bound, with C++'s integer division.
    std::function<long(const CppExpression&)> integer = [&](const CppExpression& e) -> long {
      if (e.kind == CppExpression::Kind::literal) {
        if (e.text.find_first_not_of("0123456789") != std::string::npos)
          throw CppReadError(e.line, "the integer " + e.text);
        return std::stol(e.text);
      }
      if (e.kind == CppExpression::Kind::name && limits.count(e.text)) return limits.at(e.text);
      if (e.kind == CppExpression::Kind::unary && e.text == "-") return -integer(e.operands[0]);
      if (e.kind == CppExpression::Kind::binary) {
        const long a = integer(e.operands[0]), b = integer(e.operands[1]);
        if (e.text == "+") return a + b;
        if (e.text == "-") return a - b;
        if (e.text == "*") return a * b;
        if (e.text == "/" && b != 0) return a / b;
      }
      throw CppReadError(e.line, spelled(e) + " in a constant's loop");
    };
    const auto scalar = [](const CppExpression& e) -> std::optional<GiNaC::numeric> {
      if (e.kind != CppExpression::Kind::call || e.text != "Scalar" || e.operands.size() != 1 ||
          e.operands[0].kind != CppExpression::Kind::literal)
        return std::nullopt;
      return decimal_value(e.operands[0].text);
    };
    const auto& body = f.body;
    if (body.size() == 1 && body[0].kind == Kind::return_) {
      const CppExpression& r = *body[0].value;
      if (spelled(r) == "std::numeric_limits<Scalar>::min()")
        return GiNaC::numeric(2).power(format.min_exponent - 1);
      if (r.kind == CppExpression::Kind::binary && r.text == "/" &&
          scalar(r.operands[0]) == GiNaC::numeric(1) && r.operands[1].kind == CppExpression::Kind::call &&
          r.operands[1].operands.empty()) {
        const std::string callee = r.operands[1].text;
        const std::string low = callee.substr(0, callee.find('<'));
        const CppFunction* other = find(low);
        if (other == nullptr || callee != low + "<Scalar>") return std::nullopt;
        const auto value = generic_value(*other, format);
        if (!value || value->is_zero()) return std::nullopt;
        return GiNaC::inverse(*value);
      }
      return std::nullopt;
    }
    if (body.size() != 3 || body[0].kind != Kind::declaration || body[0].type != "Scalar" ||
        body[1].kind != Kind::for_ || body[2].kind != Kind::return_ ||
        spelled(*body[2].value) != body[0].name)
      return std::nullopt;
    const std::optional<GiNaC::numeric> start = scalar(*body[0].value);
    const CppStatement& loop = body[1];
    const CppStatement &init = loop.body[0], &step = loop.body[1], &halve = loop.body[2];
    const CppExpression& bound = *loop.condition;
    const bool counted = init.kind == Kind::declaration && init.type == "int" &&
                         spelled(*init.value) == "0" && bound.kind == CppExpression::Kind::binary &&
                         bound.text == "<" && spelled(bound.operands[0]) == init.name &&
                         step.name == init.name;
    const bool halves = halve.kind == Kind::assignment && halve.name == body[0].name && halve.op == "/=" &&
                        scalar(*halve.value) == GiNaC::numeric(2);
    if (!start || !counted || !halves) return std::nullopt;
    const long count = integer(bound.operands[1]);
    return *start / GiNaC::numeric(2).power(std::max(count, 0L));
  }

  void prove_constants() {
    for (const auto& [spelling, constant] : named_constant_spellings()) {
      const std::string name = spelling.substr(0, spelling.find('<'));
      const CppFunction* generic = find(name);
      if (generic == nullptr) continue;  // not printed: no kernel reads it
      proven(name);
      for (const BinaryFormat& format : emitted_formats()) {
        const std::optional<GiNaC::numeric> expected = value_in(constant, format);
        const CppFunction* special = find(name, format.type);
        if (special != nullptr) {
          proven(name, format.type);
          prove_specialisation(name, *special, format, expected);
        } else if (!expected) {
          fail(name, "", "has no " + format.type + " specialisation");
        }
        if (!expected) {
          if (generic->body.size() != 1 || !generic->body[0].value ||
              spelled(*generic->body[0].value) != "std::numeric_limits<Scalar>::infinity()")
            fail(name, "", "its generic form is not std::numeric_limits<Scalar>::infinity()");
          continue;
        }
        std::optional<GiNaC::numeric> computed;
        try {
          computed = generic_value(*generic, format);
        } catch (const std::exception& error) {
          fail(name, "", error.what());
          continue;
        }
        if (!computed || *computed != *expected)
          fail(name, "", "its generic form does not give " + power_text(*expected) + " in " + format.type);
      }
    }
  }

  static std::string power_text(const GiNaC::numeric& power) {
    return "2^" + std::to_string(*exact_binary_logarithm(power));
  }

  // A float or double specialisation `T name<T>() { return v; }`: v the constant's value in T, a literal
  // 0x1pN (with the suffix f in float), or for +∞ the builtin of the type.
  void prove_specialisation(const std::string& name, const CppFunction& special, const BinaryFormat& format,
                            const std::optional<GiNaC::numeric>& expected) {
    if (special.result != format.type || special.body.size() != 1 ||
        special.body[0].kind != CppStatement::Kind::return_) {
      fail(
          name, "",
          "its " + format.type + " specialisation is not `" + format.type + " " + name + "() { return …; }`");
      return;
    }
    const CppExpression& value = *special.body[0].value;
    if (!expected) {
      const std::string builtin = format.type == "float" ? "__builtin_huge_valf()" : "__builtin_huge_val()";
      if (spelled(value) != builtin)
        fail(name, "", "its " + format.type + " value is " + spelled(value) + ", not " + builtin);
      return;
    }
    const std::optional<GiNaC::numeric> literal = value.kind == CppExpression::Kind::literal
                                                      ? power_of_two_literal(value.text, format.type)
                                                      : std::nullopt;
    if (!literal || *literal != *expected)
      fail(name, "",
           "its " + format.type + " value is " + spelled(value) + ", not " + power_text(*expected) +
               (format.type == "float" ? " written 0x1p…f" : " written 0x1p…"));
  }

  // absolute_value(x) is `x < Scalar(0) ? -x : x`: −x where x < 0, x elsewhere (−0 included, which
  // is +0 in value): |x|.
  void prove_absolute_value() {
    const CppFunction* f = find("absolute_value");
    if (f == nullptr) return;
    proven("absolute_value");
    const bool shaped =
        f->parameters.size() == 1 && f->body.size() == 1 && f->body[0].kind == CppStatement::Kind::return_;
    const std::string x = shaped ? f->parameters[0].second : "";
    if (!shaped || spelled(*f->body[0].value) != "((" + x + " < Scalar(0)) ? -" + x + " : " + x + ")")
      fail("absolute_value", "", "is not `x < Scalar(0) ? -x : x`");
  }

  const std::vector<CppFunction>& functions_;
  const std::vector<Kernel>& kernels_;
  const std::vector<Claim>& claims_;
  std::vector<RoundingBound>& bounds_;
  const std::function<bool(const std::string&)>& proves_rounding_of_;
  std::set<std::string> proven_, predicates_done_;
  std::map<std::string, GiNaC::exmap> printed_constants_;  ///< by format type, read once (printed_facts)
  std::vector<KernelProblem> problems_;
};

}  // namespace

std::vector<KernelProblem> prove_printed(const std::string& header, const std::vector<Kernel>& kernels,
                                         const std::vector<Claim>& claims, std::vector<RoundingBound>& bounds,
                                         const std::function<bool(const std::string&)>& proves_rounding_of) {
  try {
    const std::vector<CppFunction> functions = read_functions(header);
    return ReadBack(functions, kernels, claims, bounds, proves_rounding_of).run();
  } catch (const std::exception& error) {
    return {{"(the printed header)", "", std::string("cannot be read back: ") + error.what()}};
  }
}

}  // namespace billiards::derive

namespace billiards::derive {

namespace {

// What a kernel list's functions must call: each kernel by the name the list spells it with, and how
// many outputs it returns.
struct Listed {
  std::string spelled;
  const Kernel* kernel;
};

class ListReadBack {
 public:
  ListReadBack(const std::vector<CppFunction>& functions, std::vector<Listed> listed)
      : functions_(functions), listed_(std::move(listed)) {}

  std::vector<KernelProblem> run() {
    bool called = false, summed = false;
    for (const CppFunction& f : functions_) {
      if (f.name == "call") {
        called = true;
        prove_call(f);
      } else if (f.name == "sum_of_every_kernel") {
        summed = true;
        prove_sum(f);
      } else {
        fail(f.name, "a function of the kernel list that nothing proves");
      }
    }
    if (!called) fail("call", "the kernel list has no call");
    if (!summed) fail("sum_of_every_kernel", "the kernel list has no sum_of_every_kernel");
    return problems_;
  }

 private:
  void fail(const std::string& where, const std::string& reason) {
    problems_.push_back({where, "", "in the kernel list: " + reason});
  }

  // The kernel an expression calls, with its arguments each as `argument(i)` spells it; nullptr (and a
  // problem) otherwise.
  const Listed* called(const std::string& where, const CppExpression& e,
                       const std::function<std::string(std::size_t)>& argument) {
    using Kind = CppExpression::Kind;
    if (e.kind != Kind::call) {
      fail(where, spelled(e) + " is no call of a kernel");
      return nullptr;
    }
    const auto found = std::find_if(listed_.begin(), listed_.end(),
                                    [&](const Listed& l) { return l.spelled == e.text; });
    if (found == listed_.end()) {
      fail(where, "calls " + e.text + ", which is no kernel of the model");
      return nullptr;
    }
    const Kernel& kernel = *found->kernel;
    std::vector<std::string> expected, printed;
    for (std::size_t i = 0; i < kernel.parameters.size(); ++i) expected.push_back(argument(i));
    for (const CppExpression& operand : e.operands) printed.push_back(spelled(operand));
    if (printed != expected) {
      std::string list;
      for (const std::string& a : expected) list += (list.empty() ? "" : ", ") + a;
      fail(where, spelled(e) + " does not pass (" + list + ")");
      return nullptr;
    }
    return &*found;
  }

  // `if (name == "K") { const auto r = K(at("p1"), …); return {r.first, r.second}; }` for every kernel,
  // in order, then the throw.
  void prove_call(const CppFunction& f) {
    using Kind = CppStatement::Kind;
    std::size_t next = 0;
    for (const CppStatement& s : f.body) {
      if (s.kind == Kind::throw_) continue;
      const CppExpression* condition = s.kind == Kind::if_ ? &*s.condition : nullptr;
      const bool block = s.kind == Kind::if_ && s.body.size() == 1 && s.body[0].kind == Kind::block &&
                         s.body[0].body.size() == 2 && s.body[0].body[0].kind == Kind::declaration &&
                         s.body[0].body[1].kind == Kind::return_;
      if (!block || condition->kind != CppExpression::Kind::binary || condition->text != "==" ||
          spelled(condition->operands[0]) != "name" || next >= listed_.size()) {
        fail("call", "a statement other than the next kernel's branch, at line " + std::to_string(s.line));
        return;
      }
      const Listed& expected = listed_[next++];
      const std::string label = "\"" + expected.spelled.substr(expected.spelled.rfind(':') == std::string::npos
                                                                   ? 0
                                                                   : expected.spelled.rfind(':') + 1) +
                                "\"";
      if (condition->operands[1].text != label) {
        fail("call", "the branch " + condition->operands[1].text + " where " + label + " is listed");
        continue;
      }
      const CppStatement& declared = s.body[0].body[0];
      const Kernel& kernel = *expected.kernel;
      const Listed* found = called("call", *declared.value, [&](std::size_t i) {
        return "at(\"" + symbol_name(kernel.parameters[i]) + "\")";
      });
      if (found == nullptr) continue;
      if (found != &expected) fail("call", "the branch " + label + " calls " + found->spelled);
      prove_outputs("call", *found->kernel, declared.name, *s.body[0].body[1].value);
    }
    if (next != listed_.size()) fail("call", "lists " + std::to_string(next) + " of the kernels");
  }

  // `return {r.first, r.second};` or `return {r};`: every output, in order.
  void prove_outputs(const std::string& where, const Kernel& kernel, const std::string& r,
                     const CppExpression& value) {
    std::vector<std::string> expected, printed;
    if (kernel.outputs.size() == 1) {
      expected = {r};
    } else {
      expected = {r + ".first", r + ".second"};
    }
    for (const CppExpression& operand : value.operands) printed.push_back(spelled(operand));
    if (value.kind != CppExpression::Kind::braced || printed != expected)
      fail(where, kernel.name + "'s outputs returned as " + spelled(value));
  }

  // `sum += K(a[0], …);` or `{ const auto r = K(a[0], …); sum += r.first + r.second; }` for every kernel
  // (reference kernels aside), in order.
  void prove_sum(const CppFunction& f) {
    using Kind = CppStatement::Kind;
    std::size_t next = 0;
    std::vector<const Listed*> kernels;
    for (const Listed& l : listed_) {
      if (l.spelled.find("::") == std::string::npos) kernels.push_back(&l);
    }
    for (const CppStatement& s : f.body) {
      if (s.kind == Kind::declaration || s.kind == Kind::return_) continue;  // sum = 0 and return sum
      const auto argument = [](std::size_t i) { return "a[" + std::to_string(i) + "]"; };
      const Listed* found = nullptr;
      std::string summed;
      if (s.kind == Kind::assignment && s.op == "+=" && s.name == "sum") {
        found = called("sum_of_every_kernel", *s.value, argument);
        summed = found && found->kernel->outputs.size() == 1 ? "ok" : "";
      } else if (s.kind == Kind::block && s.body.size() == 2 && s.body[0].kind == Kind::declaration &&
                 s.body[1].kind == Kind::assignment && s.body[1].op == "+=") {
        found = called("sum_of_every_kernel", *s.body[0].value, argument);
        const std::string r = s.body[0].name;
        summed = found && found->kernel->outputs.size() == 2 &&
                         spelled(*s.body[1].value) == "(" + r + ".first + " + r + ".second)"
                     ? "ok"
                     : "";
      } else {
        fail("sum_of_every_kernel", "a statement other than a kernel's sum, at line " + std::to_string(s.line));
        return;
      }
      if (found == nullptr) {
        ++next;  // its problem told; the next statement is the next kernel's
        continue;
      }
      if (next >= kernels.size() || found != kernels[next]) {
        fail("sum_of_every_kernel", "calls " + found->spelled + " out of the kernels' order");
        return;
      }
      ++next;
      if (summed.empty()) fail("sum_of_every_kernel", "does not add each output of " + found->spelled);
    }
    if (next != kernels.size()) fail("sum_of_every_kernel", "sums " + std::to_string(next) + " of the kernels");
  }

  const std::vector<CppFunction>& functions_;
  std::vector<Listed> listed_;
  std::vector<KernelProblem> problems_;
};

}  // namespace

std::vector<KernelProblem> prove_kernel_list(const std::string& header, const std::vector<Kernel>& kernels,
                                             const std::vector<Kernel>& reference_kernels,
                                             const std::string& reference_namespace) {
  std::vector<Listed> listed;
  std::size_t largest_arity = 0;
  for (const Kernel& k : kernels) {
    listed.push_back({k.name, &k});
    largest_arity = std::max(largest_arity, k.parameters.size());
  }
  for (const Kernel& k : reference_kernels) listed.push_back({reference_namespace + "::" + k.name, &k});
  std::vector<KernelProblem> problems;
  // The one variable: the most parameters any kernel takes.
  const std::string arity = "largest_arity = " + std::to_string(largest_arity) + ";";
  if (header.find(arity) == std::string::npos)
    problems.push_back({"largest_arity", "", "in the kernel list: not " + arity});
  try {
    const std::vector<KernelProblem> found = ListReadBack(read_functions(header), listed).run();
    problems.insert(problems.end(), found.begin(), found.end());
  } catch (const std::exception& error) {
    problems.push_back({"(the kernel list)", "", std::string("cannot be read back: ") + error.what()});
  }
  return problems;
}

}  // namespace billiards::derive
