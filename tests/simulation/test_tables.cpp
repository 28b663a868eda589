// The snooker and carom tables and the games' starting positions against their definitions worked by
// hand: the WPBSA's and the UMB's sizes, the snooker pockets' narrowest openings between the curved
// facings, a carom table of four cushions and no pockets, the snooker set-up on its spots, the
// three-cushion opening position, the cue ball in hand and the respotted colours; and strokes of
// snooker and three-cushion played through the engine and decided by their rules (three-cushion's
// against the cushions counted by hand).
#include <billiards/simulation/games.hpp>
#include <billiards/simulation/shot.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

namespace {

using namespace billiards::simulation;
namespace ball = billiards::simulation::snooker_ball;

double distance(const PoolBall& a, const PoolBall& b) {
  return std::hypot(a.position.x() - b.position.x(), a.position.y() - b.position.y());
}

TableVector centre(const PoolBall& b) { return {b.position.x(), b.position.y()}; }

}  // namespace

TEST_CASE("snooker_table: the WPBSA's playing area, pockets narrowest between the curved facings",
          "[simulation][tables]") {
  const PoolTable table = snooker_table();
  CHECK(table.length == 3.569);
  CHECK(table.width == 1.778);
  CHECK(table_preset("snooker") == table);
  const auto cushions = table.cushions();
  const auto jaws = table.jaws();
  REQUIRE(cushions.size() == 6);
  REQUIRE(jaws.size() == 12);
  REQUIRE(table.pockets().size() == 6);
  // The two jaws nearest the corner (0, 0): the head cushion's start and the side cushion's start.
  const Jaw& head = jaws[0];
  const Jaw& side = jaws[4];
  CHECK((head.centre - side.centre).norm() - head.radius - side.radius == Approx(0.083).epsilon(1e-12));
  // The middle pocket at (L/2, 0): the side cushions' inner ends.
  const Jaw& left = jaws[5];
  const Jaw& right = jaws[6];
  CHECK((left.centre - right.centre).norm() - left.radius - right.radius == Approx(0.087).epsilon(1e-12));
  CHECK(head.radius == Approx(4 * 0.0254));
  CHECK(left.radius == Approx(2.5 * 0.0254));
  const PoolPhysics physics = physics_preset("snooker");
  CHECK(2 * physics.radius == Approx(0.0525));
  CHECK(physics.mass == Approx(0.140));
  CHECK(table.nose_height >= physics.radius);
}

TEST_CASE("carom_table: the UMB's 2.84 × 1.42 m, four cushions meeting at the corners, no pockets",
          "[simulation][tables]") {
  const PoolTable table = carom_table();
  CHECK(table.length == 2.84);
  CHECK(table.width == 1.42);
  CHECK(table.nose_height == Approx(0.037));
  CHECK(table.jaws().empty());
  CHECK(table.pockets().empty());
  const auto cushions = table.cushions();
  REQUIRE(cushions.size() == 4);
  double perimeter = 0;
  for (const CushionSegment& c : cushions) {
    perimeter += (c.end - c.start).norm();
    CHECK(c.normal.norm() == Approx(1));
    CHECK(std::fabs(c.normal.dot(c.end - c.start)) < 1e-15);
  }
  CHECK(perimeter == Approx(2 * (2.84 + 1.42)));
  const PoolPhysics physics = physics_preset("carom");
  CHECK(2 * physics.radius == Approx(0.0615));
  CHECK(physics.mass >= 0.205);
  CHECK(physics.mass <= 0.220);
  CHECK(physics.cloth.rolling_friction < PoolPhysics{}.cloth.rolling_friction);
  CHECK_THROWS_WITH(table_preset("12ft"), "table is '12ft', expected 7ft, 8ft, 9ft, snooker or carom");
  CHECK_THROWS_WITH(physics_preset("pocket"), Catch::Contains("expected 7ft, 8ft, 9ft, snooker or carom"));
  CHECK(table_preset("8ft") == pool_table("8ft"));
}

TEST_CASE("carom_table: a ball into a corner meets both cushions and stays on the table",
          "[simulation][tables]") {
  const PoolTable table = carom_table();
  const PoolPhysics physics = carom_physics();
  std::vector<PoolBall> balls(1);
  balls[0].position = {0.5, 0.5, physics.radius};
  ShotOptions options;
  options.check_invariants = true;
  Shot shot(table, physics, balls, options);
  shot.strike(0, {0.567, 6.0, std::atan2(-0.5, -0.5), 0.0, 0.0, 0.0, 1.0});
  shot.play();
  std::vector<std::size_t> cushions;
  for (const ShotEvent& e : shot.events())
    if (e.kind == ShotEvent::Kind::cushion) cushions.push_back(e.second);
  REQUIRE(cushions.size() >= 2);
  CHECK(((cushions[0] == 0 && cushions[1] == 2) || (cushions[0] == 2 && cushions[1] == 0)));
  CHECK_FALSE(shot.balls()[0].pocketed);
}

TEST_CASE("snooker_setup: the colours on their spots, the reds a frozen triangle behind the pink, the white in "
          "the D",
          "[simulation][tables]") {
  const PoolTable table = snooker_table();
  const PoolPhysics physics = snooker_physics();
  const double R = physics.radius, L = table.length, middle = table.width / 2;
  const std::vector<PoolBall> balls = snooker_setup(table, physics);
  REQUIRE(balls.size() == 22);
  const auto at = [&](std::size_t b, double x, double y) {
    CHECK(balls[b].position.x() == Approx(x).margin(1e-12));
    CHECK(balls[b].position.y() == Approx(y).margin(1e-12));
  };
  at(ball::yellow, 0.737, middle - 0.292);
  at(ball::green, 0.737, middle + 0.292);
  at(ball::brown, 0.737, middle);
  at(ball::blue, L / 2, middle);
  at(ball::pink, (L / 2 + L) / 2, middle);
  at(ball::black, L - 0.324, middle);
  const SnookerMarkings m = snooker_markings(table);
  CHECK(m.in_d(centre(balls[0]), table.width));
  // The apex red: on the long axis just behind the pink, not touching it.
  const double apex_gap = distance(balls[ball::first_red], balls[ball::pink]) - 2 * R;
  CHECK(apex_gap > 0);
  CHECK(apex_gap < 3e-3 * R);
  // Every red touches at least two others (up to rounding); no two balls overlap.
  for (std::size_t i = 0; i < balls.size(); ++i) {
    int touching = 0;
    for (std::size_t j = 0; j < balls.size(); ++j) {
      if (i == j) continue;
      CHECK(distance(balls[i], balls[j]) >= 2 * R * (1 - 1e-12));
      touching += std::fabs(distance(balls[i], balls[j]) - 2 * R) < 1e-12 ? 1 : 0;
    }
    if (ball::is_red(i)) CHECK(touching >= 2);
  }
  CHECK(ball::value(ball::first_red) == 1);
  CHECK(ball::value(ball::black) == 7);
  CHECK(std::string(ball::name(ball::brown)) == "brown");
  CHECK_NOTHROW(Shot(table, physics, balls));
  CHECK_THROWS_WITH(snooker_setup(pool_table("7ft"), physics), Catch::Contains("too short"));
}

TEST_CASE("three_cushion_setup: the UMB's opening position", "[simulation][tables]") {
  const PoolTable table = carom_table();
  const PoolPhysics physics = carom_physics();
  const auto balls = three_cushion_setup(table, physics, -1);
  REQUIRE(balls.size() == 3);
  CHECK(balls[2].position.x() == Approx(2.84 - 0.71));
  CHECK(balls[1].position.x() == Approx(0.71));
  CHECK(balls[1].position.y() == Approx(0.71));
  CHECK(balls[0].position.x() == Approx(0.71));
  CHECK(balls[0].position.y() == Approx(0.71 - 0.182));
  CHECK_NOTHROW(Shot(table, physics, balls));
  CHECK_THROWS_WITH(three_cushion_setup(table, physics, 0), "side is 0, expected +1 or -1");
}

TEST_CASE("placing by hand: the cue ball in the D, colours respotted on their spot or the highest free one",
          "[simulation][tables]") {
  const PoolTable table = snooker_table();
  const PoolPhysics physics = snooker_physics();
  const double R = physics.radius;
  const SnookerMarkings m = snooker_markings(table);
  std::vector<PoolBall> balls = snooker_setup(table, physics);
  SECTION("in the D only, on the cloth, clear of every ball") {
    CHECK(place_ball(table, physics, balls, 0, {0.6, table.width / 2}, Placement::in_d));
    CHECK_FALSE(place_ball(table, physics, balls, 0, {0.8, table.width / 2}, Placement::in_d));
    CHECK_FALSE(place_ball(table, physics, balls, 0, m.spot(ball::brown) + TableVector(-R, 0), Placement::in_d));
    CHECK_FALSE(place_ball(table, physics, balls, 0, {0.5 * R, 0.5}, Placement::anywhere));
    CHECK(place_ball(table, physics, balls, 0, {1.0, 0.5}, Placement::anywhere));
    CHECK_FALSE(place_ball(table, physics, balls, 0, {1.0, 0.5}, Placement::behind_head_string));
  }
  SECTION("a wanted place that is taken: the nearest free point to the D's middle") {
    place_cue_ball(table, physics, balls, m.spot(ball::brown), Placement::in_d);
    CHECK(m.in_d(centre(balls[0]), table.width));
    for (std::size_t b = 1; b < balls.size(); ++b) CHECK(distance(balls[0], balls[b]) >= 2 * R);
  }
  SECTION("the pink's spot covered: the pink goes to the highest free spot") {
    balls[ball::pink].pocketed = true;
    balls[ball::blue].pocketed = true;
    balls[ball::black].pocketed = true;
    REQUIRE(place_ball(table, physics, balls, 0, m.spot(ball::pink) + TableVector(0, 1.5 * R)));
    respot_colour(table, physics, balls, ball::pink);
    CHECK(centre(balls[ball::pink]).isApprox(m.spot(ball::black)));
    // The black's spot taken as well: the blue's.
    balls[ball::pink].pocketed = true;
    REQUIRE(place_ball(table, physics, balls, ball::black, m.spot(ball::black)));
    respot_colour(table, physics, balls, ball::pink);
    CHECK(centre(balls[ball::pink]).isApprox(m.spot(ball::blue)));
    CHECK_FALSE(balls[ball::pink].pocketed);
  }
  SECTION("every spot covered: as near its own spot as it fits towards the top cushion") {
    balls[ball::yellow].pocketed = true;
    REQUIRE(place_ball(table, physics, balls, 0, m.spot(ball::yellow)));
    respot_colour(table, physics, balls, ball::yellow);
    CHECK(balls[ball::yellow].position.y() == Approx(m.spot(ball::yellow).y()));
    CHECK(balls[ball::yellow].position.x() > m.spot(ball::yellow).x() + 2 * R);
    CHECK(balls[ball::yellow].position.x() < m.spot(ball::yellow).x() + 2 * R + R / 8 + 1e-12);
  }
  CHECK_THROWS_WITH(respot_colour(table, physics, balls, 3), Catch::Contains("is not a colour"));
}

TEST_CASE("snooker through the engine: a red potted, then an in-off", "[simulation][games][snooker]") {
  const PoolTable table = snooker_table();
  const PoolPhysics physics = snooker_physics();
  const double R = physics.radius;
  std::vector<PoolBall> balls = snooker_setup(table, physics);
  for (std::size_t b = 2; b <= ball::last_red; ++b) balls[b].pocketed = true;
  games::SnookerState state;
  for (std::size_t b = 2; b <= ball::last_red; ++b) state.on_table[b] = false;
  // Red 1 in front of the top-right corner pocket at (L, W), the white behind it on the diagonal.
  const Eigen::Vector3d diagonal = Eigen::Vector3d(1, 1, 0).normalized();
  const Eigen::Vector3d corner(table.length, table.width, R);
  balls[1].position = corner - 0.25 * diagonal;
  balls[0].position = corner - 0.6 * diagonal;
  const auto play = [&](const std::vector<PoolBall>& layout, const billiards::Cue<double>& cue) {
    Shot shot(table, physics, layout);
    shot.strike(0, cue);
    shot.play();
    return games::snooker(state, shot.events());
  };
  auto d = play(balls, {0.567, 2.0, M_PI / 4, 0.0, 0.0, -0.3, 1.0});
  CHECK(d.verdict.legal());
  CHECK(d.verdict.points == 1);
  CHECK(d.next.on == games::SnookerOn::colour);
  // Followed through hard: the white drops after the red, an in-off worth 4 to the opponent.
  d = play(balls, {0.567, 2.5, M_PI / 4, 0.0, 0.0, 0.6, 1.0});
  CHECK(d.verdict.fouls == std::vector<games::Foul>{games::Foul::scratch});
  CHECK(d.verdict.penalty == 4);
  CHECK(d.next.ball_in_hand == games::BallInHand::in_d);
}

TEST_CASE("three-cushion through the engine: shots from the opening position decided as counted by hand",
          "[simulation][games][three_cushion]") {
  const PoolTable table = carom_table();
  const PoolPhysics physics = carom_physics();
  const std::vector<PoolBall> opening = three_cushion_setup(table, physics);
  int points = 0, misses = 0;
  for (int k = 0; k < 360; ++k) {
    Shot shot(table, physics, opening);
    shot.strike(0, {0.567, 3.0 + 3.0 * (k % 3), 2 * M_PI * k / 360.0, 0.0, 0.0, 0.2, 1.0});
    shot.play();
    // By hand: the white's cushions until it has met both other balls.
    int cushions = 0;
    bool met[3] = {false, false, false}, scored = false;
    for (const ShotEvent& e : shot.events()) {
      if (e.kind == ShotEvent::Kind::cushion && e.first == 0) ++cushions;
      if (e.kind != ShotEvent::Kind::ball || (e.first != 0 && e.second != 0)) continue;
      met[e.first == 0 ? e.second : e.first] = true;
      if (met[1] && met[2]) {
        scored = cushions >= 3;
        break;
      }
    }
    const auto d = games::three_cushion(games::ThreeCushionState{}, shot.events());
    CHECK(d.verdict.points == (scored ? 1 : 0));
    CHECK(d.next.player == (scored ? 0u : 1u));
    (scored ? points : misses) += 1;
  }
  // The fan of shots holds both outcomes.
  CHECK(points > 0);
  CHECK(misses > 0);
}
