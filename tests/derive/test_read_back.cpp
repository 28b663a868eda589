// Proven is what is printed: the reader of the emitted C++, the proof of a header from its text, and a
// derivation step that stops.
#include "core/named_constants.hpp"
#include "core/record.hpp"
#include "prove/cpp_reader.hpp"
#include "emit/emitter.hpp"
#include "prove/read_back.hpp"
#include "models/parkin2023/paper.hpp"
#include "models/spinning/spinning.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

using namespace billiards::derive;
using GiNaC::ex;

namespace {

// A kernels header as the prover reads it: the support header's helpers first.
std::string with_support(const std::string& header) { return kernel_support_header() + header; }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

// prove_printed with the rounding bounds it finds left aside.
std::vector<KernelProblem> prove_printed(const std::string& header, const std::vector<Kernel>& kernels,
                                         const std::vector<Claim>& claims) {
  std::vector<RoundingBound> bounds;
  return billiards::derive::prove_printed(header, kernels, claims, bounds);
}

// The same without the Gappa proofs: for slips of the text, which the reading catches.
std::vector<KernelProblem> read_back(const std::string& header, const std::vector<Kernel>& kernels,
                                     const std::vector<Claim>& claims) {
  std::vector<RoundingBound> bounds;
  return billiards::derive::prove_printed(header, kernels, claims, bounds, [](const std::string&) { return false; });
}

std::string reasons(const std::vector<KernelProblem>& problems) {
  std::string out;
  for (const KernelProblem& p : problems) out += p.kernel + ": " + p.reason + "\n";
  return out;
}

}  // namespace

TEST_CASE("The reader of the emitted C++", "[derive][read_back]") {
  SECTION("operators bind as in C++") {
    CHECK(spelled(read_expression("a + b * c - d / e")) == "((a + (b * c)) - (d / e))");
    CHECK(spelled(read_expression("-(a - b) < c && d <= e")) == "((-(a - b) < c) && (d <= e))");
    CHECK(spelled(read_expression("x < Scalar(0) ? -x : x")) == "((x < Scalar(0)) ? -x : x)");
    CHECK(spelled(read_expression("smallest_normal<Scalar>() <= m1")) == "(smallest_normal<Scalar>() <= m1)");
    CHECK(spelled(read_expression("(std::bit_cast<Bits>(x) >> stored) & all_ones")) ==
          "((std::bit_cast<Bits>(x) >> stored) & all_ones)");
  }
  SECTION("a function template, a specialisation and their statements") {
    const std::vector<CppFunction> functions = read_functions(
        "namespace n {\n"
        "template <typename Scalar>\nstruct Pair {\n  Scalar first;\n};\n"
        "/// doc\ntemplate <typename Scalar>\nBILLIARDS_HOST_DEVICE constexpr Scalar f(Scalar a, Scalar b) "
        "noexcept {\n"
        "  const Scalar s = a + b;  // a comment\n  Scalar t = s;\n  if (s < Scalar(0)) t = -s;\n  return "
        "t;\n}\n"
        "template <>\nBILLIARDS_HOST_DEVICE constexpr float g<float>() noexcept {\n  return 0x1p-61f;\n}\n"
        "}  // namespace n\n");
    REQUIRE(functions.size() == 2);
    CHECK(functions[0].name == "f");
    CHECK(functions[0].result == "Scalar");
    CHECK(functions[0].parameters.size() == 2);
    REQUIRE(functions[0].body.size() == 4);
    CHECK(functions[0].body[0].type == "const Scalar");
    CHECK(functions[0].body[2].kind == CppStatement::Kind::if_);
    CHECK(functions[1].name == "g");
    CHECK(functions[1].specialization == "float");
    CHECK(spelled(*functions[1].body[0].value) == "0x1p-61f");
  }
  SECTION("a kernel list's strings, members, indices, throw and variable") {
    CHECK(spelled(read_expression("name == \"m1\"")) == "(name == \"m1\")");
    CHECK(spelled(read_expression("r.first + a[2]")) == "(r.first + a[2])");
    const std::vector<CppFunction> functions = read_functions(
        "inline constexpr std::size_t largest_arity = 6;\n"
        "template <typename Scalar, typename Arguments>\n"
        "std::vector<Scalar> call(const std::string& name, const Arguments& at) {\n"
        "  if (name == \"k\") {\n    const auto r = k(at(\"x\"));\n    return {r};\n  }\n"
        "  throw std::invalid_argument(\"no kernel named \" + name);\n}\n");
    REQUIRE(functions.size() == 1);
    REQUIRE(functions[0].body.size() == 2);
    CHECK(functions[0].body[0].body.at(0).kind == CppStatement::Kind::block);
    CHECK(functions[0].body[1].kind == CppStatement::Kind::throw_);
  }
  SECTION("anything outside the subset is an error naming the line") {
    CHECK_THROWS_AS(read_functions("int f() {\n  return 1 +;\n}\n"), CppReadError);
    CHECK_THROWS_WITH(read_functions("int f() {\n  while (1) {}\n}\n"), Catch::Contains("line 2"));
  }
}

TEST_CASE("A printed header is proven from its text", "[derive][read_back]") {
  SECTION("every model's header, and the slips the reader must see") {
    for (const Derivation& derivation : {parkin2023::derive(), spinning::derive()}) {
      const std::string header = with_support(kernels_header(derivation, "{}"));
      INFO(derivation.model.name);
      CHECK(reasons(prove_printed(header, derivation.kernels, derivation.claims)).empty());
      // Each of these is a slip the reader must see: a relational operator changed, a function printed
      // that nothing proves, a kernel missing.
      const bool spinning = derivation.model.name == "spinning";
      const std::string from = spinning ? "if (m2 < m1)" : "if (gap < Scalar(0))";
      const std::string to = spinning ? "if (m2 <= m1)" : "if (gap <= Scalar(0))";
      CHECK_FALSE(read_back(replaced(header, from, to), derivation.kernels, derivation.claims).empty());
      const std::string extra = replaced(
          header, "/// |x|,",
          "template <typename Scalar>\nScalar twice(Scalar x) noexcept {\n  return x + x;\n}\n/// |x|,");
      CHECK_THAT(reasons(read_back(extra, derivation.kernels, derivation.claims)),
                 Catch::Contains("twice: as printed: is printed but nothing reads it back"));
      std::vector<Kernel> more = derivation.kernels;
      more.push_back(more.front());
      more.back().name = "unprinted_kernel";
      more.back().fast_path.reset();
      CHECK_THAT(reasons(read_back(header, more, derivation.claims)),
                 Catch::Contains("unprinted_kernel: as printed: the function is not in the header"));
    }
  }
  SECTION("the reference header too") {
    const Derivation derivation = parkin2023::derive();
    const std::string header = reference_kernels_header(derivation, "{}");
    CHECK(reasons(prove_printed(header, derivation.reference_kernels, derivation.claims)).empty());
    CHECK_FALSE(prove_printed(replaced(header, "Scalar(4) * quadratic_a", "Scalar(2) * quadratic_a"),
                              derivation.reference_kernels, derivation.claims)
                    .empty());
  }
  SECTION("text that cannot be read is a problem, not an exception") {
    const Derivation derivation = parkin2023::derive();
    CHECK_THAT(reasons(prove_printed("int f( {", derivation.kernels, derivation.claims)),
               Catch::Contains("cannot be read back"));
  }
}

TEST_CASE("A step that stops names itself and the claim it was building", "[derive][read_back]") {
  const GiNaC::symbol x("x");
  SECTION("inside a claim") {
    Record record;
    record_steps(record, [&](Recorder& recorder) {
      recorder.section("first_step", "First", "");
      recorder.add({.id = "first.fine", .paper_expression = x, .derived_expression = x});
      recorder.section("second_step", "Second", "");
      recorder.add({.id = "second.divides_by_zero", .paper_expression = x, .derived_expression = x / 0});
    });
    REQUIRE(record.claims.size() == 2);
    const Claim& stopped = record.claims.back();
    CHECK(stopped.id == "derivation.stopped");
    CHECK(stopped.verdict == Verdict::failed);
    CHECK(stopped.section == "second_step");
    CHECK_THAT(stopped.failure, Catch::Contains("the step `second_step` stopped while building the claim "
                                                "`second.divides_by_zero`"));
    CHECK_THAT(stopped.failure, Catch::Contains("division by zero"));
  }
  SECTION("between claims") {
    Record record;
    record_steps(record, [&](Recorder& recorder) {
      recorder.section("only_step", "Only", "");
      recorder.add({.id = "only.fine", .paper_expression = x, .derived_expression = x});
      const GiNaC::ex broken = x / 0;
      recorder.add({.id = "only.never", .paper_expression = broken, .derived_expression = x});
    });
    CHECK_THAT(
        record.claims.back().failure,
        Catch::Contains("the step `only_step` stopped after the claim `only.fine`, outside any claim"));
  }
}

TEST_CASE("Gappa proves each fast path's domain safe, from the plain form as printed",
          "[derive][read_back]") {
  const Derivation derivation = parkin2023::derive();
  const std::string header = with_support(kernels_header(derivation, "{}"));
  std::vector<RoundingBound> bounds;
  REQUIRE(reasons(billiards::derive::prove_printed(header, derivation.kernels, derivation.claims, bounds))
              .empty());
  // Every kernel, in float and double: the four plain forms, the cushion and time_of_impact in one case
  // each, the four full forms in four (beyond_plain_mass_cases).
  CHECK(bounds.size() == 2 * (4 + 1 + 1 + 4 * 4));
  for (const Kernel& kernel : derivation.kernels) {
    for (const std::string format : {"float", "double"}) {
      INFO(kernel.name << " in " << format);
      CHECK(std::count_if(bounds.begin(), bounds.end(), [&](const RoundingBound& b) {
              return b.kernel == kernel.name && b.format == format;
            }) == (kernel.fast_path ? 4 : 1));
    }
  }
  for (const RoundingBound& bound : bounds) {
    INFO(bound.kernel << " in " << bound.format);
    // −2 v·n is exact: a doubling and a negation.
    if (bound.kernel == "cushion_normal_velocity_change") CHECK(bound.relative.front() == 0);
    if (bound.kernel.find("velocity_change") != std::string::npos && bound.kernel.rfind("cushion", 0) != 0)
      CHECK(bound.outputs.size() == 2);
    if (bound.kernel != "plain_elastic_normal_velocity_change") continue;
    // By hand: m1 + m2, 2 m2 over it, v2n − v1n and their product round once each (2 m2 is exact), so
    // the relative error is at most (1 + u)^4 − 1, u = ε/2: just over 2 ε.
    const GiNaC::numeric u = GiNaC::numeric(2).power(bound.format == "float" ? -24 : -53);
    for (const GiNaC::numeric& relative : bound.relative) {
      CHECK(relative >= 4 * u * GiNaC::numeric(99, 100));
      CHECK(relative <= (1 + u).power(4) - 1 + u * GiNaC::numeric(1, 100));
    }
    CHECK(bound.in_epsilons.front() == Approx(2.01));
  }
  SECTION("the script is the printed kernel, rounded, over the domain in the type") {
    const std::vector<CppFunction> functions = read_functions(header);
    const auto plain = std::find_if(functions.begin(), functions.end(), [](const CppFunction& f) {
      return f.name == "plain_elastic_normal_velocity_change";
    });
    REQUIRE(plain != functions.end());
    const Kernel& kernel = derivation.kernels.front();
    REQUIRE(kernel.name == plain->name);
    const std::string script =
        gappa_script(*plain, kernel, emitted_formats().back(), kernel.rounding_cases.front(), {});
    CHECK_THAT(script, Catch::Contains("@rnd = float<ieee_64, ne>;"));
    CHECK_THAT(script, Catch::Contains("c_total_mass rnd= (p_m1 + p_m2);"));
    CHECK_THAT(script, Catch::Contains("p_m1 in [1b-509, 1b509]"));
    CHECK_THAT(script, Catch::Contains("(p_v2n - p_v1n) in [1, 2]"));
    CHECK_THAT(script, Catch::Contains("(c_first_change - e_first_change) / e_first_change in ?"));
  }
  SECTION("a full form's case: its masses in the type, its guards as decided, its intermediates finite") {
    const std::vector<CppFunction> functions = read_functions(header);
    const auto full = std::find_if(functions.begin(), functions.end(), [](const CppFunction& f) {
      return f.name == "full_elastic_normal_velocity_change";
    });
    REQUIRE(full != functions.end());
    const Kernel& kernel = derivation.kernels.at(1);
    REQUIRE(kernel.name == "elastic_normal_velocity_change");
    // The light first ball beside a heavy second one whose share underflows: the second change from the
    // impulse per total mass times m1.
    const std::string script = gappa_script(*full, kernel, emitted_formats().back(),
                                            kernel.rounding_cases.at(2), {false, false, true, true});
    CHECK_THAT(script, Catch::Contains("p_m1 in [1b-1, 5b-3] /\\ p_m2 in [3b1021, 7b1020]"));
    CHECK_THAT(script, Catch::Contains("c_second_factor rnd= c_impulse_per_total_mass;"));
    CHECK_THAT(script, Catch::Contains("c_second_multiplier rnd= p_m1;"));
    CHECK_THAT(script, Catch::Contains("|c_first_mass_ratio| <= "));
    CHECK_THAT(script, Catch::Contains("|c_o_1| in [1b-1022, "));  // the output, −second_change
  }
  SECTION("a domain widened past what is safe is not proven") {
    Derivation widened = derivation;
    for (Kernel& k : widened.kernels) {
      for (ex& condition : k.domain) condition = condition.subs(plain_mass_low() == smallest_normal());
      if (k.fast_path)
        for (ex& condition : k.fast_path->conditions)
          condition = condition.subs(plain_mass_low() == smallest_normal());
    }
    std::vector<RoundingBound> none;
    CHECK_THAT(reasons(billiards::derive::prove_printed(with_support(kernels_header(widened, "{}")), widened.kernels,
                                                        widened.claims, none)),
               Catch::Contains("plain_elastic_normal_velocity_change: its rounding proof: in float"));
  }
}
