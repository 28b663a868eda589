// The checked API: every argument out of its domain is rejected with its name, its value and what was
// expected; everything else gives exactly the unchecked result.
#include <billiards/checked.hpp>

#include <catch2/catch.hpp>

#include <limits>
#include <string>

namespace {

using Vector = Eigen::Vector3d;
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();

const Vector v1(1, 0, 0), v2(-1, 0.5, 0), n(1, 0, 0);

// Runs `call`, which must throw billiards::invalid_argument for `argument`; checks the message names
// the argument, shows `value` and says what was expected.
template <typename Call>
void rejects(Call call, const std::string& argument, const std::string& value) {
  try {
    call();
    FAIL("accepted; expected " << argument << " to be rejected");
  } catch (const billiards::invalid_argument& error) {
    CHECK(error.argument() == argument);
    CHECK(error.value().find(value) != std::string::npos);
    CHECK_FALSE(error.expected().empty());
    const std::string message = error.what();
    CHECK(message.find(argument + " is " + error.value()) != std::string::npos);
    CHECK(message.find("expected " + error.expected()) != std::string::npos);
  }
}

}  // namespace

TEST_CASE("checked::collide rejects what is out of its domain", "[runtime][checked]") {
  using billiards::checked::collide;
  SECTION("masses: positive, finite or +infinity, not both infinite") {
    rejects([] { (void)collide(-1.0, v1, 1.0, v2, n); }, "m1", "-1");
    rejects([] { (void)collide(0.0, v1, 1.0, v2, n); }, "m1", "0");
    rejects([] { (void)collide(1.0, v1, not_a_number, v2, n); }, "m2", "nan");
    rejects([] { (void)collide(1.0, v1, -infinity, v2, n); }, "m2", "-inf");
    rejects([] { (void)collide(infinity, v1, infinity, v2, n); }, "m2", "inf");
  }
  SECTION("velocities: finite and within the component limit") {
    rejects([] { (void)collide(1.0, Vector(not_a_number, 0, 0), 1.0, v2, n); }, "v1", "nan");
    rejects([] { (void)collide(1.0, v1, 1.0, Vector(0, infinity, 0), n); }, "v2", "inf");
    const double too_big = 2 * billiards::component_limit<double>();
    rejects([&] { (void)collide(1.0, v1, 1.0, Vector(0, 0, too_big), n); }, "v2", "(0, 0, ");
  }
  SECTION("the normal: finite, non-zero, of unit length") {
    rejects([] { (void)collide(1.0, v1, 1.0, v2, Vector(0, 0, 0)); }, "n", "(0, 0, 0)");
    rejects([] { (void)collide(1.0, v1, 1.0, v2, Vector(2, 0, 0)); }, "n", "(2, 0, 0)");
    rejects([] { (void)collide(1.0, v1, 1.0, v2, Vector(not_a_number, 0, 0)); }, "n", "nan");
    rejects([] { (void)collide(1.0, v1, 1.0, v2, Vector(1 + 1e-9, 0, 0)); }, "n", "(1.0000000");
  }
  SECTION("restitution: in [0, 1]") {
    rejects([] { (void)collide(1.0, v1, 1.0, v2, n, -0.25); }, "restitution", "-0.25");
    rejects([] { (void)collide(1.0, v1, 1.0, v2, n, 1.5); }, "restitution", "1.5");
    rejects([] { (void)collide(1.0, v1, 1.0, v2, n, not_a_number); }, "restitution", "nan");
  }
  SECTION("the exception is a std::invalid_argument") {
    CHECK_THROWS_AS((void)collide(-1.0, v1, 1.0, v2, n), std::invalid_argument);
  }
}

TEST_CASE("checked calls accept their domain and return the unchecked result", "[runtime][checked]") {
  SECTION("collide, elastic and with restitution") {
    const auto checked = billiards::checked::collide(2.0, v1, 3.0, v2, n);
    const auto unchecked = billiards::collide(2.0, v1, 3.0, v2, n);
    CHECK(checked.first == unchecked.first);
    CHECK(checked.second == unchecked.second);
    const auto checked_e = billiards::checked::collide(2.0, v1, 3.0, v2, n, 0.5);
    CHECK(checked_e.first == billiards::collide(2.0, v1, 3.0, v2, n, 0.5).first);
  }
  SECTION("an immovable body, a unit normal normalised in float, subnormal masses") {
    const auto wall = billiards::checked::collide(1.0, v1, infinity, Vector::Zero().eval(), n);
    CHECK(wall.first == billiards::reflect(v1, n));
    const Eigen::Vector3f n_float = Eigen::Vector3f(1, 2, 3).normalized();
    const auto in_float =
        billiards::checked::collide(1.0f, Eigen::Vector3f(1, 0, 0), 1.0f, Eigen::Vector3f(0, 1, 0), n_float);
    CHECK(in_float.first.allFinite());
    const double tiny = std::numeric_limits<double>::denorm_min();
    CHECK(billiards::checked::collide(tiny, v1, 1e308, v2, n).first.allFinite());
  }
  SECTION("collide_along_direction and collide_if_approaching") {
    const Vector d(3, 0, 0);
    CHECK(billiards::checked::collide_along_direction(2.0, v1, 3.0, v2, d).first ==
          billiards::collide_along_direction(2.0, v1, 3.0, v2, d).first);
    rejects([] { (void)billiards::checked::collide_along_direction(1.0, v1, 1.0, v2, Vector(0, 0, 0)); }, "d",
            "(0, 0, 0)");
    const Vector p1(0, 0, 0), p2(1, 0, 0);
    CHECK(billiards::checked::collide_if_approaching(2.0, p1, v1, 3.0, p2, v2).second ==
          billiards::collide_if_approaching(2.0, p1, v1, 3.0, p2, v2).second);
    rejects([&] { (void)billiards::checked::collide_if_approaching(1.0, p1, v1, 1.0, p1, v2); }, "p2",
            "(0, 0, 0)");
    rejects(
        [&] {
          (void)billiards::checked::collide_if_approaching(1.0, Vector(not_a_number, 0, 0), v1, 1.0, p2, v2);
        },
        "p1", "nan");
  }
  SECTION("reflect") {
    CHECK(billiards::checked::reflect(v2, n) == billiards::reflect(v2, n));
    rejects([] { (void)billiards::checked::reflect(v2, Vector(0, 0, 0.5)); }, "n", "(0, 0, 0.5)");
  }
  SECTION("at the component limit the result is finite") {
    const double limit = billiards::component_limit<double>();
    const Vector fast(limit, -limit, limit), other(-limit, limit, -limit);
    const Vector diagonal = Vector(1, 1, 1).normalized();
    const auto result = billiards::checked::collide(1e-300, fast, 1e300, other, diagonal, 1.0);
    CHECK(result.first.allFinite());
    CHECK(result.second.allFinite());
  }
}

TEST_CASE("checked::time_of_impact", "[runtime][checked][time_of_impact]") {
  const Vector origin = Vector::Zero(), p2(10, 0, 0), approaching(-3, 0, 0);
  SECTION("accepted: exactly the unchecked result, +infinity included") {
    CHECK(billiards::checked::time_of_impact(origin, v1, p2, approaching, 2.0) ==
          billiards::time_of_impact(origin, v1, p2, approaching, 2.0));
    CHECK(billiards::checked::time_of_impact(origin, v1, p2, approaching, 2.0) == 2.0);
    CHECK(billiards::checked::time_of_impact(origin, origin, p2, Vector(1, 0, 0), 2.0) == infinity);
  }
  SECTION("the contact distance: positive and finite") {
    rejects([&] { (void)billiards::checked::time_of_impact(origin, v1, p2, approaching, -1.0); },
            "contact_distance", "-1");
    rejects([&] { (void)billiards::checked::time_of_impact(origin, v1, p2, approaching, 0.0); },
            "contact_distance", "0");
    rejects([&] { (void)billiards::checked::time_of_impact(origin, v1, p2, approaching, not_a_number); },
            "contact_distance", "nan");
  }
  SECTION("a contact distance too small beside the distance to decide a hit is rejected, not missed") {
    const double limit = billiards::relative_contact_distance_limit<double>();
    CHECK(limit == Approx(6.0e-154).epsilon(0.01));
    rejects([&] { (void)billiards::checked::time_of_impact(origin, origin, p2, approaching, 1e-160); },
            "contact_distance", "e-16");
    // Just above it: a head-on hit, at (10 − r)/3.
    CHECK(billiards::checked::time_of_impact(origin, origin, p2, approaching, 1e-152) == Approx(10.0 / 3));
    // Extreme scales: a crawl at 1e-161 over a gap, overlapping specks of radius 2e-170.
    CHECK(billiards::checked::time_of_impact(origin, origin, Vector(1.4, 0, 0), Vector(-1e-161, 0, 0),
                                             0.057) == Approx((1.4 - 0.057) / 1e-161));
    CHECK(billiards::checked::time_of_impact(origin, Vector(1, 0, 0), Vector(2e-170, 0, 0), origin, 4e-170) ==
          0);
  }
  SECTION("the limit holds where |p2 − p1|² underflows (float: the fuzz harness's case)") {
    // |p2 − p1| = 2.6e-23: its square underflows in float, and a plain norm read it as 0.
    using Vector2f = Eigen::Vector2f;
    const Vector2f a(0.0f, 2.6469779601696886e-23f), b(-0.0f, -0.0f);
    const Vector2f va(-0.0f, -1.5839090484674637e-30f), vb(0.0f, 3.7252902984619141e-09f);
    rejects([&] { (void)billiards::checked::time_of_impact(a, va, b, vb, 1.4012984643248171e-45f); },
            "contact_distance", "1.4");
    // Above the limit (4.3e-19 · 2.6e-23 = 1.1e-41) the head-on hit is found, at (|p| − r)/|w|.
    const float r = 1e-40f;
    CHECK(billiards::checked::time_of_impact(a, va, b, vb, r) ==
          Approx((2.6469779601696886e-23 - 1e-40) / (3.7252902984619141e-09 + 1.5839090484674637e-30)));
  }
  SECTION("positions and velocities: finite and within the component limit") {
    rejects(
        [&] { (void)billiards::checked::time_of_impact(Vector(infinity, 0, 0), v1, p2, approaching, 2.0); },
        "p1", "inf");
    rejects(
        [&] { (void)billiards::checked::time_of_impact(origin, v1, p2, Vector(0, not_a_number, 0), 2.0); },
        "v2", "nan");
  }
  SECTION("distances and speeds whose product would overflow the kernel's squares") {
    const double limit = billiards::component_limit<double>();
    rejects(
        [&] {
          (void)billiards::checked::time_of_impact(origin, origin, Vector(limit, 0, 0), Vector(-limit, 0, 0),
                                                   1.0);
        },
        "v2 − v1", "(");
    // Just inside: large but representable, and never NaN.
    const double t =
        billiards::checked::time_of_impact(origin, origin, Vector(1e70, 0, 0), Vector(-1e70, 0, 0), 1.0);
    CHECK(t == Approx(1.0));
  }
}
