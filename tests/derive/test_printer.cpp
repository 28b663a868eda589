// The printer must give the same text for the same mathematics on every run.
#include "print/printer.hpp"

#include <catch2/catch.hpp>

using namespace billiards::derive;
using GiNaC::ex;

TEST_CASE("Canonical printing", "[derive][printer]") {
  const GiNaC::possymbol m1("m1", "m_1"), m2("m2", "m_2");
  const GiNaC::realsymbol a("a"), b("b");

  SECTION("(a − b)² and (b − a)² print alike") {
    CHECK(print(GiNaC::pow(a - b, 2), Notation::text) == print(GiNaC::pow(b - a, 2), Notation::text));
  }
  SECTION("a sum prints the same whatever order it was built in") {
    CHECK(print(m2 + m1 + a, Notation::text) == print(a + m1 + m2, Notation::text));
    CHECK(print(m1 * (m1 + m2), Notation::text) == print((m2 + m1) * m1, Notation::text));
  }
  SECTION("an odd power of a flipped sum carries the sign out") {
    CHECK(print(m1 * (b - a), Notation::text) == print(-m1 * (a - b), Notation::text));
  }
  SECTION("fractions and TeX names") {
    CHECK(print(2 * m2 / (m1 + m2), Notation::text) == "2*m2/(m1+m2)");
    CHECK(print(2 * m2 / (m1 + m2), Notation::latex) == "\\frac{2 m_2}{m_1 + m_2}");
    CHECK(print(GiNaC::numeric(1, 2) * m1 * a * a, Notation::latex) == "\\frac{a^{2} m_1}{2}");
  }
  SECTION("|b − a| and |a − b| print alike") {
    CHECK(print(GiNaC::abs(a - b), Notation::latex) == print(GiNaC::abs(b - a), Notation::latex));
  }
  SECTION("factored_form is the same for expanded and factored input") {
    const ex expanded = GiNaC::pow(m1, 2) * (a * a - 2 * a * b + b * b);
    const ex factored = GiNaC::pow(m1 * (b - a), 2);
    CHECK(print(factored_form(expanded), Notation::text) == print(factored_form(factored), Notation::text));
    CHECK(print(factored_form(expanded), Notation::text) == "(a-b)^2*m1^2");
  }
}
