// The prover checked: Gappa's verdict read exactly, the proof cache keyed by the whole script, the
// reader's round trip, the bit helpers run from their text, a printer that ends on any expression, and the
// canaries every run asks.
#include "core/powers_of_two.hpp"
#include "prove/bit_helpers.hpp"
#include "prove/canaries.hpp"
#include "prove/cpp_reader.hpp"
#include "prove/gappa.hpp"
#include "print/printer.hpp"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace billiards::derive;

namespace {

// A folder of its own, removed at the end of the test.
struct ScratchFolder {
  std::filesystem::path path;
  ScratchFolder() {
    std::string name = (std::filesystem::temp_directory_path() / "billiards-test-XXXXXX").string();
    REQUIRE(mkdtemp(name.data()) != nullptr);
    path = name;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = text.find('\n', at);
    lines.push_back(text.substr(at, end - at + 1));
    at = end + 1;
  }
  return lines;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += line;
  return out;
}

std::string read_text(const std::string& path) {
  std::ifstream file(path);
  REQUIRE(file);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

const std::string script =
    "@rnd = float<ieee_32, ne>;\n"
    "p_x = rnd(input_x);\n"
    "p_y = rnd(input_y);\n"
    "c_product rnd= (p_x * p_y);\n"
    "e_product = (p_x * p_y);\n"
    "{ p_x in [1, 2] /\\ p_y in [1, 2]\n"
    "  -> |c_product| in [1b-126, 16777215b104]\n"
    "  /\\ (c_product - e_product) / e_product in ? }\n";

}  // namespace

TEST_CASE("Gappa's verdict is its own success: exit status 0 and no property unsatisfied",
          "[derive][prover]") {
  SECTION("a clean exit is a proof") { CHECK(gappa_proved(0, "Results:\n  x in [1, 2]\n")); }
  SECTION("a failure status is none, whatever Gappa printed") {
    CHECK_FALSE(gappa_proved(1, "Results:\n  x in [1, 2]\n"));
    CHECK_FALSE(gappa_proved(-1, ""));
  }
  SECTION("an unsatisfied property or an error is none, whatever the status") {
    CHECK_FALSE(
        gappa_proved(0, "Error: some properties were not satisfied:\n  BND(x), best: [2, 3]\nResults:\n"));
    CHECK_FALSE(gappa_proved(0, "Error: no contradiction was found.\n"));
  }
  SECTION("Gappa itself: a false property beside a goal it answers prints Results: and is refused") {
    const GappaAnswer answer = run_gappa(
        "@rnd = float<ieee_64, ne>;\nx = rnd(input_x);\n{ x in [1, 2] -> x + 1 in [0, 2] /\\ x * x in ? }\n");
    CHECK(answer.output.find("Results:") != std::string::npos);
    CHECK_FALSE(answer.proven);
    CHECK(gappa_failure(answer.output).find("x + 1") != std::string::npos);
  }
  SECTION("Gappa itself: a true property is proven") {
    CHECK(run_gappa("@rnd = float<ieee_64, ne>;\nx = rnd(input_x);\n{ x in [1, 2] -> x + 1 in [2, 3] }\n")
              .proven);
  }
}

TEST_CASE("The proof cache answers only for the very script and Gappa version it kept", "[derive][prover]") {
  const ScratchFolder folder;
  const ProofCache cache(folder.path, "Gappa 1.4.1\n");
  cache.keep(script, 0, "proven, as Gappa printed it");
  const auto found = cache.find(script);
  REQUIRE(found);
  CHECK(found->first == 0);
  CHECK(found->second == "proven, as Gappa printed it");

  SECTION("changing any single line of the script misses, and so does dropping or repeating it") {
    const std::vector<std::string> lines = lines_of(script);
    REQUIRE(lines.size() == 8);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      for (const std::string& changed : {lines[i].substr(0, lines[i].size() - 1) + " \n", std::string(),
                                         lines[i] + lines[i], "x" + lines[i]}) {
        std::vector<std::string> other = lines;
        other[i] = changed;
        INFO("line " << i + 1 << " as `" << changed << "`");
        CHECK_FALSE(cache.find(joined(other)));
      }
    }
  }
  SECTION("the same script for double misses: the @rnd line is part of the key") {
    std::string double_script = script;
    double_script.replace(double_script.find("ieee_32"), 7, "ieee_64");
    CHECK_FALSE(cache.find(double_script));
    CHECK(cache.path(double_script) != cache.path(script));
  }
  SECTION("another Gappa version misses") {
    const ProofCache other(folder.path, "Gappa 1.4.2\n");
    CHECK_FALSE(other.find(script));
  }
  SECTION("only proven and unproven answers are kept") {
    const std::string other = script + "# another\n";
    cache.keep(other, 2, "a crash");
    CHECK_FALSE(cache.find(other));
  }
  SECTION("no version, no cache") {
    const ProofCache none(folder.path, "");
    none.keep(script + "\n", 0, "");
    CHECK_FALSE(none.find(script + "\n"));
  }
}

TEST_CASE("The reader's round trip: a statement printed again is the text it was read from",
          "[derive][prover]") {
  const std::vector<CppFunction> functions = read_functions(
      "template <typename Scalar>\n"
      "Scalar f(Scalar a, Scalar b, Scalar c) noexcept {\n"
      "  const Scalar q = a * b / c;\n"
      "  const Scalar r = a - (b - c) * -q;\n"
      "  Scalar s = -(a + b);\n"
      "  if (q < smallest_normal<Scalar>() && !(r >= Scalar(0))) s = (a + b) / (c * q);\n"
      "  return (x >> 3) & m ? s : -s;\n"
      "}\n");
  REQUIRE(functions.size() == 1);
  for (const CppStatement& s : functions[0].body) {
    INFO(printed_again(s));
    CHECK(reads_as_printed(s));
  }
  SECTION("a statement whose expression is grouped otherwise does not read as printed") {
    CppStatement q = functions[0].body[0];  // a * b / c, regrouped as a * (b / c)
    CppExpression& product = q.value->operands[0];
    REQUIRE(product.text == "*");
    CppExpression quotient = *q.value;
    quotient.operands[0] = product.operands[1];
    CppExpression regrouped = product;
    regrouped.operands[1] = quotient;
    q.value = regrouped;
    CHECK(printed_again(q) == "const Scalar q = a * (b / c);");
    CHECK_FALSE(reads_as_printed(q));
  }
  SECTION("a dropped negation does not read as printed") {
    CppStatement s = functions[0].body[2];
    const CppExpression negated = s.value->operands.at(0);  // a copy: the value is replaced by a part of it
    s.value = negated;
    CHECK_FALSE(reads_as_printed(s));
  }
}

TEST_CASE("The bit helpers are run from their text over every exponent", "[derive][prover]") {
  const std::string header =
      read_text(std::string(BILLIARDS_SOURCE_DIR) + "/generated/billiards/kernel_support.hpp");
  const std::vector<CppFunction> functions = read_functions(header);
  CHECK(prove_bit_helpers(functions).empty());
  SECTION("an exponent one off is found, in both formats") {
    std::string mutated = header;
    const std::string from = "static_cast<int>(field) - bias)";
    mutated.replace(mutated.find(from), from.size(), "static_cast<int>(field) - bias - 1)");
    const std::vector<KernelProblem> problems = prove_bit_helpers(read_functions(mutated));
    REQUIRE(problems.size() == 2);
    CHECK(problems[0].kernel == "binary_exponent");
    CHECK(problems[0].reason.find("in float (on the host)") != std::string::npos);
    CHECK(problems[1].reason.find("in double (on the host)") != std::string::npos);
  }
  SECTION("a scaling one off where it calls std::ldexp is found, on the device path too") {
    std::string mutated = header;
    const std::string from = "return std::ldexp(x, exponent);";
    mutated.replace(mutated.find(from), from.size(), "return std::ldexp(x, exponent + 1);");
    const std::vector<KernelProblem> problems = prove_bit_helpers(read_functions(mutated));
    REQUIRE_FALSE(problems.empty());
    for (const KernelProblem& p : problems) CHECK(p.kernel == "times_power_of_two");
    CHECK(std::any_of(problems.begin(), problems.end(), [](const KernelProblem& p) {
      return p.reason.find("the device path") != std::string::npos;
    }));
  }
}

TEST_CASE("The printer ends on any expression: deep nesting is elided in text, refused in C++",
          "[derive][prover]") {
  const GiNaC::symbol x("x"), y("y");
  GiNaC::ex deep = x;
  for (int i = 0; i < 3000; ++i) deep = binary_exponent(deep * y);  // 6000 levels, each printed once
  const std::string text = print(deep, Notation::text);
  CHECK(text.find("…") != std::string::npos);
  CHECK_THROWS_AS(print(deep, Notation::cpp), std::invalid_argument);
  SECTION("a power of two with a symbolic exponent prints in text") {
    const GiNaC::symbol k("k");
    CHECK(print(GiNaC::pow(2, k) * x, Notation::text).find("2^k") != std::string::npos);
  }
}

TEST_CASE("Every canary answers as a sound prover must, and one told otherwise does not",
          "[derive][prover]") {
  const std::vector<CanaryOutcome> outcomes = ask_canaries(prover_canaries());
  REQUIRE(outcomes.size() == prover_canaries().size());
  for (const CanaryOutcome& outcome : outcomes) {
    INFO(outcome.id << ": expected " << outcome.expected << ", answered " << outcome.answered);
    CHECK(outcome.as_expected());
  }
  std::vector<Canary> wrong = {prover_canaries().front()};
  wrong[0].expected = "proven";
  CHECK_FALSE(ask_canaries(wrong).at(0).as_expected());
  const Canary throws{"test.throws", "a canary that throws", "anything",
                      []() -> std::string { throw std::runtime_error("no Gappa"); }};
  const CanaryOutcome thrown = ask_canaries({throws}).at(0);
  CHECK(thrown.answered == "failed: no Gappa");
  CHECK_FALSE(thrown.as_expected());
}
