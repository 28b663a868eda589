// The checker is one small function; these tests prove it can fail.
#include "core/algebra.hpp"
#include "core/claim.hpp"

#include <catch2/catch.hpp>

using namespace billiards::derive;
using GiNaC::ex;
using GiNaC::lst;

namespace {

const GiNaC::possymbol m1("m1"), m2("m2");
const GiNaC::realsymbol a("a"), b("b");

Claim identity_claim(const ex& paper, const ex& derived) {
  Claim claim;
  claim.id = "test.identity";
  claim.comparison = Comparison::identity;
  claim.paper_expression = paper;
  claim.derived_expression = derived;
  return claim;
}

}  // namespace

TEST_CASE("The checker verifies true identities and fails false ones", "[derive][checker]") {
  // The discriminant of the paper, D = m1²((v2 − v1)·n)², against its expansion.
  const ex expanded = GiNaC::pow(m1, 2) * (a * a + b * b - 2 * a * b);
  const ex factored = GiNaC::pow(m1, 2) * GiNaC::pow(b - a, 2);

  SECTION("an identity after normal() is verified with residual zero") {
    Claim claim = identity_claim(factored, expanded);
    check(claim);
    CHECK(claim.verdict == Verdict::verified);
    CHECK(claim.residual.is_zero());
  }
  SECTION("the discriminant with a sign flipped fails, with the residual shown") {
    Claim claim = identity_claim(factored, GiNaC::pow(m1, 2) * (a * a + b * b + 2 * a * b));
    check(claim);
    CHECK(claim.verdict == Verdict::failed);
    CHECK(GiNaC::normal(claim.residual - 4 * GiNaC::pow(m1, 2) * a * b).is_zero());
  }
  SECTION("lists are compared component by component; one wrong component fails") {
    Claim good = identity_claim(lst{a + b, a * b}, lst{b + a, b * a});
    check(good);
    CHECK(good.verdict == Verdict::verified);
    Claim bad = identity_claim(lst{a + b, a * b}, lst{b + a, a * a});
    check(bad);
    CHECK(bad.verdict == Verdict::failed);
  }
  SECTION("a list against a single expression, or lists of different length, fail") {
    Claim mixed = identity_claim(lst{a}, a);
    check(mixed);
    CHECK(mixed.verdict == Verdict::failed);
    Claim shorter = identity_claim(lst{a, b}, lst{a});
    check(shorter);
    CHECK(shorter.verdict == Verdict::failed);
  }
}

TEST_CASE("Constraints are imposed by substitution, not assumed", "[derive][checker]") {
  const Vec n = component_symbols("n", "n", "", 3);
  const ex unit = unit_normal_relation(n);

  SECTION("n·n − 1 is zero only with the constraint") {
    Claim with = identity_claim(1, dot(n, n));
    with.constraints = {{unit, "n·n = 1"}};
    check(with);
    CHECK(with.verdict == Verdict::verified);
    Claim without = identity_claim(1, dot(n, n));
    check(without);
    CHECK(without.verdict == Verdict::failed);
  }
  SECTION("higher powers of the last component are reduced too") {
    Claim claim = identity_claim(1, GiNaC::pow(dot(n, n), 3));
    claim.constraints = {{unit, "n·n = 1"}};
    check(claim);
    CHECK(claim.verdict == Verdict::verified);
  }
}

TEST_CASE("Sets, signs and assumptions", "[derive][checker]") {
  SECTION("the same elements in another order are the same set") {
    Claim claim = identity_claim(lst{a, b}, lst{b, a});
    claim.comparison = Comparison::same_set;
    check(claim);
    CHECK(claim.verdict == Verdict::verified);
  }
  SECTION("a different element is a different set") {
    Claim claim = identity_claim(lst{a, b}, lst{b, -a});
    claim.comparison = Comparison::same_set;
    check(claim);
    CHECK(claim.verdict == Verdict::failed);
  }
  SECTION("m1² times a square is nonnegative; a difference of squares is not shown to be") {
    Claim square = identity_claim(0, GiNaC::pow(m1, 2) * GiNaC::pow(a - b, 2));
    square.comparison = Comparison::nonnegative;
    check(square);
    CHECK(square.verdict == Verdict::verified);
    Claim difference = identity_claim(0, a * a - b * b);
    difference.comparison = Comparison::nonnegative;
    check(difference);
    CHECK(difference.verdict == Verdict::failed);
  }
  SECTION("a sign claim needs real symbols: z² ≥ 0 is false for a complex z") {
    const GiNaC::symbol z("z");  // complex, GiNaC's default
    Claim complex = identity_claim(0, GiNaC::pow(z, 2));
    complex.comparison = Comparison::nonnegative;
    check(complex);
    CHECK(complex.verdict == Verdict::failed);
    CHECK_THAT(complex.failure, Catch::Contains("real"));
    Claim real = identity_claim(0, GiNaC::pow(a, 2));
    real.comparison = Comparison::nonnegative;
    check(real);
    CHECK(real.verdict == Verdict::verified);
  }
  SECTION("a sign claim includes the paper side: what the paper prints must be the derived expression") {
    Claim same = identity_claim(GiNaC::pow(m1, 2) * GiNaC::pow(b - a, 2), GiNaC::pow(m1 * (a - b), 2));
    same.comparison = Comparison::nonnegative;
    check(same);
    CHECK(same.verdict == Verdict::verified);
    // Nonnegative, but not what the paper prints.
    Claim other = identity_claim(GiNaC::pow(m1, 2) * GiNaC::pow(b - a, 2), GiNaC::pow(m1 * (a + b), 2));
    other.comparison = Comparison::nonnegative;
    check(other);
    CHECK(other.verdict == Verdict::failed);
  }
  SECTION("an assumption is never verified") {
    Claim claim = identity_claim(a, a);
    claim.comparison = Comparison::assumption;
    check(claim);
    CHECK(claim.verdict == Verdict::assumption);
  }
}

TEST_CASE("What the audit shows is what was compared", "[derive][checker]") {
  const GiNaC::realsymbol shorthand("S");
  Claim claim = identity_claim(a + b, b + a);
  SECTION("a display the checker proves equal to the compared expression is accepted") {
    claim.paper_display = shorthand;
    claim.display_definitions = {{shorthand, a + b}};
    check(claim);
    CHECK(claim.verdict == Verdict::verified);
  }
  SECTION("a display that is not what was compared fails the claim, though the comparison holds") {
    claim.paper_display = shorthand;
    claim.display_definitions = {{shorthand, a - b}};
    check(claim);
    CHECK(claim.verdict == Verdict::failed);
    CHECK_THAT(claim.failure, Catch::Contains("paper side shown"));
  }
  SECTION("a display with a symbol nothing defines fails") {
    claim.derived_display = shorthand;
    check(claim);
    CHECK(claim.verdict == Verdict::failed);
    CHECK_THAT(claim.failure, Catch::Contains("derived side shown"));
  }
  SECTION("a vector display is expanded into components") {
    const GiNaC::symbol v("v"), n("n");
    const Vec vc = component_symbols("v1", "v", "1", 2), nc = component_symbols("n", "n", "", 2);
    Claim vector = identity_claim(to_lst(add(vc, scale(2, nc))), to_lst(add(scale(2, nc), vc)));
    vector.paper_display = v + 2 * n;
    vector.display_components = {{{v, vc[0]}, {n, nc[0]}}, {{v, vc[1]}, {n, nc[1]}}};
    check(vector);
    CHECK(vector.verdict == Verdict::verified);
    vector.paper_display = v + 3 * n;
    check(vector);
    CHECK(vector.verdict == Verdict::failed);
  }
}

TEST_CASE("The checker never throws", "[derive][checker]") {
  const Vec n = component_symbols("n", "n", "", 3);
  SECTION("a comparison GiNaC cannot carry out is a failed claim with the reason") {
    // Reducing modulo n·n = 1 asks for the degree in n_z of an expression holding √(n_z): GiNaC throws
    // (mul::degree(): undefined degree), as it did for the slip B² + 4AC in the paper's derivation.
    Claim claim = identity_claim(0, GiNaC::sqrt(n[2]) * n[2] * n[2] + a);
    claim.constraints = {{unit_normal_relation(n), "n·n = 1"}};
    REQUIRE_NOTHROW(check(claim));
    CHECK(claim.verdict == Verdict::failed);
    CHECK_THAT(claim.failure, Catch::Contains("could not be carried out"));
  }
  SECTION("lists that cannot be compared fail too, without throwing") {
    Claim claim = identity_claim(lst{0}, lst{GiNaC::sqrt(n[2]) * n[2] * n[2]});
    claim.constraints = {{unit_normal_relation(n), "n·n = 1"}};
    REQUIRE_NOTHROW(check(claim));
    CHECK(claim.verdict == Verdict::failed);
  }
}

TEST_CASE("Square roots of perfect squares and absolute values", "[derive][algebra]") {
  const GiNaC::realsymbol s("s");
  SECTION("the square root of m1²(a − b)² is m1|a − b|") {
    const ex root = square_root_of_perfect_square(GiNaC::pow(m1, 2) * (a * a - 2 * a * b + b * b));
    CHECK(
        GiNaC::normal(GiNaC::pow(root, 2) - GiNaC::pow(m1, 2) * GiNaC::pow(GiNaC::abs(a - b), 2)).is_zero());
    CHECK((root.has(GiNaC::abs(a - b)) || root.has(GiNaC::abs(b - a))));
  }
  SECTION("a non-square keeps GiNaC's sqrt, so comparisons fail visibly") {
    const ex root = square_root_of_perfect_square(a * a + b * b);
    CHECK(root.is_equal(GiNaC::sqrt(a * a + b * b)));
  }
  SECTION("|−m1 s| resolves to m1 s for s ≥ 0 and −m1 s for s < 0") {
    const ex e = GiNaC::abs(-m1 * s);
    CHECK(resolve_absolute_values(e, s, +1).is_equal(m1 * s));
    CHECK(resolve_absolute_values(e, s, -1).is_equal(-m1 * s));
  }
  SECTION("an |…| not proportional to s is left alone") {
    const ex e = GiNaC::abs(s + a);
    CHECK(resolve_absolute_values(e, s, +1).is_equal(e));
  }
}
