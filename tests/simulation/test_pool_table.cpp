// The pool table's geometry and racks against their definitions worked by hand: the WPA's sizes, the
// cushions between the pockets' mouths, jaws tangent to the noses where the cushions end, capture circles
// behind the noses, racks that touch or keep their gaps, numbered as the games rack them.
#include <billiards/simulation/shot.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using billiards::simulation::PoolTable;
using billiards::simulation::TableVector;

TEST_CASE("pool_table: the presets' playing surfaces", "[simulation][pool]") {
  const double inch = 0.0254;
  CHECK(billiards::simulation::pool_table("9ft").length == Approx(100 * inch).epsilon(1e-12));
  CHECK(billiards::simulation::pool_table("9ft").width == Approx(50 * inch).epsilon(1e-12));
  CHECK(billiards::simulation::pool_table("8ft").length == Approx(92 * inch).epsilon(1e-12));
  CHECK(billiards::simulation::pool_table("8ft").width == Approx(46 * inch).epsilon(1e-12));
  CHECK(billiards::simulation::pool_table("7ft").length == Approx(78 * inch).epsilon(1e-12));
  CHECK(billiards::simulation::pool_table("7ft").width == Approx(39 * inch).epsilon(1e-12));
  const PoolTable table = billiards::simulation::pool_table("9ft");
  CHECK(table.corner_mouth >= 4.5 * inch);
  CHECK(table.corner_mouth <= 4.625 * inch);
  CHECK(table.side_mouth >= 5 * inch);
  CHECK(table.side_mouth <= 5.125 * inch);
  CHECK(table.nose_height / (2 * 0.028575) == Approx(0.635).epsilon(1e-3));
  CHECK_THROWS_WITH(billiards::simulation::pool_table("10ft"), "table is '10ft', expected 7ft, 8ft or 9ft");
}

TEST_CASE("pool_table: cushions between the mouths, jaws tangent at their ends, pockets behind the noses",
          "[simulation][pool]") {
  for (const char* size : {"7ft", "8ft", "9ft"}) {
    const PoolTable table = billiards::simulation::pool_table(size);
    const auto cushions = table.cushions();
    const auto jaws = table.jaws();
    const auto pockets = table.pockets();
    REQUIRE(cushions.size() == 6);
    REQUIRE(jaws.size() == 12);
    REQUIRE(pockets.size() == 6);
    double nose_length = 0;
    for (std::size_t i = 0; i < cushions.size(); ++i) {
      const auto& c = cushions[i];
      INFO(size << " cushion " << i);
      CHECK(c.normal.norm() == Approx(1).epsilon(1e-15));
      CHECK(std::fabs((c.end - c.start).dot(c.normal)) <= 1e-15);  // the normal is across the nose
      const TableVector inside = (c.start + c.end) / 2 + 0.01 * c.normal;
      CHECK(inside.x() > 0);
      CHECK(inside.x() < table.length);
      CHECK(inside.y() > 0);
      CHECK(inside.y() < table.width);
      nose_length += (c.end - c.start).norm();
      for (int k = 0; k < 2; ++k) {
        const auto& jaw = jaws[2 * i + static_cast<std::size_t>(k)];
        const TableVector end = k == 0 ? c.start : c.end;
        // Behind the nose line by its radius, straight behind the cushion's end.
        CHECK((end - jaw.centre).dot(c.normal) == Approx(jaw.radius).epsilon(1e-12));
        CHECK((end - jaw.centre - jaw.radius * c.normal).norm() <= 1e-15);
      }
    }
    // The noses' length: each rail less m_c/√2 at each of its corners, the long rails less a side mouth.
    const double c = table.corner_mouth / std::sqrt(2.0);
    CHECK(nose_length == Approx(2 * (table.length - 2 * c) + 2 * (table.width - 2 * c) - 2 * table.side_mouth));
    // The mouths: between the ends of the cushions meeting at each pocket.
    CHECK((cushions[0].start - cushions[2].start).norm() == Approx(table.corner_mouth));
    CHECK((cushions[3].start - cushions[2].end).norm() == Approx(table.side_mouth));
    for (const auto& pocket : pockets) {
      const bool beyond = pocket.centre.x() < 0 || pocket.centre.x() > table.length || pocket.centre.y() < 0 ||
                          pocket.centre.y() > table.width;
      CHECK(beyond);
      CHECK(pocket.radius > 0.028575);
    }
  }
}

TEST_CASE("rack: touching racks, numbered as the games rack them", "[simulation][pool]") {
  const PoolTable table = billiards::simulation::pool_table("9ft");
  const billiards::simulation::PoolPhysics physics;
  const double R = physics.radius;
  for (const auto kind : {billiards::simulation::Rack::nine_ball, billiards::simulation::Rack::eight_ball}) {
    const auto balls = billiards::simulation::rack(table, physics, kind);
    const bool nine = kind == billiards::simulation::Rack::nine_ball;
    REQUIRE(balls.size() == (nine ? 10u : 16u));
    CHECK(balls[0].position.head<2>() == table.head_spot());
    CHECK(balls[1].position.head<2>() == table.foot_spot());
    // The 9 (or the 8) in the middle of the third row, two rows behind the apex, on the long axis.
    const auto& middle = balls[nine ? 9 : 8].position;
    CHECK(middle.x() == Approx(table.foot_spot().x() + 2 * std::sqrt(3.0) * R));
    CHECK(middle.y() == Approx(table.width / 2));
    int touching = 0;
    for (std::size_t i = 0; i < balls.size(); ++i) {
      CHECK(balls[i].position.z() == R);
      CHECK(balls[i].velocity.isZero(0));
      CHECK_FALSE(balls[i].pocketed);
      for (std::size_t j = i + 1; j < balls.size(); ++j) {
        const double d = (balls[i].position - balls[j].position).norm();
        CHECK(d >= 2 * R * (1 - 1e-12));
        touching += d <= 2 * R * (1 + 1e-12);
      }
    }
    // Every neighbour touches: 16 pairs in the diamond, 30 in the triangle.
    CHECK(touching == (nine ? 16 : 30));
  }
}

TEST_CASE("rack: a jitter keeps every gap at least jitter R, the same seed the same rack", "[simulation][pool]") {
  const PoolTable table = billiards::simulation::pool_table("8ft");
  const billiards::simulation::PoolPhysics physics;
  const double R = physics.radius;
  const auto a = billiards::simulation::rack(table, physics, billiards::simulation::Rack::eight_ball, 0.01, 7);
  const auto b = billiards::simulation::rack(table, physics, billiards::simulation::Rack::eight_ball, 0.01, 7);
  const auto c = billiards::simulation::rack(table, physics, billiards::simulation::Rack::eight_ball, 0.01, 8);
  bool differs = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].position == b[i].position);
    differs = differs || a[i].position != c[i].position;
    for (std::size_t j = i + 1; j < a.size(); ++j) CHECK((a[i].position - a[j].position).norm() >= 2 * R + 0.01 * R);
  }
  CHECK(differs);
  CHECK_THROWS_WITH(billiards::simulation::rack(table, physics, billiards::simulation::Rack::nine_ball, 2.0),
                    Catch::Contains("jitter is 2"));
}
