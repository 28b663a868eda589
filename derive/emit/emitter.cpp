#include "emit/emitter.hpp"

#include "core/named_constants.hpp"
#include "core/powers_of_two.hpp"
#include "print/printer.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>

namespace billiards::derive {

using GiNaC::ex;

namespace {

constexpr std::size_t column_limit = 110;

// Every sum inside `e` (including `e` itself), oriented as print() writes it.
void collect_sums(const ex& e, std::vector<ex>& sums) {
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::add>(*it)) sums.push_back(reads_negated(*it) ? ex(-*it) : *it);
  }
}

// + − × ÷, square roots, scalings and negations in a line of emitted C++: binary operators stand between
// spaces, a unary minus is followed directly by its operand.
int count_operations(const std::string& code) {
  int count = 0;
  for (std::size_t i = 0; i < code.size(); ++i) {
    const char c = code[i];
    const bool spaced = i > 0 && code[i - 1] == ' ' && i + 1 < code.size() && code[i + 1] == ' ';
    if ((c == '+' || c == '*' || c == '/' || c == '-') && spaced) ++count;
    if (c == '-' && i + 1 < code.size() && code[i + 1] != ' ') ++count;
  }
  // A square root, a fused multiply-add, a binary exponent and a scaling by a power of two count as one
  // operation each.
  for (const std::string call : {"std::sqrt(", "std::fma(", "binary_exponent(", "times_power_of_two("}) {
    for (std::size_t at = code.find(call); at != std::string::npos; at = code.find(call, at + 1)) ++count;
  }
  return count;
}

// `text` as comment lines, each `prefix` and as many words as fit in `width` characters after it.
std::string filled_comment(const std::string& text, const std::string& prefix, std::size_t width) {
  std::istringstream words(text);
  std::string word, line, out;
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += prefix + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) out += prefix + line + "\n";
  return out;
}

// "/// " lines holding `text`, wrapped before the column limit.
std::string doc_comment(const std::string& text, const std::string& indent = "") {
  return filled_comment(text, indent + "/// ", 100 - indent.size());
}

// `head` followed by `items` separated by ", " and then `tail`, wrapped like clang-format: items
// that do not fit continue on the next line, aligned under the first item.
std::string wrapped_list(const std::string& head, const std::vector<std::string>& items,
                         const std::string& tail) {
  const std::string continuation(head.size(), ' ');
  std::string out = head, line = head;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string piece = items[i] + (i + 1 < items.size() ? "," : tail);
    const bool first_on_line = line.size() == head.size();
    if (!first_on_line && line.size() + 1 + piece.size() > column_limit) {
      out += "\n" + continuation;
      line = continuation;
    } else if (!first_on_line) {
      out += " ";
      line += " ";
    }
    out += piece;
    line += piece;
  }
  return out;
}

// `head` and a conditional expression `code` ending in ";", broken like clang-format when too long: at
// " ? " and " : ".
// `if (condition) statement` on one line when it fits (the project's clang-format style allows short
// ifs without else), otherwise the statement on the next line, indented.
std::string short_if(const std::string& head, const std::string& statement) {
  if (2 + head.size() + 1 + statement.size() <= column_limit) return head + " " + statement;
  return head + "\n    " + statement;
}

// `head` then `items` joined by `separator` (which ends a line where one breaks), wrapped before the
// column limit with continuation lines indented to `indent`, then `tail`; `head` starts at column
// `column`.
std::string wrapped_terms(std::size_t column, const std::string& head, const std::vector<std::string>& items,
                          const std::string& separator, const std::string& indent, const std::string& tail) {
  std::string out = head;
  std::size_t width = column + head.size();
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string piece = items[i] + (i + 1 < items.size() ? separator : tail);
    if (i > 0 && width + 1 + piece.size() > column_limit) {
      out += "\n" + indent;
      width = indent.size();
    } else if (i > 0) {
      out += " ";
      ++width;
    }
    out += piece;
    width += piece.size();
  }
  return out;
}

// `code` (a statement's expression and its ";"), starting at `column`, broken where it passes the column
// limit as clang-format does: after a binary operator or a comma, each continuation line indented to
// `indent`.
std::string wrapped_code(std::size_t column, const std::string& code, const std::string& indent) {
  std::vector<std::string> pieces(1);
  for (std::size_t i = 0; i < code.size(); ++i) {
    const bool after_operator = code[i] == ' ' && i >= 2 && code[i - 2] == ' ' &&
                                std::string("+-*/").find(code[i - 1]) != std::string::npos;
    const bool after_comma = code[i] == ' ' && i >= 1 && code[i - 1] == ',';
    if (after_operator || after_comma) {
      pieces.emplace_back();
    } else {
      pieces.back() += code[i];
    }
  }
  return wrapped_terms(column, "", pieces, "", indent, "");
}

// `head code;` in a function body (indented by 2), or, when that passes the column limit, broken after
// the "=" with the expression on the next line indented by 4 more, and that broken again where it is
// still too long, as clang-format does.
std::string assignment(const std::string& head, const std::string& code) {
  if (2 + head.size() + 1 + code.size() + 1 <= column_limit) return head + " " + code + ";";
  return head + "\n      " + wrapped_code(6, code + ";", "      ");
}

// A relational as a C++ condition: `lhs op rhs`.
std::string print_condition(const ex& condition) {
  if (!GiNaC::is_a<GiNaC::relational>(condition)) {
    throw std::invalid_argument("a guard's condition must be a relational, not " +
                                print(condition, Notation::text));
  }
  return print(condition, Notation::cpp);
}

// Whether any of the kernel's expressions (steps, guards' alternatives, outputs) has `property`.
template <typename Property>
bool any_expression(const Kernel& kernel, Property property) {
  for (const KernelStep& step : kernel.steps) {
    if (property(step.expression)) return true;
    for (const Guard& guard : step.guards) {
      if (property(guard.alternative)) return true;
    }
  }
  return std::any_of(kernel.outputs.begin(), kernel.outputs.end(), property);
}

// True when the kernel scales by powers of two: binary_exponent and times_power_of_two.
bool scales(const Kernel& kernel) { return any_expression(kernel, uses_power_of_two_scaling); }

// True when the kernel calls a function that is not constexpr: std::sqrt, std::fma, or the scaling
// helpers (std::ilogb and std::ldexp outside their bit paths).
bool needs_runtime_math(const Kernel& kernel) {
  if (scales(kernel)) return true;
  return any_expression(kernel, [](const ex& e) {
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
      if (GiNaC::is_a<GiNaC::power>(*it) && it->op(1) == GiNaC::numeric(1, 2)) return true;
      if (GiNaC::is_a<GiNaC::function>(*it) && GiNaC::ex_to<GiNaC::function>(*it).get_name() == "fused_multiply_add")
        return true;
    }
    return false;
  });
}

// A function signature as clang-format lays it out in the project's style: on one line when it fits,
// else on two to four lines aligned under the "(", else broken after the "(" with the parameters on a line
// of their own, indented by 4, or on as many such lines as they fill.
std::string signature(const std::string& head, const std::vector<std::string>& parameters,
                      const std::string& tail) {
  std::string list;
  for (const std::string& parameter : parameters) list += (list.empty() ? "" : ", ") + parameter;
  if (head.size() + list.size() + tail.size() <= column_limit) return head + list + tail;
  // Aligned under the "(" when that takes two to four lines, as clang-format prefers it then.
  const std::string aligned = wrapped_list(head, parameters, tail);
  const std::size_t line_break = aligned.find('\n');
  std::size_t lines = 0, longest = 0;
  for (std::size_t start = 0; start <= aligned.size(); ++lines) {
    const std::size_t end = std::min(aligned.find('\n', start), aligned.size());
    longest = std::max(longest, end - start);
    start = end + 1;
  }
  if (line_break != std::string::npos && lines <= 4 && longest <= column_limit) return aligned;
  if (4 + list.size() + tail.size() <= column_limit) return head + "\n    " + list + tail;
  // Else broken after the "(", the parameters filling lines of their own, indented by 4.
  return head + "\n    " + wrapped_terms(4, "", parameters, ",", "    ", tail);
}

// The parameters of `kernel` that `conditions` read, in signature order.
std::vector<std::string> parameters_read(const Kernel& kernel, const std::vector<ex>& conditions) {
  std::vector<std::string> names;
  for (const ex& parameter : kernel.parameters) {
    const bool read = std::any_of(conditions.begin(), conditions.end(),
                                  [&](const ex& condition) { return condition.has(parameter); });
    if (read) names.push_back(GiNaC::ex_to<GiNaC::symbol>(parameter).get_name());
  }
  return names;
}

std::string joined(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

// The interval [low, high] when `conditions` say exactly that each parameter of `kernel` they read lies
// in it — `low <= p` and `p <= high` for each, nothing else — with low and high named constants,
// positive and finite in float and double, low the smaller: then the predicate may compare bits.
std::optional<std::pair<ex, ex>> common_interval(const Kernel& kernel, const std::vector<ex>& conditions) {
  const std::vector<std::string> read = parameters_read(kernel, conditions);
  if (read.empty() || conditions.size() != 2 * read.size()) return std::nullopt;
  std::map<std::string, ex> lower, upper;
  for (const ex& condition : conditions) {
    if (!GiNaC::is_a<GiNaC::relational>(condition) ||
        !GiNaC::ex_to<GiNaC::relational>(condition).info(GiNaC::info_flags::relation_less_or_equal)) {
      return std::nullopt;
    }
    const ex left = condition.lhs(), right = condition.rhs();
    if (GiNaC::is_a<GiNaC::symbol>(right) && positive_finite_rank(left) >= 0 && !is_named_constant(right)) {
      lower.emplace(GiNaC::ex_to<GiNaC::symbol>(right).get_name(), left);
    } else if (GiNaC::is_a<GiNaC::symbol>(left) && positive_finite_rank(right) >= 0 &&
               !is_named_constant(left)) {
      upper.emplace(GiNaC::ex_to<GiNaC::symbol>(left).get_name(), right);
    } else {
      return std::nullopt;
    }
  }
  // Two conditions a parameter: a bound given twice leaves another missing.
  if (lower.empty() || upper.empty()) return std::nullopt;
  const ex low = lower.begin()->second, high = upper.begin()->second;
  for (const std::string& name : read) {
    if (!lower.count(name) || !upper.count(name) || !lower.at(name).is_equal(low) ||
        !upper.at(name).is_equal(high)) {
      return std::nullopt;
    }
  }
  if (positive_finite_rank(low) >= positive_finite_rank(high)) return std::nullopt;
  return std::pair<ex, ex>{low, high};
}

// A fast path's predicate as a documented constexpr function: true where every condition holds. Where
// the conditions put every parameter they read in one interval of positive finite constants, the host
// code for IEEE float and double compares bits instead (bits_above: integer operations where the
// comparisons would be floating-point ones, each a branch), the device code the numbers.
std::string predicate_function(const Kernel& kernel) {
  const FastPath& path = *kernel.fast_path;
  std::vector<std::string> parameters, conditions;
  const std::vector<std::string> read = parameters_read(kernel, path.conditions);
  for (const std::string& name : read) parameters.push_back("Scalar " + name);
  for (const ex& condition : path.conditions) conditions.push_back(print_condition(condition));
  const std::optional<std::pair<ex, ex>> interval = common_interval(kernel, path.conditions);
  std::string brief = path.brief, bits;
  if (interval) {
    brief +=
        " On the host, for IEEE float and double (orders_as_bits), it compares bits: the largest "
        "bits_above of the low end at most the high end's.";
    const std::string low = print(interval->first, Notation::cpp);
    // Two parameters in one expression; more by a running largest, one line each.
    std::string largest = "bits_above(" + read[0] + ", low)", running;
    if (read.size() > 2) {
      running = "    auto largest = " + largest + ";\n";
      for (std::size_t i = 1; i < read.size(); ++i)
        running += "    largest = larger(largest, bits_above(" + read[i] + ", low));\n";
      largest = "largest";
    } else {
      for (std::size_t i = 1; i < read.size(); ++i)
        largest = "larger(" + largest + ", bits_above(" + read[i] + ", low))";
    }
    const std::string head = "    return " + largest + " <=",
                      tail = "bits_above(" + print(interval->second, Notation::cpp) + ", low);";
    bits =
        "#if !defined(__CUDA_ARCH__)\n  if constexpr (orders_as_bits<Scalar>()) {\n    const Scalar low = " +
        low + ";\n" + running + head +
        (head.size() + 1 + tail.size() <= column_limit ? " " : "\n" + std::string(11, ' ')) + tail +
        "\n  }\n#endif\n";
  }
  return "\n" + doc_comment(brief) + "template <typename Scalar>\n" +
         signature("BILLIARDS_HOST_DEVICE constexpr bool " + path.predicate + "(", parameters,
                   ") noexcept {") +
         "\n" + bits + wrapped_terms(0, "  return ", conditions, " &&", "         ", ";") + "\n}\n";
}

// Every kernel as a documented `template <typename Scalar>` function: its brief, the audit claims it
// implements, its operation count and its body; before the first kernel with a fast path, that path's
// predicate.
std::string functions(const std::vector<Kernel>& kernels, const PairResult& model_pair) {
  std::ostringstream out;
  std::vector<std::string> predicates;
  for (const Kernel& kernel : kernels) {
    if (kernel.fast_path &&
        std::find(predicates.begin(), predicates.end(), kernel.fast_path->predicate) == predicates.end()) {
      predicates.push_back(kernel.fast_path->predicate);
      out << predicate_function(kernel);
    }
    const EmittedKernel emitted = emit_kernel(kernel);
    std::string claims;
    for (const std::string& id : cited_claims(kernel)) {
      if (id != kernel.equals) claims += (claims.empty() ? "" : ", ") + ("`" + id + "`");
    }
    std::vector<std::string> parameters;
    for (const ex& parameter : kernel.parameters) {
      parameters.push_back("Scalar " + GiNaC::ex_to<GiNaC::symbol>(parameter).get_name());
    }
    const std::string result =
        kernel.outputs.size() == 1 ? "Scalar" : kernel.pair.value_or(model_pair).name + "<Scalar>";
    const std::string proven =
        doc_comment("Proven equal to the derived expression of the audit claim `" + kernel.equals +
                    "` before it was printed" + (claims.empty() ? "" : "; also implements " + claims) + ".");
    const auto function = [&](const std::string& brief, const std::string& name,
                              const std::vector<std::string>& body) {
      out << "\n"
          << doc_comment(brief) << "///\n"
          << proven << "///\n"
          << "/// Total ops: " << emitted.operation_count << "\n"
          << "template <typename Scalar>\n"
          << signature(std::string("BILLIARDS_HOST_DEVICE ") +
                           (needs_runtime_math(kernel) ? "" : "constexpr ") + result + " " + name + "(",
                       parameters, ") noexcept {")
          << "\n";
      for (const std::string& line : body) out << "  " << line << "\n";
      out << "}\n";
    };
    if (kernel.fast_path) {
      const FastPath& path = *kernel.fast_path;
      function("The full form of " + kernel.name + ", right for every valid input: " + kernel.name +
                   " takes " + path.kernel + " where " + path.predicate + " holds and this elsewhere. " +
                   "A function of its own, so that the compilers inline the test and " + path.kernel +
                   " into each caller however long this form is; call " + kernel.name + ".",
               full_form_name(kernel), emitted.full_body);
    }
    function(kernel.brief, kernel.name, emitted.body);
  }
  return out.str();
}

}  // namespace

EmittedKernel emit_kernel(const Kernel& kernel) {
  // Hoist every sum that occurs more than once across the steps and outputs.
  std::vector<ex> sums;
  for (const KernelStep& step : kernel.steps) {
    collect_sums(step.expression, sums);
    for (const Guard& guard : step.guards) collect_sums(guard.alternative, sums);
  }
  for (const ex& output : kernel.outputs) collect_sums(output, sums);
  std::vector<std::pair<GiNaC::symbol, ex>> hoisted;
  std::map<std::string, int> occurrences;
  for (const ex& sum : sums) ++occurrences[print(sum, Notation::text)];
  for (const ex& sum : sums) {
    const std::string key = print(sum, Notation::text);
    if (occurrences[key] < 2) continue;
    occurrences[key] = 0;  // hoist once
    std::string name = "common_subexpression_" + std::to_string(hoisted.size());
    for (const auto& [hint, expression] : kernel.names) {
      if (print(expression, Notation::text) == key) name = hint;
    }
    hoisted.emplace_back(GiNaC::symbol(name), sum);
  }
  // In the order of their text, not of discovery: GiNaC orders the factors of a product by hash, which
  // may differ from run to run, and the output must not.
  std::stable_sort(hoisted.begin(), hoisted.end(), [](const auto& a, const auto& b) {
    return print(a.second, Notation::text) < print(b.second, Notation::text);
  });
  GiNaC::exmap replace;
  for (const auto& [symbol, sum] : hoisted) {
    replace[sum] = symbol;
    replace[-sum] = -symbol;
  }

  EmittedKernel emitted;
  std::vector<bool> placed(hoisted.size(), false);
  const auto define = [&](const std::string& name, const ex& expression) {
    const std::string code = print(expression, Notation::cpp);
    emitted.operation_count += count_operations(code);
    emitted.body.push_back(assignment("const Scalar " + name + " =", code));
  };
  const auto place_hoisted_used_by = [&](const ex& expression) {
    for (std::size_t i = 0; i < hoisted.size(); ++i) {
      if (!placed[i] && expression.has(hoisted[i].first)) {
        define(hoisted[i].first.get_name(), hoisted[i].second);
        placed[i] = true;
      }
    }
  };
  try {
    for (const KernelStep& step : kernel.steps) {
      const ex expression = step.expression.subs(replace);
      place_hoisted_used_by(expression);
      if (step.guards.empty()) {
        define(step.name.get_name(), expression);
        continue;
      }
      const std::string name = step.name.get_name(), usual = print(expression, Notation::cpp);
      emitted.operation_count += count_operations(usual);
      emitted.body.push_back(assignment("Scalar " + name + " =", usual));
      for (const Guard& guard : step.guards) {
        // The usual value, replaced under the condition: one comparison more, and the other form.
        const ex alternative = guard.alternative.subs(replace), condition = guard.condition.subs(replace);
        place_hoisted_used_by(alternative);
        place_hoisted_used_by(condition);
        const std::string other = print(alternative, Notation::cpp);
        emitted.operation_count += 1 + count_operations(other);
        emitted.body.push_back(
            short_if("if (" + print_condition(condition) + ")", name + " = " + other + ";"));
      }
    }
    std::vector<std::string> results;
    for (const ex& output : kernel.outputs) {
      const ex expression = output.subs(replace);
      place_hoisted_used_by(expression);
      const std::string code = print(expression, Notation::cpp);
      emitted.operation_count += count_operations(code);
      results.push_back(code);
    }
    if (results.size() == 1) {
      emitted.body.push_back("return " + wrapped_code(9, results.front() + ";", "      "));
    } else {
      emitted.body.push_back(wrapped_list("  return {", results, "};").substr(2));
    }
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument("kernel " + kernel.name + ": " + error.what());
  }
  if (kernel.fast_path) {
    // Where the predicate holds, the faster kernel of the same claim, before any step is computed;
    // elsewhere full_<name>, which holds every step.
    std::vector<std::string> arguments;
    for (const ex& parameter : kernel.parameters) {
      arguments.push_back(GiNaC::ex_to<GiNaC::symbol>(parameter).get_name());
    }
    const std::string test = "if (" + kernel.fast_path->predicate + "(" +
                             joined(parameters_read(kernel, kernel.fast_path->conditions), ", ") + "))";
    const std::string call = "return " + kernel.fast_path->kernel + "(";
    std::string statement = call + joined(arguments, ", ") + ");";
    // On a line of its own (indented by 4) when it does not fit beside the test, and its arguments
    // wrapped under the first when it does not fit there either.
    if (2 + test.size() + 1 + statement.size() > column_limit && 4 + statement.size() > column_limit) {
      statement = wrapped_list("    " + call, arguments, ");").substr(4);
    }
    emitted.full_body = std::move(emitted.body);
    emitted.body = {short_if(test, statement),
                    wrapped_list("  return " + full_form_name(kernel) + "(", arguments, ");").substr(2)};
  }
  return emitted;
}

std::string fingerprint(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ULL;  // FNV-1a, 64 bits
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ULL;
  }
  char digits[17];
  std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(hash));
  return std::string("fnv1a64:") + digits;
}

namespace {

constexpr const char* fingerprint_marker = "@FINGERPRINT@";

// `text` with its fingerprint marker replaced by the fingerprint of the text (marker included) followed
// by the audit: a change to either changes it.
std::string with_fingerprint(const std::string& text, const std::string& audit_text) {
  const std::string value = fingerprint(text + audit_text);
  std::string out = text;
  out.replace(out.find(fingerprint_marker), std::string(fingerprint_marker).size(), value);
  return out;
}

// `text` as "// " comment lines, each filled up to the column limit (as clang-format reflows them).
std::string line_comment(const std::string& text) { return filled_comment(text, "// ", column_limit - 3); }

// The header's opening comment: generated, do not edit, `description` (one paragraph), the fingerprint.
std::string preamble(const std::string& description, bool of_the_audit = true) {
  return "// Generated by derive/ (billiards-derive): do not edit. Regenerate with ./tools/derive "
         "generated.\n"
         "//\n" +
         line_comment(description) +
         "//\n"
         "// Fingerprint: " +
         fingerprint_marker + (of_the_audit ? " (of this header and the audit)\n" : " (of this header)\n");
}

// The scaling helpers a kernel with binary_exponent or times_power_of_two calls (after orders_as_bits
// and BitsOf).
std::string scaling_helpers() {
  return "\n/// The exponent k of x = f · 2^k, 1 ≤ |f| < 2: ⌊log2 |x|⌋ for a finite nonzero x, subnormals "
         "included,\n"
         "/// as a Scalar (an integer, exact); 0 for ±0, ±∞ and NaN, which times_power_of_two(x, −k) then "
         "leaves\n"
         "/// as they are. On the host, for IEEE float and double (orders_as_bits), it reads the exponent "
         "field\n"
         "/// of a normal x; elsewhere, and for a subnormal x, std::ilogb.\n"
         "template <typename Scalar>\n"
         "BILLIARDS_HOST_DEVICE Scalar binary_exponent(Scalar x) noexcept {\n"
         "#if !defined(__CUDA_ARCH__)\n"
         "  if constexpr (orders_as_bits<Scalar>()) {\n"
         "    using Bits = BitsOf<Scalar>;\n"
         "    constexpr int stored = std::numeric_limits<Scalar>::digits - 1;\n"
         "    constexpr int bias = std::numeric_limits<Scalar>::max_exponent - 1;\n"
         "    constexpr Bits all_ones = static_cast<Bits>(2 * bias + 1);\n"
         "    const Bits field = static_cast<Bits>((std::bit_cast<Bits>(x) >> stored) & all_ones);\n"
         "    if (field != 0 && field != all_ones) return Scalar(static_cast<int>(field) - bias);\n"
         "  }\n"
         "#endif\n"
         "  if (x == Scalar(0) || !(absolute_value(x) < infinity<Scalar>())) return Scalar(0);\n"
         "  return Scalar(std::ilogb(x));\n"
         "}\n"
         "\n"
         "/// x · 2^k for an integer k (a Scalar, as binary_exponent gives it), correctly rounded: exact "
         "unless\n"
         "/// the result is subnormal, ±∞ beyond the largest finite number. k is first clamped to [−4096, "
         "4096]\n"
         "/// (a NaN to −4096), beyond which every finite x · 2^k is ±0 or ±∞ anyway. On the host, for "
         "IEEE float\n"
         "/// and double, one multiplication by 2^k built from its bits where 2^k is a normal number; "
         "elsewhere\n"
         "/// std::ldexp.\n"
         "template <typename Scalar>\n"
         "BILLIARDS_HOST_DEVICE Scalar times_power_of_two(Scalar x, Scalar k) noexcept {\n"
         "  const int exponent = !(k >= Scalar(-4096)) ? -4096 : k > Scalar(4096) ? 4096 : "
         "static_cast<int>(k);\n"
         "#if !defined(__CUDA_ARCH__)\n"
         "  if constexpr (orders_as_bits<Scalar>()) {\n"
         "    using Bits = BitsOf<Scalar>;\n"
         "    constexpr int stored = std::numeric_limits<Scalar>::digits - 1;\n"
         "    constexpr int bias = std::numeric_limits<Scalar>::max_exponent - 1;\n"
         "    if (exponent >= 1 - bias && exponent <= bias)\n"
         "      return x * std::bit_cast<Scalar>(static_cast<Bits>(static_cast<Bits>(exponent + bias) << "
         "stored));\n"
         "  }\n"
         "#endif\n"
         "  return std::ldexp(x, exponent);\n"
         "}\n";
}

// The explicit float and double specialisations of a constant function template `name<Scalar>()`,
// each with its comment and its literal (device code has no std::numeric_limits).
std::string float_and_double(const std::string& name, const std::string& float_brief,
                             const std::string& float_value, const std::string& double_brief,
                             const std::string& double_value) {
  std::string text;
  for (const auto& [type, brief, value] :
       {std::tuple<std::string, std::string, std::string>{"float", float_brief, float_value},
        {"double", double_brief, double_value}}) {
    text += "/// " + brief + "\ntemplate <>\nBILLIARDS_HOST_DEVICE constexpr " + type + " " + name + "<" +
            type + ">() noexcept {\n  return " + value + ";\n}\n";
  }
  return text;
}

// A range of powers of two as the constant function templates `<name>_low<Scalar>()`, `start` halved
// `halvings` times (the generic form; float and double take their literals), and `<name>_high`, its
// inverse, each after `doc`.
std::string power_of_two_range(const std::string& doc, const std::string& name, const std::string& start,
                               const std::string& start_comment, const std::string& halvings,
                               const std::pair<std::string, std::string>& in_float,
                               const std::pair<std::string, std::string>& in_double) {
  const std::string low = name + "_low", high = name + "_high";
  return "\n" + doc_comment(doc) + "template <typename Scalar>\nBILLIARDS_HOST_DEVICE constexpr Scalar " +
         low + "() noexcept {\n  Scalar low = Scalar(" + start + ");" + start_comment +
         "\n  for (int k = 0; k < " + halvings + "; ++k) low /= Scalar(2);\n  return low;\n}\n" +
         float_and_double(low, in_float.first, in_float.second, in_double.first, in_double.second) +
         "/// `1/" + low +
         "<Scalar>()`, exactly (a power of two).\ntemplate <typename Scalar>\n"
         "BILLIARDS_HOST_DEVICE constexpr Scalar " +
         high + "() noexcept {\n  return Scalar(1) / " + low + "<Scalar>();\n}\n";
}

// The structs the kernels with two outputs return, each once, in the order the kernels first return them
// (the model's own where a kernel names none).
std::vector<PairResult> pair_results(const std::vector<Kernel>& kernels, const PairResult& model_pair) {
  std::vector<PairResult> pairs;
  for (const Kernel& kernel : kernels) {
    if (kernel.outputs.size() != 2) continue;
    const PairResult pair = kernel.pair.value_or(model_pair);
    const auto same = [&](const PairResult& p) { return p.name == pair.name; };
    if (std::none_of(pairs.begin(), pairs.end(), same)) pairs.push_back(pair);
  }
  return pairs;
}

}  // namespace

std::string kernels_header(const Derivation& derivation, const std::string& audit_text) {
  const bool runtime_math =
      std::any_of(derivation.kernels.begin(), derivation.kernels.end(), needs_runtime_math);
  std::ostringstream out;
  out << preamble("The scalar kernels of " + derivation.model.citation +
                  ", printed from the expressions the derivation selected. Each function was proven equal to "
                  "a verified claim of the derivation audit before it was printed, and names the claims it "
                  "implements. They take masses and dot products, so they serve vectors of any dimension and "
                  "need no Eigen.")
      << "#pragma once\n\n"
      << "#include <" << kernel_support_path << ">\n\n"
      << (runtime_math ? "#include <cmath>\n" : "") << "#include <limits>\n\n"
      << "namespace " << derivation.model.kernels_namespace << " {\n\n";
  for (const PairResult& pair : pair_results(derivation.kernels, derivation.model.pair_result)) {
    out << doc_comment(pair.brief) << "template <typename Scalar>\n"
        << "struct " << pair.name << " {\n"
        << "  Scalar first;   ///< " << pair.first << "\n"
        << "  Scalar second;  ///< " << pair.second << "\n"
        << "};\n\n";
  }
  std::string printed = functions(derivation.kernels, derivation.model.pair_result);
  if (printed.rfind("\n", 0) == 0) printed.erase(0, 1);  // one blank line after the structs
  out << printed << "\n}  // namespace " << derivation.model.kernels_namespace << "\n";
  return with_fingerprint(out.str(), audit_text);
}

std::string kernel_support_header() {
  std::ostringstream out;
  out << preamble("The numeric helpers every kernels header includes, printed once: |x|, the smallest normal "
                  "number and +∞ (also in device code), the ranges the fast paths and domains name (the plain "
                  "form's masses, the moderate range), the bit comparison of IEEE float and double, and the "
                  "scaling by powers of two. Each header's kernels are read back and proven with these "
                  "helpers' printed text, and the bit helpers are run from it over every exponent.",
                  false)
      << "#pragma once\n\n"
      << "#include <bit>\n#include <cmath>\n#include <cstdint>\n#include <limits>\n#include <type_traits>\n\n"
      << "#if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__\n"
      << "// -ffast-math assumes no infinities, but an infinite mass is how an immovable body is modelled.\n"
      << "#error \"billiards: -ffast-math breaks infinite masses (immovable bodies); add "
         "-fno-finite-math-only\"\n"
      << "#endif\n\n"
      << "// BILLIARDS_HOST_DEVICE marks every kernel __host__ __device__ under a CUDA compiler, so the "
         "same\n"
      << "// derived code runs in CUDA kernels; elsewhere it is empty. Define it first to override.\n"
      << "#ifndef BILLIARDS_HOST_DEVICE\n"
      << "#if defined(__CUDACC__)\n"
      << "#define BILLIARDS_HOST_DEVICE __host__ __device__\n"
      << "#else\n"
      << "#define BILLIARDS_HOST_DEVICE\n"
      << "#endif\n"
      << "#endif\n\n"
      << "namespace " << support_namespace << " {\n\n";
  out << "/// |x|, constexpr (std::abs is not before C++23).\n"
      << "template <typename Scalar>\n"
      << "BILLIARDS_HOST_DEVICE constexpr Scalar absolute_value(Scalar x) noexcept {\n"
      << "  return x < Scalar(0) ? -x : x;\n"
      << "}\n\n"
      << "/// The smallest positive normal number, `std::numeric_limits<Scalar>::min()`, also in device "
         "code.\n"
      << "template <typename Scalar>\n"
      << "BILLIARDS_HOST_DEVICE constexpr Scalar smallest_normal() noexcept {\n"
      << "  return std::numeric_limits<Scalar>::min();\n"
      << "}\n"
      << float_and_double("smallest_normal", "The smallest positive normal float, 2^−126.", "0x1p-126f",
                          "The smallest positive normal double, 2^−1022.", "0x1p-1022")
      << "\n"
      << "/// +∞, `std::numeric_limits<Scalar>::infinity()`, also in device code.\n"
      << "template <typename Scalar>\n"
      << "BILLIARDS_HOST_DEVICE constexpr Scalar infinity() noexcept {\n"
      << "  return std::numeric_limits<Scalar>::infinity();\n"
      << "}\n"
      << float_and_double("infinity", "+∞ in float.", "__builtin_huge_valf()", "+∞ in double.",
                          "__builtin_huge_val()");
  {
    out << power_of_two_range(
        "The plain form's mass range [4 √x_min, 1/(4 √x_min)], x_min = `smallest_normal<Scalar>()`: 2^−509 "
        "to "
        "2^509 in double, 2^−61 to 2^61 in float. Within it m1 + m2, (1 + e)/(m1 + m2) and each (1 + e) "
        "m_i/(m1 + m2) are normal numbers, so the one-division form keeps every digit.",
        "plain_mass", "4", "  // 4 √x_min = 4 · 2^((min_exponent − 1)/2)",
        "(1 - std::numeric_limits<Scalar>::min_exponent) / 2", {"2^−61 in float.", "0x1p-61f"},
        {"2^−509 in double.", "0x1p-509"});
  }
  {
    out << power_of_two_range(
        "The moderate range [2^−(E/4 − 2), 2^(E/4 − 2)], E = `std::numeric_limits<Scalar>::max_exponent`: "
        "2^−254 to 2^254 in double, 2^−30 to 2^30 in float. A product or quotient of four numbers in it, "
        "times 2/7 or 5/2, is a normal number, so a monomial kernel's plain form keeps every digit there.",
        "moderate", "1", "", "std::numeric_limits<Scalar>::max_exponent / 4 - 2",
        {"2^−30 in float.", "0x1p-30f"}, {"2^−254 in double.", "0x1p-254"});
  }
  {
    out << "\n/// Whether Scalar is IEEE float or double, whose positive numbers order as their bits.\n"
        << "template <typename Scalar>\n"
        << "constexpr bool orders_as_bits() noexcept {\n"
        << "  return std::numeric_limits<Scalar>::is_iec559 && (sizeof(Scalar) == 4 || sizeof(Scalar) == "
           "8);\n"
        << "}\n"
        << "/// The unsigned integer type of Scalar's width, for IEEE float and double.\n"
        << "template <typename Scalar>\n"
        << "using BitsOf = std::conditional_t<sizeof(Scalar) == 4, std::uint32_t, std::uint64_t>;\n";
  }
  {
    out << "/// The bits of x minus those of low, as an unsigned integer of Scalar's width, for IEEE float "
           "and\n"
        << "/// double (orders_as_bits). For finite 0 < low ≤ high, low ≤ x ≤ high exactly when\n"
        << "/// bits_above(x, low) ≤ bits_above(high, low): positive numbers order as their bits, and an x "
           "below\n"
        << "/// low (+0 included) wraps around, and a negative x (−0 included), +∞ and a NaN lie above it.\n"
        << "/// Host code; on the device the predicates compare the numbers.\n"
        << "template <typename Scalar>\n"
        << "constexpr auto bits_above(Scalar x, Scalar low) noexcept {\n"
        << "  using Bits = BitsOf<Scalar>;\n"
        << "  return static_cast<Bits>(std::bit_cast<Bits>(x) - std::bit_cast<Bits>(low));\n"
        << "}\n"
        << "/// The larger of two unsigned integers.\n"
        << "template <typename Bits>\n"
        << "constexpr Bits larger(Bits a, Bits b) noexcept {\n"
        << "  return a > b ? a : b;\n"
        << "}\n";
  }
  out << scaling_helpers() << "\n}  // namespace " << support_namespace << "\n";
  return with_fingerprint(out.str(), "");
}

std::string reference_kernels_header(const Derivation& derivation, const std::string& audit_text) {
  std::ostringstream out;
  out << preamble(
             "Reference kernels for the benchmark only, not part of the runtime and not installed: the "
             "derivation of " +
             derivation.model.citation +
             " before simplification, printed from the same derived "
             "expressions as " +
             derivation.model.kernels_path + " and proven the same way.")
      << "#pragma once\n\n"
      << "#include <" << derivation.model.kernels_path << ">\n\n"
      << "#include <cmath>\n\n"
      << "namespace " << derivation.model.reference_namespace << " {\n\n"
      << "using " << derivation.model.kernels_namespace << "::" << derivation.model.pair_result.name << ";\n"
      << functions(derivation.reference_kernels, derivation.model.pair_result) << "\n}  // namespace "
      << derivation.model.reference_namespace << "\n";
  return with_fingerprint(out.str(), audit_text);
}

namespace {

std::string parameter_name(const ex& parameter) { return GiNaC::ex_to<GiNaC::symbol>(parameter).get_name(); }

// `if (name == "kernel") { … return {outputs}; }` for call().
std::string call_branch(const Kernel& kernel, const std::string& qualified) {
  std::vector<std::string> arguments;
  for (const ex& parameter : kernel.parameters)
    arguments.push_back("at(\"" + parameter_name(parameter) + "\")");
  std::string out = "  if (name == \"" + kernel.name + "\") {\n";
  std::string call = qualified + "(";
  for (std::size_t i = 0; i < arguments.size(); ++i) call += (i ? ", " : "") + arguments[i];
  call += ");";
  // As clang-format lays it out: on one line, else broken after "=", else aligned under the "(".
  if (19 + call.size() <= column_limit) {
    out += "    const auto r = " + call + "\n";
  } else if (8 + call.size() <= column_limit) {
    out += "    const auto r =\n        " + call + "\n";
  } else {
    out += wrapped_list("    const auto r = " + qualified + "(", arguments, ");") + "\n";
  }
  out += kernel.outputs.size() == 1 ? "    return {r};\n" : "    return {r.first, r.second};\n";
  return out + "  }\n";
}

}  // namespace

std::string kernel_list_header(const Derivation& derivation, const std::string& audit_text) {
  const ModelInfo& model = derivation.model;
  std::size_t largest_arity = 0;
  for (const Kernel& kernel : derivation.kernels)
    largest_arity = std::max(largest_arity, kernel.parameters.size());
  std::ostringstream out;
  out << preamble("For tests only, not installed: every kernel of " + model.citation +
                  ", listed by the derivation, so that tests call, measure and compile each one without a "
                  "list kept by hand.")
      << "#pragma once\n\n"
      << "#include <" << model.kernels_path << ">\n";
  if (!model.reference_path.empty()) out << "#include <" << model.reference_path << ">\n";
  out << "\n#include <cstddef>\n#include <stdexcept>\n#include <string>\n#include <vector>\n\n"
      << "namespace " << model.kernels_namespace << "::list {\n\n"
      << "/// The most parameters any kernel takes.\n"
      << "inline constexpr std::size_t largest_arity = " << largest_arity << ";\n\n"
      << doc_comment(
             "Calls the kernel or reference kernel `name` with its arguments looked up by parameter "
             "name, `at(\"m1\")`; returns its outputs in order. Throws std::invalid_argument for an "
             "unknown name.")
      << "template <typename Scalar, typename Arguments>\n"
      << "std::vector<Scalar> call(const std::string& name, const Arguments& at) {\n";
  for (const Kernel& kernel : derivation.kernels) out << call_branch(kernel, kernel.name);
  for (const Kernel& kernel : derivation.reference_kernels) {
    out << call_branch(kernel, model.reference_namespace + "::" + kernel.name);
  }
  out << "  throw std::invalid_argument(\"no kernel named \" + name);\n}\n\n"
      << doc_comment(
             "Every kernel called with arguments taken in order from `a` (at least largest_arity of "
             "them), its outputs summed: instantiates every kernel for Scalar, on the host or a device.")
      << "template <typename Scalar>\n"
      << "BILLIARDS_HOST_DEVICE Scalar sum_of_every_kernel(const Scalar* a) noexcept {\n"
      << "  Scalar sum = Scalar(0);\n";
  for (const Kernel& kernel : derivation.kernels) {
    std::vector<std::string> arguments;
    for (std::size_t i = 0; i < kernel.parameters.size(); ++i)
      arguments.push_back("a[" + std::to_string(i) + "]");
    if (kernel.outputs.size() == 1) {
      out << wrapped_list("  sum += " + kernel.name + "(", arguments, ");") << "\n";
    } else {
      out << "  {\n"
          << wrapped_list("    const auto r = " + kernel.name + "(", arguments, ");") << "\n"
          << "    sum += r.first + r.second;\n  }\n";
    }
  }
  out << "  return sum;\n}\n\n}  // namespace " << model.kernels_namespace << "::list\n";
  return with_fingerprint(out.str(), audit_text);
}

}  // namespace billiards::derive
