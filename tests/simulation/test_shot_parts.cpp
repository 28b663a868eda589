// The shot engine's parts on their own — detection (shot/detection.hpp), evolution (shot/evolution.hpp),
// resolution (shot/resolution.hpp), checks (shot/checks.hpp) and history (shot/history.hpp) — each
// against answers worked by hand from the motion (uniform acceleration, the rolling condition, the
// conservation of momentum and energy), never captured from the code.
#include <billiards/simulation/shot.hpp>

#include <billiards/detail/exact_roots.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using namespace billiards::simulation;
using billiards::BallOnCloth;
using billiards::Motion;

namespace {

constexpr double R = 0.028575;
constexpr double never = std::numeric_limits<double>::infinity();  // no contact within the horizon

BallOnCloth<double> ball(Eigen::Vector3d velocity, Eigen::Vector3d spin,
                         Eigen::Vector3d position = {1, 0.5, R}) {
  return {position, velocity, spin, R};
}

}  // namespace

// contact_lower_bound, on which a shot queues a pair's contact before placing it, against the exact first
// root of the polynomial as given (Sturm's sequence in exact arithmetic, detail/exact_roots.hpp): never
// after it, nor after the time earliest_contact places (up to 16 units in the last place before it), and
// +∞ only where no root lies within the horizon. Families: a rack's gaps (10⁻¹⁵ to 10⁻² R) closing, balls
// anywhere on a table with any velocity and the cloth's accelerations, constant velocities (the
// polynomial is then its own quadratic bound, which only the bound's margin keeps from landing a unit
// above the root) and grazes at constant velocity (missing or touching by 10⁻¹⁶ to 10⁻⁸ of 2R, where
// the quadratic's discriminant is a difference of nearly equal terms).
TEST_CASE("Detection: a contact's lower bound never lies after its exact first root",
          "[simulation][shot][detection]") {
  std::mt19937_64 random(2026);
  std::uniform_real_distribution<double> unit(0, 1), angle(0, 2 * M_PI);
  const auto direction = [&] {
    const double a = angle(random);
    return Eigen::Vector2d(std::cos(a), std::sin(a));
  };
  for (const char* family : {"rack", "table", "constant velocity", "graze"}) {
    int bounded = 0, certified = 0, roots = 0, tight = 0;
    for (int k = 0; k < 3000; ++k) {
      shot::Path relative;
      const Eigen::Vector2d n = direction();
      if (std::string(family) == "rack") {
        const double gap = R * std::pow(10.0, -15 + 13 * unit(random));
        relative.position = (2 * R + gap) * n;
        relative.velocity = -(0.01 + 10 * unit(random)) * (n + 0.3 * (2 * unit(random) - 1) * direction());
        relative.acceleration = 5 * unit(random) * direction();
      } else if (std::string(family) == "graze") {
        // At constant velocity, passing at 2R (1 ± δ) from each other, δ from 10⁻¹⁶ to 10⁻⁸.
        const Eigen::Vector2d m(-n.y(), n.x());
        const double miss = (unit(random) < 0.5 ? -1 : 1) * std::pow(10.0, -16 + 8 * unit(random));
        relative.position = 2 * R * (1 + miss) * n + (0.01 + unit(random)) * m;
        relative.velocity = -(0.1 + 5 * unit(random)) * m;
      } else {
        relative.position = (2 * R + 2 * unit(random)) * n;
        relative.velocity = 6 * unit(random) * direction();
        if (std::string(family) == "table") relative.acceleration = 4 * unit(random) * direction();
      }
      const double horizon = std::pow(10.0, -3 + 4 * unit(random));
      const std::array<double, 5> p = shot::ball_contact_polynomial(relative, R);
      const double bound = shot::contact_lower_bound(p, horizon);
      const std::optional<double> exact = billiards::detail::exact::earliest_contact_after_zero(p, horizon);
      const std::optional<double> placed = billiards::earliest_contact(p, horizon);
      INFO(family << ": c = " << p[0] << ", " << p[1] << ", " << p[2] << ", " << p[3] << ", " << p[4]
                  << ", horizon " << horizon << ", bound " << bound);
      REQUIRE(bound >= 0);
      if (exact) ++roots;
      if (bound == never) {
        ++certified;
        REQUIRE_FALSE(exact);
        continue;
      }
      if (bound == 0) continue;
      ++bounded;
      if (exact) {
        REQUIRE(bound <= *exact);
        REQUIRE(placed);
        REQUIRE(bound <= *placed);
        if (bound >= 0.5 * *exact) ++tight;
      }
    }
    INFO(family << ": " << bounded << " bounded, " << certified << " certified apart, " << roots << " roots, "
                << tight << " bounds within half the root");
    // The bound is of use: most contacts get one near their time, most misses are told at once.
    CHECK(bounded + certified > 2700);
    CHECK(tight >= roots / 2);
    if (std::string(family) == "rack") CHECK(tight > 2000);
  }
}

// nose_line_bracket, on which a shot queues a cushion's contact before placing it, against the exact first
// root of the nose line's polynomial as given (Sturm's sequence in exact arithmetic): the root lies
// between its ends and nose_line_contact places it there; it is empty where no root lies before the
// horizon. Families: balls approaching the line from up to 2 m at up to 6 m/s with the cloth's
// accelerations either way; balls slowing to a stop within 10⁻¹⁶ to 10⁻⁶ (relative) of the line, where
// the closed form's root is off by up to the square root of the precision (a double root), far more than
// the bracket's width; balls approaching without an acceleration across the line (a polynomial of degree
// 1); and balls moving away. bracketed_nose_line_root, which places a bracketed root, gives what
// nose_line_contact gives on every one of them, bit for bit.
TEST_CASE("Detection: a cushion's bracket holds its exact first root", "[simulation][shot][detection]") {
  std::mt19937_64 random(2027);
  std::uniform_real_distribution<double> unit(0, 1);
  const CushionSegment cushion{{0, 0}, {2, 0}, {0, 1}};  // the nose along the x axis, the table above it
  for (const char* family : {"approach", "stopping at the line", "straight at the line", "moving away"}) {
    int bracketed = 0, roots = 0;
    for (int k = 0; k < 3000; ++k) {
      shot::Path path;
      const double gap = std::pow(10.0, -9 + 9.3 * unit(random));  // of the centre from R above the line
      path.position = {2 * unit(random), R + gap};
      if (std::string(family) == "stopping at the line") {
        // q = gap + v t + ½ a t² touching 0 at its vertex: a = v²/(2 gap), moved by 10^(−16…−6).
        const double v = 0.01 + 6 * unit(random), shift = std::pow(10.0, -16 + 10 * unit(random));
        path.velocity = {0.3 * (2 * unit(random) - 1), -v};
        path.acceleration = {0, v * v / (2 * gap) * (1 + (unit(random) < 0.5 ? -shift : shift))};
      } else {
        const double sign = std::string(family) == "moving away" ? 1 : -1;
        path.velocity = {2 * unit(random) - 1, sign * (0.01 + 6 * unit(random))};
        path.acceleration = {2 * unit(random) - 1, 4 * (2 * unit(random) - 1)};
        if (std::string(family) == "straight at the line") path.acceleration.y() = 0;
      }
      const double horizon = std::pow(10.0, -3 + 4 * unit(random));
      const std::array<double, 3> q = shot::nose_line_polynomial(path, cushion, R);
      const auto [low, high] = shot::nose_line_bracket(q, horizon);
      const std::optional<double> exact = billiards::detail::exact::earliest_contact_after_zero(q, horizon);
      INFO(family << ": q = " << q[0] << ", " << q[1] << ", " << q[2] << ", horizon " << horizon
                  << ", bracket " << low << ", " << high);
      if (exact) ++roots;
      const double contact = shot::nose_line_contact(path, cushion, R, horizon);
      REQUIRE(std::bit_cast<std::uint64_t>(shot::bracketed_nose_line_root(q, horizon)) ==
              std::bit_cast<std::uint64_t>(contact));
      if (low == 0 && high == 0) continue;
      ++bracketed;
      REQUIRE(exact);
      REQUIRE(0 < low);
      REQUIRE(low < *exact);
      REQUIRE(std::nextafter(*exact, never) < high);
      REQUIRE(high < horizon);
      REQUIRE(low < contact);
      REQUIRE(contact < high);
    }
    INFO(family << ": " << bracketed << " bracketed, " << roots << " roots");
    if (std::string(family) == "approach" || std::string(family) == "straight at the line")
      CHECK(bracketed > roots * 9 / 10);
    if (std::string(family) == "moving away") CHECK(bracketed == 0);
  }
}

// nose_side: where along the nose a centre lies, an end's margin left undecided.
TEST_CASE("Detection: the side of a cushion's nose a centre lies on", "[simulation][shot][detection]") {
  const CushionSegment cushion{{0, 0}, {2, 0}, {0, 1}};
  const shot::Path path{{-1, 0.5}, {1, 0}, {0, 0}};  // along the nose, 0.5 m in front of it
  CHECK(shot::nose_side(path, cushion, 0.5) == 2);   // x = −0.5: before the start
  CHECK(shot::nose_side(path, cushion, 2) == 1);     // x = 1
  CHECK(shot::nose_side(path, cushion, 3.5) == 3);   // x = 2.5: past the end
  CHECK(shot::nose_side(path, cushion, 1) == 0);     // x = 0: at the start
  CHECK(shot::nose_side(path, cushion, 1 + 1e-10) == 0);
  CHECK(shot::nose_side(path, cushion, 1 + 1e-8) == 1);
  CHECK(shot::nose_side(path, cushion, 3 - 1e-10) == 0);  // x within 10⁻¹⁰ of the end
}

TEST_CASE("Detection: the next contact of a path, worked by hand", "[simulation][shot][detection]") {
  SECTION("two balls closing at 2 m/s from 1 m apart touch when their centres are 2R apart") {
    const shot::Path relative{{1, 0}, {-2, 0}, {0, 0}};
    CHECK(shot::ball_contact(relative, R, 10) == Approx((1 - 2 * R) / 2).epsilon(1e-14));
    CHECK(shot::ball_contact(relative, R, 0.4) == never);                 // beyond the horizon
    CHECK(shot::ball_contact({{1, 0}, {2, 0}, {0, 0}}, R, 10) == never);  // moving apart
  }
  SECTION("a ball slowing towards a cushion meets it where r − v t + ½ a t² = R") {
    const CushionSegment left{{0, 0}, {0, 1}, {1, 0}};  // the line x = 0, its normal into the table
    const shot::Path path{{1, 0.5}, {-2, 0}, {0.5, 0}};
    // 0.25 t² − 2 t + (1 − R) = 0, the earlier root.
    CHECK(shot::cushion_contact(path, left, R, 10) ==
          Approx((2 - std::sqrt(4 - (1 - R))) / 0.5).epsilon(1e-13));
    // The same motion beyond the segment's end (y = 5): the jaws, not the straight part, take the ball.
    CHECK(shot::cushion_contact({{1, 5}, {-2, 0}, {0.5, 0}}, left, R, 10) == never);
    // Too slow to get there: 1 − R at 2 m/s with a deceleration of 3 m/s² stops after 2/3 m.
    CHECK(shot::cushion_contact({{1, 0.5}, {-2, 0}, {3, 0}}, left, R, 10) == never);
  }
  SECTION("a centre enters a pocket's circle, and a ball meets a jaw, at the reach's distance") {
    const Pocket pocket{{0, 0}, 0.05};
    CHECK(shot::pocket_entry({{1, 0}, {-1, 0}, {0, 0}}, pocket, 10) == Approx(0.95).epsilon(1e-14));
    CHECK(shot::pocket_entry({{1, 0}, {1, 0}, {0, 0}}, pocket, 10) == never);
    const Jaw jaw{{0, 0}, 0.01};
    CHECK(shot::jaw_contact({{1, 0}, {-2, 0}, {0, 0}}, jaw, R, 10) ==
          Approx((1 - R - 0.01) / 2).epsilon(1e-14));
  }
  SECTION("a path's box holds its turning point and rules far bodies out") {
    // x(t) = t − t²/2 over [0, 2]: out to 0.5 at t = 1 and back to 0.
    const shot::Path path{{0, 0}, {1, 0}, {-1, 0}};
    const shot::Box box = shot::path_box(path, 2, true, R);
    CHECK(box.x_low <= 0);
    CHECK(box.x_high >= 0.5);
    CHECK(box.x_high - 0.5 <= 1e-6 * (0.5 + R) * 1.0000001);
    CHECK(box.y_low <= 0);
    CHECK(box.y_high >= 0);
    CHECK(box.near({0.55, 0}, 0.06));
    CHECK_FALSE(box.near({0.7, 0}, 0.06));
    const shot::Box near = shot::path_box({{0.5 + 1.9 * R, 0}, {0, 0}, {0, 0}}, 2, false, R);
    CHECK(box.widened(2 * R).overlaps(near));
    CHECK_FALSE(box.widened(2 * R).overlaps(shot::path_box({{0.6 + 2 * R + 0.01, 0}, {0, 0}, {0, 0}}, 2, false, R)));
    CHECK(box.widened(2 * R).overlaps(shot::path_box({{0.3, 1.9 * R}, {0, 0}, {0, 0}}, 2, false, R)));
    CHECK_FALSE(box.widened(2 * R).overlaps(shot::path_box({{0.3, -2.1 * R}, {0, 0}, {0, 0}}, 2, false, R)));
  }
  SECTION("bodies overlapping within the tolerance count as touching; deeper ones do not") {
    std::vector<double> p = {-0.5 * R * overlap_tolerance, 1, 1};
    shot::touching(p, 1, R);
    CHECK(p[0] == 0);
    p[0] = -2 * R * overlap_tolerance;
    shot::touching(p, 1, R);
    CHECK(p[0] == -2 * R * overlap_tolerance);
  }
  SECTION("a cushion's polynomial moving off stays apart only while it stays positive") {
    const std::array<double, 3> q = {1, -0.1, -0.01};  // 1 − 0.1 t − 0.01 t²: 0.89 at t = 1, < 0 at t = 10
    CHECK(shot::stays_apart(q, 1));
    CHECK_FALSE(shot::stays_apart(q, 10));
  }
}

TEST_CASE("Detection: the certificate of no contact holds only where the path keeps its distance",
          "[simulation][shot][detection]") {
  // Against the path's distance sampled densely in long double (and around the nearest sample refined by
  // ternary search): wherever the certificate says apart, the distance stays above D; a path that
  // passes within 1e-12 of D is always left to the polynomial; one far away is certified.
  std::mt19937_64 random(2026);
  std::uniform_real_distribution<double> unit(-1, 1);
  const double D = 0.05715;
  const auto nearest = [](const shot::Path& path, double horizon) {
    const auto distance = [&](long double t) {
      const long double x = path.position.x() + t * path.velocity.x() + 0.5L * t * t * path.acceleration.x();
      const long double y = path.position.y() + t * path.velocity.y() + 0.5L * t * t * path.acceleration.y();
      return std::sqrt(x * x + y * y);
    };
    const int samples = 4000;
    const long double step = horizon / static_cast<long double>(samples);
    int best = 0;
    for (int k = 1; k <= samples; ++k) {
      if (distance(k * step) < distance(best * step)) best = k;
    }
    long double low = std::max(0.0L, (best - 1) * step), high = std::min<long double>(horizon, (best + 1) * step);
    for (int k = 0; k < 200; ++k) {
      const long double a = low + (high - low) / 3, b = high - (high - low) / 3;
      if (distance(a) < distance(b))
        high = b;
      else
        low = a;
    }
    return std::min(distance(best * step), distance(0.5L * (low + high)));
  };
  int certified = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    shot::Path path{{0.3 * unit(random), 0.3 * unit(random)}, {2 * unit(random), 2 * unit(random)},
                    {2 * unit(random), 2 * unit(random)}};
    const double horizon = 0.4 * (1 + unit(random));
    if (!shot::certainly_apart(path, D, horizon)) continue;
    ++certified;
    INFO("trial " << trial);
    REQUIRE(nearest(path, horizon) > D);
  }
  CHECK(certified > 2000);
  // Grazes: the straight path passing at D (1 + 1e-12) and at D (1 − 1e-12), no acceleration.
  for (const double miss : {1e-12, -1e-12, 0.0}) {
    const shot::Path graze{{-1, D * (1 + miss)}, {1, 0}, {0, 0}};
    CHECK_FALSE(shot::certainly_apart(graze, D, 2.0));
  }
  CHECK(shot::certainly_apart(shot::Path{{-1, 3 * D}, {1, 0}, {0, 0}}, D, 2.0));
  // The drift of the acceleration counts: a path that clears by 2 D straight but curves into the point.
  CHECK_FALSE(shot::certainly_apart(shot::Path{{-1, 3 * D}, {1, 0}, {0, -6 * D}}, D, 2.0));
  CHECK_FALSE(shot::certainly_apart(shot::Path{{-1, 3 * D}, {1, 0}, {0, 0}}, D,
                                    std::numeric_limits<double>::max()));

  // Accelerations along the velocity (a rolling ball slowing, or one sped up), a sideways part of up to
  // 9e-4 of it, horizons up to past the stop and back: the same reference.
  int along = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Eigen::Vector2d v{2 * unit(random), 2 * unit(random)};
    const Eigen::Vector2d sideways{-v.y(), v.x()};
    const double k = (trial % 4 == 0 ? 1 : -1) * (0.05 + std::fabs(unit(random))) / v.norm();
    const Eigen::Vector2d a = k * v + 9e-4 * k * unit(random) * sideways;
    const shot::Path path{{0.3 * unit(random), 0.3 * unit(random)}, v, a};
    const double horizon = 1.5 * std::fabs(unit(random)) / std::fabs(k);
    if (!shot::certainly_apart(path, D, horizon)) continue;
    ++along;
    INFO("trial " << trial);
    REQUIRE(nearest(path, horizon) > D);
  }
  CHECK(along > 12000);
  // A rolling ball passing 2 D from the point over its whole roll (its path's drift from the straight
  // line over the horizon, ½ |a| horizon² = 1 m, would hide it): apart; 0.5 D from it: not.
  CHECK(shot::certainly_apart(shot::Path{{-1, 2 * D}, {1, 0}, {-0.5, 0}}, D, 2.0));
  CHECK_FALSE(shot::certainly_apart(shot::Path{{-1, 0.5 * D}, {1, 0}, {-0.5, 0}}, D, 2.0));
  // A sideways part of the acceleration (8e-4 of a radian) curves the path by 0.8 mm over the horizon:
  // a path that clears by 0.4 mm straight meets the point, one that clears by 1.2 mm does not.
  CHECK_FALSE(shot::certainly_apart(shot::Path{{-1, D + 4e-4}, {1, 0}, {-0.5, -4e-4}}, D, 2.0));
  CHECK(shot::certainly_apart(shot::Path{{-1, D + 1.2e-3}, {1, 0}, {-0.5, -4e-4}}, D, 2.0));
  // Rolling straight at the point: stopping 3 D short of it is apart for any horizon past the stop;
  // stopping on it is not (the path runs out to the stop, not only to where it is at the horizon).
  const double stop = 1 - 3 * D;
  CHECK(shot::certainly_apart(shot::Path{{-1, 0}, {1, 0}, {-1 / (2 * stop), 0}}, D, 10.0));
  CHECK_FALSE(shot::certainly_apart(shot::Path{{-1, 0}, {1, 0}, {-0.5, 0}}, D, 10.0));
}

TEST_CASE("Evolution: a ball's phase, its duration and acceleration, worked by hand",
          "[simulation][shot][evolution]") {
  const billiards::Cloth<double> cloth{0.2, 0.01, 0.0127, 9.81};
  SECTION("a ball struck without spin slides for 2|u|/(7 μs g), slowing at μs g, then rolls at 5/7 of v") {
    const BallOnCloth<double> s = ball({1, 0, 0}, {0, 0, 0});
    const shot::Phase p = shot::phase_of(s, cloth);
    CHECK(p.motion == Motion::sliding);
    CHECK(p.moving);
    CHECK(p.duration == Approx(2.0 / (7 * 0.2 * 9.81)).epsilon(1e-14));
    CHECK(p.acceleration.x() == Approx(-0.2 * 9.81).epsilon(1e-14));
    CHECK(p.acceleration.y() == 0);
    const auto [r, v] = shot::centre_and_velocity(s, p, 0.1);
    CHECK(r.x() == Approx(1 + 0.1 - 0.5 * 0.2 * 9.81 * 0.01).epsilon(1e-14));
    CHECK(v.x() == Approx(1 - 0.2 * 9.81 * 0.1).epsilon(1e-14));
    const BallOnCloth<double> end = shot::end_of_phase(s, p.motion, p.duration, cloth);
    CHECK(billiards::motion(end, cloth) == Motion::rolling);
    CHECK(end.velocity.x() == Approx(5.0 / 7).epsilon(1e-13));
    CHECK(shot::finish(s, Motion::sliding).velocity.x() == Approx(5.0 / 7).epsilon(1e-15));
  }
  SECTION("a rolling ball slows at μr g and stops after v/(μr g)") {
    const BallOnCloth<double> s = ball({0.5, 0, 0}, {0, 0.5 / R, 0});  // ω = ẑ × v / R: no slip
    const shot::Phase p = shot::phase_of(s, cloth);
    CHECK(p.motion == Motion::rolling);
    CHECK(p.duration == Approx(0.5 / (0.01 * 9.81)).epsilon(1e-13));
    CHECK(p.acceleration.x() == Approx(-0.01 * 9.81).epsilon(1e-14));
    const BallOnCloth<double> stopped = shot::finish(s, Motion::rolling);
    CHECK(stopped.velocity.isZero(0));
  }
  SECTION("a ball at rest has no end to its phase and does not move") {
    const shot::Phase p = shot::phase_of(ball({0, 0, 0}, {0, 0, 0}), cloth);
    CHECK(p.motion == Motion::stationary);
    CHECK_FALSE(p.moving);
    CHECK(std::isinf(p.duration));
    CHECK(p.acceleration.isZero(0));
  }
  SECTION("the kinetic energy of a solid sphere: ½ m v² + ⅕ m R² ω²") {
    CHECK(shot::kinetic_energy(ball({3, 4, 0}, {0, 0, 10}), 0.17) ==
          Approx(0.5 * 0.17 * 25 + 0.2 * 0.17 * R * R * 100).epsilon(1e-15));
  }
}

TEST_CASE("Resolution: the contact laws and the pressed contacts, worked by hand",
          "[simulation][shot][resolution]") {
  PoolPhysics physics;
  physics.radius = R;
  physics.ball_restitution = 1;
  physics.ball_friction = 0;
  SECTION("equal balls head on, elastic and frictionless, exchange their velocities") {
    const BallOnCloth<double> a = ball({1, 0, 0}, {0, 0, 0}, {1, 0.5, R});
    const BallOnCloth<double> b = ball({0, 0, 0}, {0, 0, 0}, {1 + 2 * R, 0.5, R});
    CHECK(shot::towards(a, b) == Eigen::Vector3d(1, 0, 0));
    const auto after = shot::ball_ball(a, b, shot::towards(a, b), physics);
    REQUIRE(after);
    CHECK(after->first.velocity.norm() <= 1e-15);
    CHECK(after->second.velocity.x() == Approx(1).epsilon(1e-15));
    // Moving apart: nothing changes.
    CHECK_FALSE(shot::ball_ball(ball({-1, 0, 0}, {0, 0, 0}, a.position), b, shot::towards(a, b), physics));
  }
  SECTION("a ball meets a cushion whose nose is at its centre's height: reflected, on the cloth") {
    PoolTable table = pool_table("9ft");
    table.nose_height = R;
    physics.cushion_restitution = 1;
    physics.cushion_friction = 0;
    const CushionSegment left{{0, 0}, {0, 1}, {1, 0}};
    CHECK(shot::towards(left) == Eigen::Vector3d(-1, 0, 0));
    BallOnCloth<double> a = ball({-1, 0.25, 0}, {0, 0, 0}, {R, 0.5, R});
    const auto after = shot::ball_cushion(a, shot::towards(left), table, physics);
    REQUIRE(after);
    shot::take(a, *after);
    CHECK(a.velocity.x() == Approx(1).epsilon(1e-15));
    CHECK(a.velocity.y() == Approx(0.25).epsilon(1e-15));
    CHECK(a.velocity.z() == 0);
    CHECK_FALSE(
        shot::ball_cushion(ball({1, 0, 0}, {0, 0, 0}, {R, 0.5, R}), shot::towards(left), table, physics));
    const Jaw jaw{{0, 0.5}, 0.01};
    CHECK((shot::towards(jaw, {0.1, 0.5, R}) - Eigen::Vector3d(-1, 0, 0)).norm() <= 1e-16);
  }
  SECTION("separation: the speed raised from the motion along the plane, then the spins, energy kept") {
    const shot::Separation s = shot::separation(0, 4e-6, 0, 1e-3);
    CHECK(s.normal == Approx(1e-3).epsilon(1e-15));
    CHECK(s.tangential_factor == Approx(std::sqrt(0.75)).epsilon(1e-15));
    CHECK(s.spin_factor == 1);
    // Not enough to pay for it: everything spent, the separation below the speed.
    const shot::Separation poor = shot::separation(0, 1e-7, 1e-7, 1e-3);
    CHECK(poor.normal == Approx(std::sqrt(2e-7)).epsilon(1e-14));
    CHECK(poor.tangential_factor == 0);
    CHECK(poor.spin_factor == 0);
  }
  SECTION("a pressed pair leaves at the pressing speed, momentum and energy kept") {
    const billiards::Cloth<double> cloth{0.2, 0.01, 0.0127, 9.81};
    const double m = 0.17;
    // a at rest; b touching it along +x, at rest but spinning so that its contact slips along +x: the
    // cloth pushes b back into a.
    BallOnCloth<double> a = ball({0, 0, 0}, {0, 0, 0}, {1, 0.5, R});
    BallOnCloth<double> b = ball({0, 0, 0}, {0, -0.01 / R, 0}, {1 + 2 * R, 0.5, R});
    REQUIRE(shot::acceleration(b, billiards::motion(b, cloth), cloth).x() < 0);
    const double before = shot::kinetic_energy(a, m) + shot::kinetic_energy(b, m);
    CHECK(shot::separate_pressed_pair(a, b, {1, 0, 0}, cloth, 1e-3));
    CHECK((b.velocity - a.velocity).x() == Approx(1e-3).epsilon(1e-14));
    CHECK((a.velocity + b.velocity).norm() <= 1e-18);
    CHECK(shot::kinetic_energy(a, m) + shot::kinetic_energy(b, m) == Approx(before).epsilon(1e-14));
    // Not pressed (nothing pushes them together): left alone.
    BallOnCloth<double> c = ball({0, 0, 0}, {0, 0, 0}, {1, 0.5, R});
    BallOnCloth<double> d = ball({0, 0, 0}, {0, 0, 0}, {1 + 2 * R, 0.5, R});
    CHECK_FALSE(shot::separate_pressed_pair(c, d, {1, 0, 0}, cloth, 1e-3));
    CHECK(d.velocity.isZero(0));
  }
  SECTION("a ball pressed into a cushion leaves it at the pressing speed, energy kept") {
    const billiards::Cloth<double> cloth{0.2, 0.01, 0.0127, 9.81};
    const double m = 0.17;
    // At the left cushion, spinning so that its contact slips along −x: the cloth pushes it into it.
    BallOnCloth<double> a = ball({0, 0.002, 0}, {0, -0.01 / R, 0}, {R, 0.5, R});
    REQUIRE(shot::acceleration(a, billiards::motion(a, cloth), cloth).x() < 0);
    const double before = shot::kinetic_energy(a, m);
    CHECK(shot::separate_pressed_ball(a, {-1, 0, 0}, cloth, 1e-3));
    CHECK(a.velocity.x() == Approx(1e-3).epsilon(1e-14));
    CHECK(shot::kinetic_energy(a, m) == Approx(before).epsilon(1e-14));
  }
}

TEST_CASE("Pressing: the pieces of sustained contact, worked by hand", "[simulation][shot][pressed]") {
  const PoolPhysics physics;
  const double mu_g = physics.cloth.sliding_friction * physics.cloth.gravity, mu_b = physics.ball_friction;
  // A with follow (u < 0: the cloth pushes it on), B sliding on (u > 0: held back), their contact points
  // slipping (σ > 0): N = μ_s g from −N + μ_s g = N − μ_s g, the pair coasting (v̇ = 0); R ω̇ = −(5/2)(f + μ_b N).
  {
    const auto piece = shot::pair_piece(0.5, {-1.0, 0.3}, 1.2, physics);
    REQUIRE(piece);
    CHECK(piece->force == Approx(mu_g));
    CHECK(piece->acceleration == Approx(0).margin(1e-12));
    CHECK(piece->spin_rate[0] == Approx(-2.5 * (mu_g + mu_b * mu_g)));
    CHECK(piece->spin_rate[1] == Approx(-2.5 * (-mu_g + mu_b * mu_g)));
    // B's slip 0.3 closes at u̇ = v̇ − R ω̇ = 2.5 (−μ_s g + μ_b μ_s g), A's −1 at 2.5 (μ_s g + μ_b μ_s g).
    const double b_end = 0.3 / (2.5 * mu_g * (1 - mu_b)), a_end = 1.0 / (2.5 * mu_g * (1 + mu_b));
    CHECK(piece->duration == Approx(std::min(a_end, b_end)));
    CHECK(piece->ending == (a_end < b_end ? shot::PressedEnd::first_slip : shot::PressedEnd::second_slip));
  }
  // A rolling behind B sliding on: f_A = (2N − 5T)/7 keeps A rolling, T = μ_b N; v̇_A = −N + f_A − the
  // rolling resistance's share (1 − |f_A|/(μ_s g)) μ_r g, v̇_B = N − μ_s g.
  {
    const auto piece = shot::pair_piece(0.5, {0.0, 0.3}, 0.8, physics);
    REQUIRE(piece);
    const double N = piece->force, f = (2 * N - 5 * mu_b * N) / 7;
    const double resistance = (1 - std::fabs(f) / mu_g) * physics.cloth.rolling_friction * physics.cloth.gravity;
    CHECK(piece->rolling[0]);
    CHECK_FALSE(piece->rolling[1]);
    CHECK(-N + f - resistance == Approx(N - mu_g));
    CHECK(piece->acceleration == Approx(N - mu_g));
  }
  // Both rolling at one speed: nothing presses them (N would be 0), so no piece.
  CHECK_FALSE(shot::pair_piece(0.5, {0.0, 0.0}, 1.0, physics));
  // A ball against the cushion: at rest, its spin running down at (5/2)(μ_s g + μ_c P).
  const auto [sine, cosine] = billiards::detail::nose_angle(0.03629, physics.radius);
  const auto cushion = shot::cushion_piece(2.0, sine, cosine, physics);
  REQUIRE(cushion);
  const double P = mu_g / (cosine + physics.cushion_friction * sine);
  CHECK(cushion->spin_rate == Approx(-2.5 * (mu_g + physics.cushion_friction * P)));
  CHECK(cushion->duration == Approx(2.0 / (2.5 * (mu_g + physics.cushion_friction * P))));
  CHECK_FALSE(shot::cushion_piece(-1.0, sine, cosine, physics));  // spin that pulls it away
}

TEST_CASE("Checks: bad physics and balls named, capture circles closing the mouths, invariants",
          "[simulation][shot][checks]") {
  const PoolTable table = pool_table("9ft");
  PoolPhysics physics;
  physics.cushion_restitution = 1.5;
  CHECK_THROWS_WITH(shot::validate(table, physics), Catch::Contains("physics.cushion_restitution"));
  std::vector<PoolBall> balls(2);
  balls[0].position = {1, 0.5, 0};
  balls[1].position = {1 + 0.01, 0.5, 0};
  CHECK_THROWS_WITH(shot::validate(balls, table, R), Catch::Contains("balls 0 and 1 overlap"));
  // Each widened circle reaches into both its jaws' reach (a centre R + ρ from each jaw's axis).
  const std::vector<Pocket> pockets = shot::capture_circles(table, R);
  for (const Pocket& pocket : pockets) {
    std::vector<double> gaps;
    for (const Jaw& jaw : table.jaws())
      gaps.push_back((jaw.centre - pocket.centre).norm() - (R + jaw.radius));
    std::sort(gaps.begin(), gaps.end());
    CHECK(pocket.radius > gaps[1]);
  }
  const std::vector<Eigen::Vector2d> centres = {{1, 0.5}, {1 + 1.5 * R, 0.5}};
  const auto broken =
      shot::broken_invariant(table, table.cushions(), table.jaws(), pockets, centres, {true, true}, R);
  REQUIRE(broken);
  CHECK(broken->first == 0);
  CHECK_THAT(broken->second, Catch::Contains("overlaps ball 1"));
  CHECK_FALSE(
      shot::broken_invariant(table, table.cushions(), table.jaws(), pockets, centres, {true, false}, R));
}

TEST_CASE("History: the balls at any time from their states at their events", "[simulation][shot][history]") {
  const billiards::Cloth<double> cloth{0.2, 0.01, 0.0127, 9.81};
  shot::History history;
  history.add(0, 0, ball({0.5, 0, 0}, {0, 0.5 / R, 0}), false);  // rolling from t = 0
  history.add(0, 2, ball({0, 0, 0}, {0, 0, 0}, {3, 0.5, R}), false);
  const std::vector<PoolBall> at_one = history.at(1, cloth);
  REQUIRE(at_one.size() == 1);
  // Rolling: x = 1 + 0.5 t − ½ μr g t².
  CHECK(at_one[0].position.x() == Approx(1 + 0.5 - 0.5 * 0.01 * 9.81).epsilon(1e-14));
  CHECK(history.at(2, cloth)[0].position.x() == 3);   // at a keyframe: its state
  CHECK(history.at(-1, cloth)[0].position.x() == 1);  // before the first: the first
}

TEST_CASE("History: each ball's keyframes apart from the others' added between them", "[simulation][shot][history]") {
  const billiards::Cloth<double> cloth{0.2, 0.01, 0.0127, 9.81};
  shot::History history;
  // Three balls at rest, each moved to a new place at its own events, their keyframes interleaved.
  for (std::size_t b = 0; b < 3; ++b) history.add(b, 0, ball({0, 0, 0}, {0, 0, 0}, {1.0 + b, 0.5, R}), false);
  history.add(1, 1, ball({0, 0, 0}, {0, 0, 0}, {2, 0.7, R}), false);
  history.add(0, 2, ball({0, 0, 0}, {0, 0, 0}, {1, 0.9, R}), false);
  history.add(1, 2, ball({0, 0, 0}, {0, 0, 0}, {2, 1.1, R}), true);
  history.add(1, 3, ball({0, 0, 0}, {0, 0, 0}, {2, 1.3, R}), true);
  const auto y = [&](double t) {
    std::vector<double> out;
    for (const PoolBall& b : history.at(t, cloth)) out.push_back(b.position.y());
    return out;
  };
  CHECK(y(-1) == std::vector<double>{0.5, 0.5, 0.5});
  CHECK(y(0.5) == std::vector<double>{0.5, 0.5, 0.5});
  CHECK(y(1) == std::vector<double>{0.5, 0.7, 0.5});
  CHECK(y(2) == std::vector<double>{0.9, 1.1, 0.5});  // at two keyframes' time: the states they hold
  CHECK(y(10) == std::vector<double>{0.9, 1.3, 0.5});
  CHECK(history.at(2.5, cloth)[1].pocketed);
  CHECK_FALSE(history.at(1.5, cloth)[1].pocketed);
  const std::vector<PoolBall> placed = history.first();
  REQUIRE(placed.size() == 3);
  for (std::size_t b = 0; b < 3; ++b) CHECK(placed[b].position.x() == 1.0 + b);
}
