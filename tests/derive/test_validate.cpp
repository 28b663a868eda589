// The kernel validation on small kernels: each rule proven able to fail, and to pass.
#include "core/claim.hpp"
#include "core/named_constants.hpp"
#include "core/powers_of_two.hpp"
#include "emit/validate.hpp"

#include <catch2/catch.hpp>

using namespace billiards::derive;
using GiNaC::ex;
using GiNaC::lst;

namespace {

const GiNaC::possymbol a("a"), b("b");
const GiNaC::realsymbol x("x");

Claim verified(const std::string& id, const ex& derived, std::vector<Case> cases = {}) {
  Claim claim;
  claim.id = id;
  claim.comparison = Comparison::identity;
  claim.paper_expression = derived;
  claim.derived_expression = derived;
  claim.cases = std::move(cases);
  check(claim);
  REQUIRE(claim.verdict == Verdict::verified);
  return claim;
}

// A kernel computing a/(a + b) · x, with a guarded step.
Kernel share_kernel() {
  const GiNaC::symbol total("total"), share("share");
  Kernel kernel;
  kernel.name = "share";
  kernel.parameters = {a, b, x};
  kernel.steps = {{total, a + b}, {share, a / total}};
  kernel.outputs = {share * x};
  kernel.equals = "test.share";
  return kernel;
}

bool mentions(const std::vector<KernelProblem>& problems, const std::string& text) {
  for (const KernelProblem& problem : problems) {
    if ((problem.kernel + " " + problem.claim + " " + problem.reason).find(text) != std::string::npos)
      return true;
  }
  return false;
}

}  // namespace

TEST_CASE("A kernel is validated against the claims", "[derive][validate]") {
  std::vector<Claim> claims = {verified("test.share", a * x / (a + b))};
  Kernel kernel = share_kernel();

  SECTION("outputs equal to the claim's derived expression: proven") {
    CHECK(validate_kernel(kernel, claims).empty());
  }
  SECTION("an output that differs is named with the claim and the residual") {
    kernel.outputs = {-kernel.outputs[0]};
    const auto problems = validate_kernel(kernel, claims);
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].kernel == "share");
    CHECK(problems[0].claim == "test.share");
  }
  SECTION("a symbol that is no parameter, earlier step or named constant") {
    kernel.steps[1].expression = a / GiNaC::symbol("later");
    CHECK(mentions(validate_kernel(kernel, claims), "reads later"));
  }
  SECTION("a claim that is missing or not verified") {
    kernel.claims = {"test.missing"};
    CHECK(mentions(validate_kernel(kernel, claims), "does not record"));
    Claim failed = verified("test.failed", 0);
    failed.verdict = Verdict::failed;
    claims.push_back(failed);
    kernel.claims = {"test.failed"};
    CHECK(mentions(validate_kernel(kernel, claims), "failed, not verified"));
  }
  SECTION("a same-value guard: its alternative must keep the outputs equal") {
    claims.push_back(verified("test.other_form", 0));
    const GiNaC::symbol share = kernel.steps[1].name;
    kernel.steps[1].guards = {
        {share < smallest_normal(), 1 - b / (a + b), Guard::Kind::same_value, "test.other_form"}};
    CHECK(validate_kernel(kernel, claims).empty());
    kernel.steps[1].guards[0].alternative = 1 - a / (a + b);
    CHECK(mentions(validate_kernel(kernel, claims), "under its guard"));
  }
  SECTION("a piecewise guard must be a case its claim states") {
    claims.push_back(verified("test.no_share", 0, {{lst{x < 0}, 0}}));
    const GiNaC::symbol share = kernel.steps[1].name;
    kernel.steps[1].guards = {{x < 0, 0, Guard::Kind::piecewise, "test.no_share"}};
    CHECK(validate_kernel(kernel, claims).empty());
    kernel.steps[1].guards[0].condition = x <= 0;
    CHECK(mentions(validate_kernel(kernel, claims), "no case the claim states"));
    kernel.steps[1].guards[0].condition = 0 > x;  // the same condition, mirrored
    CHECK(validate_kernel(kernel, claims).empty());
    kernel.steps[1].guards[0].alternative = 1;
    CHECK(mentions(validate_kernel(kernel, claims), "no case the claim states"));
  }
  SECTION("an unreachable guard must read x < 0 for the x a sign claim shows to be ≥ 0") {
    Claim sign;
    sign.id = "test.sign";
    sign.comparison = Comparison::nonnegative;
    sign.paper_expression = 0;
    sign.derived_expression = a + b;
    check(sign);
    REQUIRE(sign.verdict == Verdict::verified);
    claims.push_back(sign);
    const GiNaC::symbol total = kernel.steps[0].name;
    kernel.steps[0].guards = {{total < 0, 1, Guard::Kind::unreachable, "test.sign"}};
    CHECK(validate_kernel(kernel, claims).empty());
    kernel.steps[0].guards[0].condition = total - 1 < 0;
    CHECK(mentions(validate_kernel(kernel, claims), "x < 0"));
  }
  SECTION("an overridden guard must change no output: a piecewise guard of its condition hides it") {
    // share · x, where x < 0 gives 0: the factor x is clamped to 0 there first (overridden).
    claims.push_back(verified("test.no_share", 0, {{lst{x < 0}, 0}}));
    const GiNaC::symbol clamped("clamped"), product("product");
    const GiNaC::symbol share = kernel.steps[1].name;
    kernel.steps.push_back({clamped, x, {{x < 0, 0, Guard::Kind::overridden, "test.no_share"}}});
    kernel.steps.push_back({product, share * clamped, {{x < 0, 0, Guard::Kind::piecewise, "test.no_share"}}});
    kernel.outputs = {product};
    CHECK(validate_kernel(kernel, claims).empty());
    SECTION("no piecewise guard of the same condition") {
      kernel.steps[3].guards[0].condition = x <= 0;
      CHECK(mentions(validate_kernel(kernel, claims), "overridden by no piecewise guard"));
    }
    SECTION("the piecewise guard's value reads the clamped step") {
      kernel.steps[3].guards[0].alternative = share * clamped;
      CHECK(mentions(validate_kernel(kernel, claims), "changes an output"));
    }
    SECTION("an output beside the overridden one reads the clamped step") {
      kernel.outputs.push_back(clamped);
      CHECK(mentions(validate_kernel(kernel, claims), "changes an output"));
    }
  }
  SECTION("the kernel's parameters in the claim's terms") {
    const GiNaC::realsymbol y("y");
    claims = {verified("test.share", a * (y + 1) / (a + b))};
    kernel.in_claim_terms = {{x, y + 1}};
    CHECK(validate_kernel(kernel, claims).empty());
  }
}

TEST_CASE("A kernel scaled by powers of two is proven for any exponent", "[derive][validate]") {
  // a/(b x) on the significands of a, b and x, scaled back by 2^(ka − kb − kx) (scaled_monomial).
  const std::vector<Claim> claims = {verified("test.quotient", a / (b * x))};
  const ScaledMonomial scaled = scaled_monomial("quotient", a / (b * x), {a, b, x});
  Kernel kernel;
  kernel.name = "quotient";
  kernel.parameters = {a, b, x};
  kernel.steps = scaled.steps;
  kernel.outputs = {scaled.value};
  kernel.equals = "test.quotient";
  REQUIRE(kernel.steps.size() == 8);
  CHECK(kernel.steps[0].name.get_name() == "a_exponent");
  CHECK(kernel.steps[1].name.get_name() == "scaled_a");
  CHECK(kernel.steps[6].name.get_name() == "scaled_quotient");
  CHECK(kernel.steps[7].name.get_name() == "quotient_exponent");

  SECTION("the scaled form equals the claim") { CHECK(validate_kernel(kernel, claims).empty()); }
  SECTION("an exponent with the wrong sign is caught") {
    const ex ka = kernel.steps[0].name, kb = kernel.steps[2].name, kx = kernel.steps[4].name;
    kernel.outputs = {times_power_of_two(kernel.steps[6].name, ka + kb - kx)};
    CHECK(mentions(validate_kernel(kernel, claims), "differ"));
  }
  SECTION("a significand not scaled back is caught") {
    kernel.outputs = {kernel.steps[6].name};
    CHECK(mentions(validate_kernel(kernel, claims), "differ"));
  }
  SECTION("a significand that is not its number over 2^exponent is caught") {
    kernel.steps[3].expression = b;
    CHECK(mentions(validate_kernel(kernel, claims), "differ"));
  }
  SECTION("only a monomial of integer degrees can be scaled") {
    CHECK_THROWS_WITH(scaled_monomial("sum", a + b, {a, b}),
                      Catch::Contains("not a monomial of integer degree in a"));
    CHECK_THROWS_WITH(scaled_monomial("root", GiNaC::sqrt(a), {a}), Catch::Contains("integer degree in a"));
    CHECK_THROWS_WITH(scaled_monomial("power", GiNaC::pow(3, a), {a}),
                      Catch::Contains("integer degree in a"));
  }
}

TEST_CASE("binary_exponent is exact on rationals and held on symbols", "[derive][validate]") {
  CHECK(binary_exponent(GiNaC::numeric(1)) == 0);
  CHECK(binary_exponent(GiNaC::numeric(3, 2)) == 0);
  CHECK(binary_exponent(GiNaC::numeric(2)) == 1);
  CHECK(binary_exponent(GiNaC::numeric(-7)) == 2);
  CHECK(binary_exponent(GiNaC::numeric(1, 3)) == -2);
  CHECK(binary_exponent(GiNaC::numeric(1, 4)) == -2);
  CHECK(binary_exponent(GiNaC::numeric(0)) == 0);
  CHECK(binary_exponent(GiNaC::numeric(1).div(GiNaC::numeric(2).power(1074))) == -1074);
  CHECK(!GiNaC::is_a<GiNaC::numeric>(binary_exponent(a)));
  // The exact logarithm: only for powers of two, of either sign of exponent.
  CHECK(exact_binary_logarithm(GiNaC::numeric(8)) == 3);
  CHECK(exact_binary_logarithm(GiNaC::numeric(1)) == 0);
  CHECK(exact_binary_logarithm(GiNaC::numeric(1, 16)) == -4);
  CHECK_FALSE(exact_binary_logarithm(GiNaC::numeric(6)));
  CHECK_FALSE(exact_binary_logarithm(GiNaC::numeric(3, 4)));
  CHECK_FALSE(exact_binary_logarithm(GiNaC::numeric(-2)));
  CHECK_FALSE(exact_binary_logarithm(GiNaC::numeric(0)));
  // 2^(k + 3) · 2^(−k) resolves to 8 for the same k, to no number for another.
  const ex k = binary_exponent(a), other = binary_exponent(b);
  CHECK(GiNaC::normal(resolve_powers_of_two(GiNaC::pow(2, k + 3) * GiNaC::pow(2, -k))) == 8);
  CHECK(!GiNaC::is_a<GiNaC::numeric>(
      GiNaC::normal(resolve_powers_of_two(GiNaC::pow(2, k + 3) * GiNaC::pow(2, -other)))));
}

TEST_CASE("The printed functions' names are distinct", "[derive][validate]") {
  const std::vector<Claim> claims = {verified("test.share", a * x / (a + b))};
  Kernel plain = share_kernel();
  plain.name = "plain_share";
  const std::vector<ex> range = {plain_mass_low() <= a, a <= plain_mass_high(), plain_mass_low() <= b,
                                 b <= plain_mass_high()};
  plain.domain = range;
  Kernel full = share_kernel();
  full.fast_path = FastPath{.predicate = "share_in_range",
                            .brief = "True in the range.",
                            .conditions = range,
                            .kernel = "plain_share",
                            .claim = "test.share"};
  REQUIRE(full_form_name(full) == "full_share");
  SECTION("a plain kernel and the kernel that takes it: proven") {
    CHECK(validate_kernels({plain, full}, claims).empty());
  }
  SECTION("a kernel named as another's full form, before it or after it") {
    Kernel clash = share_kernel();
    clash.name = "full_share";
    for (const std::vector<Kernel>& kernels :
         {std::vector<Kernel>{plain, full, clash}, std::vector<Kernel>{clash, plain, full}}) {
      const auto problems = validate_kernels(kernels, claims);
      CHECK(mentions(problems,
                     "full_share test.share has the name of the function that holds share's full form"));
      CHECK(mentions(problems, "share test.share would print its full form as full_share"));
    }
  }
  SECTION("two kernels of one name") {
    CHECK(mentions(validate_kernels({plain, full, plain}, claims),
                   "plain_share test.share has the name of a kernel printed before it"));
  }
}
