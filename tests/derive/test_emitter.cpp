// The emitter: C++ without pow or floating literals, common subexpressions hoisted, honest op counts.
#include "core/named_constants.hpp"
#include "core/powers_of_two.hpp"
#include "emit/emitter.hpp"
#include "models/parkin2023/paper.hpp"
#include "print/printer.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

using namespace billiards::derive;
using GiNaC::ex;

namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("C++ notation", "[derive][emitter]") {
  const GiNaC::symbol m1("m1"), m2("m2"), v("v");
  SECTION("numbers are Scalar(integer) or exact binary fractions, never a rounded literal") {
    CHECK(print(2 * m2 / (m1 + m2), Notation::cpp) == "Scalar(2) * m2 / (m1 + m2)");
    CHECK(print(ex(GiNaC::numeric(-3, 4)), Notation::cpp) == "-(Scalar(3) / Scalar(4))");
    // A coefficient p/2^k is one exact literal, 2^k/q a division by one: one rounding, no 7 v that
    // overflows where 3.5 v would not.
    CHECK(print(GiNaC::numeric(1, 2) * v, Notation::cpp) == "Scalar(0.5) * v");
    CHECK(print(GiNaC::numeric(7, 2) / m1, Notation::cpp) == "Scalar(3.5) / m1");
    CHECK(print(GiNaC::numeric(3, 64) * v, Notation::cpp) == "Scalar(0.046875) * v");
    CHECK(print(GiNaC::numeric(2, 7) * v, Notation::cpp) == "v / Scalar(3.5)");
    CHECK(print(GiNaC::numeric(-4, 5) / v, Notation::cpp) == "-(Scalar(1) / v / Scalar(1.25))");
    // Neither: an integer ratio, as before; nor beyond float's 24 bits.
    CHECK(print(GiNaC::numeric(3, 7) * v, Notation::cpp) == "Scalar(3) * v / Scalar(7)");
    CHECK(print(GiNaC::numeric(1, 1 << 25) * v, Notation::cpp) == "v / Scalar(33554432)");
  }
  SECTION("a power of two with an exponent that is no number scales, binary_exponent is the header's") {
    const GiNaC::symbol k("k"), j("j");
    CHECK(print(v * GiNaC::pow(2, -k), Notation::cpp) == "times_power_of_two(v, -k)");
    CHECK(print(-3 * v / m1 * GiNaC::pow(2, k - j), Notation::cpp) ==
          "-(times_power_of_two(Scalar(3) * v / m1, k - j))");
    CHECK(print(binary_exponent(m1 + m2), Notation::cpp) == "binary_exponent(m1 + m2)");
    CHECK(print(binary_exponent(v), Notation::latex) == "\\lfloor \\log_2 \\left|v\\right| \\rfloor");
  }
  SECTION("integer powers are products, reciprocals are divisions: no pow()") {
    CHECK(print(GiNaC::pow(v, 3), Notation::cpp) == "v * v * v");
    CHECK(print(1 / GiNaC::pow(m1 + m2, 2), Notation::cpp) == "Scalar(1) / ((m1 + m2) * (m1 + m2))");
  }
  SECTION("positive terms first, a negative product in parentheses") {
    CHECK(print(m2 - m1, Notation::cpp) == "m2 - m1");
    CHECK(print(-2 * v, Notation::cpp) == "-(Scalar(2) * v)");
  }
  SECTION("what C++ cannot say is an error naming it") {
    CHECK_THROWS_WITH(print(GiNaC::pow(v, GiNaC::numeric(1, 3)), Notation::cpp), Catch::Contains("v^(1/3)"));
    CHECK_THROWS_AS(print(GiNaC::sin(v), Notation::cpp), std::invalid_argument);
  }
}

TEST_CASE("Kernels", "[derive][emitter]") {
  const GiNaC::symbol m1("m1"), m2("m2"), v1n("v1n"), v2n("v2n");
  const GiNaC::symbol s("relative_normal_speed"), c1("c1"), c2("c2");
  Kernel kernel{.name = "test_kernel",
                .brief = "A test.",
                .parameters = {m1, m2, v1n, v2n},
                .steps = {{s, v2n - v1n}, {c1, 2 * m2 / (m1 + m2)}, {c2, 2 * m1 / (m2 + m1)}},
                .outputs = {c1 * s, -c2 * s},
                .claims = {"some.claim"},
                .names = {{"total_mass", m1 + m2}}};

  SECTION("a sum used twice is computed once, under the name given for it") {
    const EmittedKernel emitted = emit_kernel(kernel);
    REQUIRE(emitted.body.size() == 5);
    CHECK(emitted.body[0] == "const Scalar relative_normal_speed = v2n - v1n;");
    CHECK(emitted.body[1] == "const Scalar total_mass = m1 + m2;");
    CHECK(emitted.body[2] == "const Scalar c1 = Scalar(2) * m2 / total_mass;");
    CHECK(emitted.body[3] == "const Scalar c2 = Scalar(2) * m1 / total_mass;");
    CHECK(emitted.body[4] == "return {c1 * relative_normal_speed, -(c2 * relative_normal_speed)};");
    // − + (× ÷) (× ÷) × × and one negation
    CHECK(emitted.operation_count == 9);
  }
  SECTION("without a name the hoisted sum gets a numbered one") {
    kernel.names.clear();
    CHECK(emit_kernel(kernel).body[1] == "const Scalar common_subexpression_0 = m1 + m2;");
  }
  SECTION("a step with a guarded alternative form is the usual form, replaced under its condition") {
    const GiNaC::symbol limit("limit"), change("change");
    kernel.steps.push_back({change, c1 * s, {{m1 / m2 > limit, 2 * m2 * s / (m1 + m2)}}});
    kernel.outputs = {change, -c2 * s};
    const EmittedKernel emitted = emit_kernel(kernel);
    CHECK(emitted.body[4] == "Scalar change = c1 * relative_normal_speed;");
    CHECK(emitted.body[5] ==
          "if (m1 / m2 > limit) change = Scalar(2) * m2 * relative_normal_speed / total_mass;");
  }
  SECTION("guards apply in order, with every comparison operator, and a square root drops constexpr") {
    const GiNaC::symbol limit("limit"), change("change");
    kernel.steps.push_back({change,
                            GiNaC::sqrt(m1) * s,
                            {{m1 < limit, 0, Guard::Kind::piecewise},
                             {m1 <= limit, 1, Guard::Kind::piecewise},
                             {m1 >= limit, 2, Guard::Kind::piecewise},
                             {m1 == limit, 3, Guard::Kind::piecewise},
                             {m1 != limit, 4, Guard::Kind::piecewise}}});
    kernel.outputs = {change, -c2 * s};
    const EmittedKernel emitted = emit_kernel(kernel);
    CHECK(emitted.body[4] == "Scalar change = relative_normal_speed * std::sqrt(m1);");
    CHECK(emitted.body[5] == "if (m1 < limit) change = Scalar(0);");
    CHECK(emitted.body[6] == "if (m1 <= limit) change = Scalar(1);");
    CHECK(emitted.body[7] == "if (m1 >= limit) change = Scalar(2);");
    CHECK(emitted.body[8] == "if (m1 == limit) change = Scalar(3);");
    CHECK(emitted.body[9] == "if (m1 != limit) change = Scalar(4);");
    Derivation derivation;
    derivation.kernels = {kernel};
    const std::string header = kernels_header(derivation, "{}");
    CHECK(contains(header, "#include <cmath>\n"));
    CHECK(contains(header, "BILLIARDS_HOST_DEVICE NormalVelocityChange<Scalar> test_kernel("));
  }
  SECTION("a guard whose condition is no comparison names the kernel") {
    kernel.steps.push_back({GiNaC::symbol("change"), c1 * s, {{m1 + m2, 0}}});
    CHECK_THROWS_WITH(emit_kernel(kernel), Catch::Contains("test_kernel") && Catch::Contains("relational"));
  }
  SECTION("an expression with no C++ form names the kernel") {
    kernel.outputs = {GiNaC::Pi * s};
    CHECK_THROWS_WITH(emit_kernel(kernel), Catch::Contains("test_kernel"));
  }
  SECTION("the header names the claims, the op count and the fingerprint") {
    Derivation derivation;
    derivation.kernels = {kernel};
    const std::string header = kernels_header(derivation, "{}");
    CHECK(contains(header, "do not edit"));
    CHECK(contains(header, "// Fingerprint: fnv1a64:"));
    CHECK(contains(header, "`some.claim`"));
    CHECK(contains(header, "/// Total ops: 9"));
    CHECK(contains(header,
                   "template <typename Scalar>\nBILLIARDS_HOST_DEVICE constexpr NormalVelocityChange<Scalar> "
                   "test_kernel("));
    CHECK(contains(header, ") noexcept {"));
    CHECK_FALSE(contains(header, "pow("));
    // The support header, then only the standard library: no Eigen.
    CHECK(contains(header, "#include <billiards/kernel_support.hpp>\n\n#include <limits>\n"));
    CHECK_FALSE(contains(header, "#include <Eigen"));
    // The helpers are printed once, in the support header, which includes only the standard library.
    CHECK_FALSE(contains(header, "/// |x|,"));
    const std::string support = kernel_support_header();
    CHECK(contains(support, "/// |x|,"));
    CHECK(contains(support, "namespace billiards::kernels {"));
    CHECK(std::count(support.begin(), support.end(), '#') > 0);
    for (std::size_t at = support.find("#include "); at != std::string::npos; at = support.find("#include ", at + 1))
      CHECK(support.compare(at, 10, "#include <") == 0);
    CHECK_FALSE(contains(support, "#include <billiards"));
  }
}

TEST_CASE("A fast path's predicate compares bits where its conditions are one interval",
          "[derive][emitter]") {
  const GiNaC::symbol m1("m1"), m2("m2"), v1n("v1n"), v2n("v2n"), s("relative_normal_speed");
  const Kernel plain{.name = "plain_kernel",
                     .brief = "The plain form.",
                     .parameters = {m1, m2, v1n, v2n},
                     .steps = {{s, v2n - v1n}},
                     .outputs = {s, -s}};
  Kernel full = plain;
  full.name = "full_kernel";
  full.brief = "The full form.";
  full.fast_path = FastPath{.predicate = "in_range",
                            .brief = "True in the range.",
                            .conditions = {plain_mass_low() <= m1, m1 <= plain_mass_high(),
                                           plain_mass_low() <= m2, m2 <= plain_mass_high()},
                            .kernel = "plain_kernel"};
  const auto header = [&] {
    Derivation derivation;
    derivation.kernels = {plain, full};
    return kernels_header(derivation, "{}");
  };
  SECTION("both masses in [low, high]: bits on the host, the comparisons on the device") {
    const std::string text = header();
    CHECK(contains(kernel_support_header(), "#include <bit>\n"));
    CHECK(contains(kernel_support_header(), "constexpr auto bits_above(Scalar x, Scalar low) noexcept {"));
    CHECK(contains(text,
                   "BILLIARDS_HOST_DEVICE constexpr bool in_range(Scalar m1, Scalar m2) noexcept {\n"
                   "#if !defined(__CUDA_ARCH__)\n"
                   "  if constexpr (orders_as_bits<Scalar>()) {\n"
                   "    const Scalar low = plain_mass_low<Scalar>();\n"
                   "    return larger(bits_above(m1, low), bits_above(m2, low)) <= "
                   "bits_above(plain_mass_high<Scalar>(), low);\n"
                   "  }\n"
                   "#endif\n"
                   "  return plain_mass_low<Scalar>() <= m1 && m1 <= plain_mass_high<Scalar>() &&\n"));
  }
  SECTION("the kernel: the test and the fast kernel, then full_<name>, which holds every step") {
    const std::string text = header();
    // (The signatures are wrapped at the column limit.)
    CHECK(contains(text, "NormalVelocityChange<Scalar> full_kernel(Scalar m1, Scalar m2, Scalar v1n,\n"));
    CHECK(contains(text,
                   "Scalar v2n) noexcept {\n"
                   "  if (in_range(m1, m2)) return plain_kernel(m1, m2, v1n, v2n);\n"
                   "  return full_full_kernel(m1, m2, v1n, v2n);\n"
                   "}\n"));
    CHECK(contains(text, "NormalVelocityChange<Scalar> full_full_kernel(Scalar m1, Scalar m2,\n"));
    CHECK(contains(text,
                   "Scalar v2n) noexcept {\n"
                   "  const Scalar relative_normal_speed = v2n - v1n;\n"
                   "  return {relative_normal_speed, -relative_normal_speed};\n"
                   "}\n"));
    // Printed before the kernel that calls it, and documented as the full form.
    CHECK(text.find("full_full_kernel(Scalar m1") < text.find("full_kernel(Scalar m1"));
    CHECK(contains(text,
                   "/// The full form of full_kernel, right for every valid input: full_kernel takes "
                   "plain_kernel"));
    // The kernel without a fast path is printed whole, as before.
    CHECK_FALSE(contains(text, "full_plain_kernel"));
  }
  SECTION("anything else: the comparisons alone, and no bit helpers") {
    using Conditions = std::vector<ex>;
    const std::vector<std::pair<std::string, Conditions>> others = {
        {"an unbounded end (+∞ is no finite bound)",
         {plain_mass_low() <= m1, m1 <= infinity(), plain_mass_low() <= m2, m2 <= infinity()}},
        {"two intervals",
         {plain_mass_low() <= m1, m1 <= plain_mass_high(), smallest_normal() <= m2, m2 <= plain_mass_high()}},
        {"two upper ends",
         {smallest_normal() <= m1, m1 <= plain_mass_low(), smallest_normal() <= m2, m2 <= plain_mass_high()}},
        {"the ends the wrong way round",
         {plain_mass_high() <= m1, m1 <= plain_mass_low(), plain_mass_high() <= m2, m2 <= plain_mass_low()}},
        {"a strict comparison",
         {plain_mass_low() < m1, m1 <= plain_mass_high(), plain_mass_low() <= m2, m2 <= plain_mass_high()}},
        {"no lower end",
         {m1 <= plain_mass_high(), m1 <= plain_mass_high(), m2 <= plain_mass_high(),
          m2 <= plain_mass_high()}},
        {"a bound missing", {plain_mass_low() <= m1, m1 <= plain_mass_high(), plain_mass_low() <= m2}},
        {"a bound twice",
         {plain_mass_low() <= m1, plain_mass_low() <= m1, plain_mass_low() <= m2, m2 <= plain_mass_high()}}};
    for (const auto& [what, conditions] : others) {
      INFO(what);
      full.fast_path->conditions = conditions;
      const std::string text = header();
      CHECK(contains(text, "BILLIARDS_HOST_DEVICE constexpr bool in_range("));
      CHECK_FALSE(contains(text, "bits_above"));
    }
  }
}

TEST_CASE("The reference kernels header", "[derive][emitter]") {
  const Derivation derivation = parkin2023::derive();
  REQUIRE(derivation.reference_kernels.size() == 1);
  const std::string header = reference_kernels_header(derivation, "{}");
  CHECK(contains(header, "do not edit"));
  CHECK(contains(header, "for the benchmark only"));
  CHECK(contains(header, "#include <billiards/kernels.hpp>\n"));
  CHECK(contains(header, "namespace billiards::reference_kernels {"));
  // The raw derivation: the quadratic formula's square root, its sign chosen by (v2 − v1)·n.
  CHECK(contains(header, "raw_normal_velocity_change("));
  CHECK(contains(header, "std::sqrt(discriminant)"));
  CHECK(contains(header, "if (v2n - v1n < Scalar(0))"));
  // Not constexpr: it takes a square root.
  CHECK_FALSE(contains(header, "constexpr NormalVelocityChange"));
  // None of the runtime's kernels are repeated in it.
  CHECK_FALSE(contains(header, "elastic_normal_velocity_change("));
}

TEST_CASE("The fingerprint covers the emitted text and the audit", "[derive][emitter]") {
  const Derivation derivation = parkin2023::derive();
  const auto fingerprint_line = [](const std::string& header) {
    const auto at = header.find("// Fingerprint: ");
    return header.substr(at, header.find('\n', at) - at);
  };
  const std::string header = kernels_header(derivation, "audit");
  SECTION("a different audit gives a different fingerprint") {
    CHECK(fingerprint_line(header) != fingerprint_line(kernels_header(derivation, "audiT")));
  }
  SECTION("a different kernel with the same audit gives a different fingerprint") {
    Derivation changed = derivation;
    changed.kernels.back().outputs.front() = -changed.kernels.back().outputs.front();
    CHECK(fingerprint_line(header) != fingerprint_line(kernels_header(changed, "audit")));
  }
  SECTION("the same inputs give the same bytes") { CHECK(header == kernels_header(derivation, "audit")); }
}

TEST_CASE("Fingerprints", "[derive][emitter]") {
  CHECK(fingerprint("") == "fnv1a64:cbf29ce484222325");   // the FNV-1a 64-bit offset basis
  CHECK(fingerprint("a") == "fnv1a64:af63dc4c8601ec8c");  // published FNV-1a test vector
  CHECK(fingerprint("audit") != fingerprint("audiT"));
}
