#include "prove/canaries.hpp"

#include "core/named_constants.hpp"
#include "core/powers_of_two.hpp"
#include "prove/cpp_reader.hpp"
#include "emit/emitter.hpp"
#include "prove/gappa.hpp"
#include "emit/kernel.hpp"
#include "prove/rounding.hpp"

#include <unistd.h>

#include <exception>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace billiards::derive {

namespace {

using GiNaC::ex;
using GiNaC::numeric;

const BinaryFormat& format_named(const std::string& type) {
  for (const BinaryFormat& format : emitted_formats()) {
    if (format.type == type) return format;
  }
  throw std::logic_error("no format " + type);
}

// The largest finite number of a format, (2^digits − 1) 2^(max_exponent − digits).
numeric largest_finite(const BinaryFormat& format) {
  return (numeric(2).power(format.digits) - 1) * numeric(2).power(format.max_exponent - format.digits);
}

// The canaries' kernel, product = x · y over 1 ≤ x ≤ x_high, 1 ≤ y ≤ y_high, printed by the emitter and
// read back by the reader, as a kernel's plain form is.
struct Printed {
  Kernel kernel;
  CppFunction function;
};

Printed product_kernel(const numeric& x_high, const numeric& y_high) {
  static const GiNaC::symbol x("x"), y("y"), product("product");
  Printed out;
  Kernel& k = out.kernel;
  k.name = "canary_product";
  k.parameters = {x, y};
  k.steps = {{product, x * y}};
  k.outputs = {product};
  k.domain = {1 <= x, x <= x_high, 1 <= y, y <= y_high};
  std::string text = "template <typename Scalar>\nScalar canary_product(Scalar x, Scalar y) noexcept {\n";
  for (const std::string& line : emit_kernel(k).body) text += "  " + line + "\n";
  text += "}\n";
  out.function = read_functions(text).at(0);
  return out;
}

// Whether the kernel's plain form is proven in `type`: "proven", or "refused".
std::string proven_in(const Printed& printed, const std::string& type) {
  std::vector<RoundingBound> bounds;
  const std::vector<KernelProblem> problems =
      prove_rounding_in(printed.function, printed.kernel, format_named(type), bounds);
  return problems.empty() && !bounds.empty() ? "proven" : "refused";
}

// The range at the largest finite number: x up to 2^k and y up to largest/2^k, so that x · y reaches the
// largest finite number exactly; with `wider`, y one ulp past it, where x · y overflows.
Printed at_the_edge(const std::string& type, bool wider) {
  const BinaryFormat& format = format_named(type);
  const int k = format.max_exponent - 28;
  const numeric y_high = largest_finite(format) / numeric(2).power(k);
  const numeric ulp = numeric(2).power(format.max_exponent - format.digits - k);
  return product_kernel(numeric(2).power(k), wider ? y_high + ulp : y_high);
}

// Gappa's bound on the relative error of x · y over [1, 2]² in `type`, as a power of two.
std::string one_rounding_bound(const std::string& type) {
  const Printed printed = product_kernel(2, 2);
  std::vector<RoundingBound> bounds;
  const std::vector<KernelProblem> problems =
      prove_rounding_in(printed.function, printed.kernel, format_named(type), bounds);
  if (!problems.empty() || bounds.size() != 1 || bounds[0].relative.size() != 1)
    return "refused: " + (problems.empty() ? std::string("no bound") : problems[0].reason);
  const numeric bound = bounds[0].relative[0];
  const std::optional<int> k = exact_binary_logarithm(bound);
  if (k) return "2^" + std::to_string(*k);
  std::ostringstream text;
  text << bound;
  return "a bound of " + text.str() + ", no power of two";
}

std::string verdict(const std::string& script) { return run_gappa(script).proven ? "proven" : "refused"; }

std::string reader_grouping() {
  // Each as C++ groups it (the standard's precedence; left to right within a row), every binary operation
  // in parentheses, a negation as -x.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"a * b / c", "((a * b) / c)"},
      {"a / b * c", "((a / b) * c)"},
      {"a - b + c", "((a - b) + c)"},
      {"a - b - c", "((a - b) - c)"},
      {"a - (b - c)", "(a - (b - c))"},
      {"a + b * c / d", "(a + ((b * c) / d))"},
      {"-a * b", "(-a * b)"},
      {"a * -b", "(a * -b)"},
      {"-(f(a * b, k))", "-f((a * b), k)"},
      {"a < b + c && d <= e", "((a < (b + c)) && (d <= e))"},
      {"(x >> s) & m", "((x >> s) & m)"},
      {"!(k >= a) ? b : c", "(!(k >= a) ? b : c)"}};
  for (const auto& [text, expected] : cases) {
    const std::string read = spelled(read_expression(text));  // every operation in parentheses
    if (read != expected) return "`" + text + "` read as " + read;
  }
  // And the round trip: a statement printed again is the text it was read from.
  const std::vector<CppFunction> functions = read_functions(
      "template <typename Scalar>\nScalar f(Scalar a, Scalar b, Scalar c) noexcept {\n"
      "  const Scalar q = a * b / c;\n  return -(q - a - b);\n}\n");
  for (const CppStatement& s : functions.at(0).body) {
    if (!reads_as_printed(s)) return "a statement read back as `" + printed_again(s) + "`";
  }
  return "as C++ groups it";
}

std::string cache_one_line_apart() {
  const Printed printed = product_kernel(2, 2);
  const std::string kept = gappa_script(printed.function, printed.kernel, format_named("float"), {}, {});
  const std::string other = gappa_script(printed.function, printed.kernel, format_named("double"), {}, {});
  std::string folder = (std::filesystem::temp_directory_path() / "billiards-canary-XXXXXX").string();
  if (mkdtemp(folder.data()) == nullptr) return "failed: cannot make a folder for the cache";
  struct Remove {
    std::string folder;
    ~Remove() {
      std::error_code ignored;
      std::filesystem::remove_all(folder, ignored);
    }
  } remove{folder};
  const ProofCache cache(folder, "Gappa canary\n");
  cache.keep(kept, 0, "kept");
  const auto found = cache.find(kept);
  if (!found || found->first != 0 || found->second != "kept") return "the kept script misses";
  std::vector<std::pair<std::string, std::string>> apart = {{"the double script", other}};
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < kept.size();) {
    const std::size_t end = kept.find('\n', at);
    lines.push_back(kept.substr(at, end - at + 1));
    at = end + 1;
  }
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::string dropped, changed;
    for (std::size_t j = 0; j < lines.size(); ++j) {
      dropped += j == i ? "" : lines[j];
      changed += j == i ? lines[j].substr(0, lines[j].size() - 1) + " \n" : lines[j];
    }
    apart.emplace_back("line " + std::to_string(i + 1) + " dropped", dropped);
    apart.emplace_back("line " + std::to_string(i + 1) + " changed", changed);
  }
  for (const auto& [which, script] : apart) {
    if (cache.find(script)) return "the kept script with " + which + " hits";
  }
  return "the kept script hits; every script one line apart misses";
}

}  // namespace

const std::vector<Canary>& prover_canaries() {
  static const std::vector<Canary> canaries = [] {
    std::vector<Canary> out = {
        {"gappa.refuses_a_false_property",
         "x in [1, 2] -> x + 1 in [0, 2] (false), beside a goal Gappa answers (so that it prints Results:)",
         "refused",
         [] {
           return verdict(
               "@rnd = float<ieee_64, ne>;\nx = rnd(input_x);\n{ x in [1, 2] -> x + 1 in [0, 2] /\\ x * x in "
               "? }\n");
         }},
        {"gappa.proves_a_true_property", "x in [1, 2] -> x + 1 in [2, 3]", "proven",
         [] {
           return verdict(
               "@rnd = float<ieee_64, ne>;\nx = rnd(input_x);\n{ x in [1, 2] -> x + 1 in [2, 3] }\n");
         }},
    };
    for (const std::string type : {"float", "double"}) {
      out.push_back({"range." + type + "_up_to_the_largest_finite_is_proven",
                     "x · y with x in [1, 2^k], y in [1, largest/2^k] keeps every digit in " + type, "proven",
                     [type] { return proven_in(at_the_edge(type, false), type); }});
      out.push_back({"range." + type + "_one_ulp_wider_is_refused",
                     "the same with y's upper end one ulp higher overflows in " + type, "refused",
                     [type] { return proven_in(at_the_edge(type, true), type); }});
      out.push_back({"precision." + type + "_rounds_as_" + type,
                     "the relative error of x · y over [1, 2]² in " + type + " is bounded by 2^-digits",
                     type == "float" ? "2^-24" : "2^-53", [type] { return one_rounding_bound(type); }});
      out.push_back({"precision." + type + "_product_beyond_float",
                     "x · y over [1, 2^100]² overflows in float and not in double; in " + type,
                     type == "float" ? "refused" : "proven", [type] {
                       return proven_in(product_kernel(numeric(2).power(100), numeric(2).power(100)), type);
                     }});
    }
    out.push_back({"cache.one_line_apart_misses",
                   "an answer kept for x · y's float script, asked for that script and for every script one "
                   "line apart (each line changed or dropped, the double script)",
                   "the kept script hits; every script one line apart misses", cache_one_line_apart});
    out.push_back(
        {"reader.keeps_the_grouping",
         "expressions read as C++ groups them (a * b / c as (a * b) / c, -a * b as (-a) * b, …) and "
         "statements printed again as read",
         "as C++ groups it", reader_grouping});
    return out;
  }();
  return canaries;
}

std::vector<CanaryOutcome> ask_canaries(const std::vector<Canary>& canaries) {
  std::vector<CanaryOutcome> out;
  for (const Canary& canary : canaries) {
    std::string answered;
    try {
      answered = canary.ask();
    } catch (const std::exception& error) {
      answered = std::string("failed: ") + error.what();
    }
    out.push_back({canary.id, canary.statement, canary.expected, answered});
  }
  return out;
}

}  // namespace billiards::derive
