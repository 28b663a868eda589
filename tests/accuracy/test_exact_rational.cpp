#include "exact.hpp"

#include <catch2/catch.hpp>

using billiards::accuracy::exact_rational;

TEST_CASE("Floating-point inputs become exact rationals", "[accuracy]") {
  SECTION("0.1 is 3602879701896397/2^55, a rational") {
    const GiNaC::numeric tenth = exact_rational(0.1);
    CHECK(tenth.is_rational());
    CHECK(tenth == GiNaC::numeric(3602879701896397LL) / GiNaC::numeric(2).power(55));
  }
  SECTION("GiNaC's own numeric(double) is not a rational: the trap this avoids") {
    CHECK_FALSE(GiNaC::numeric(0.1).is_rational());
  }
  SECTION("floats, negatives, subnormals and the largest finite round-trip exactly") {
    CHECK(exact_rational(0.1f) == GiNaC::numeric(13421773) / GiNaC::numeric(2).power(27));
    CHECK(exact_rational(-3.0) == -3);
    CHECK(exact_rational(std::numeric_limits<double>::denorm_min()) == GiNaC::numeric(2).power(-1074));
    CHECK(exact_rational(std::numeric_limits<float>::max()) ==
          (GiNaC::numeric(2).power(24) - 1) * GiNaC::numeric(2).power(104));
  }
  SECTION("infinities and NaN are refused") {
    CHECK_THROWS_AS(exact_rational(std::numeric_limits<double>::infinity()), std::invalid_argument);
    CHECK_THROWS_AS(exact_rational(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
  }
}
