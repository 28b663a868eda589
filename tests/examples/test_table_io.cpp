// billiards::io's table setup files and SVG (billiards/io/table.hpp) over the simulation
// library's table.
#include <billiards/io/table.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace billiards::simulation;
using namespace billiards::io;

TEST_CASE("Setup files", "[examples][table]") {
  SECTION("every directive, comments and blank lines") {
    std::istringstream in(
        "# two balls\ntable 3 1.5\nradius 0.1\n\nmass 0.2  # kg\nball 1 0.75 1 0\nball 2 0.75 0 0\n");
    const TableSetup setup = read_setup(in, "two.setup");
    CHECK(setup.width == 3);
    CHECK(setup.height == 1.5);
    CHECK(setup.radius == 0.1);
    CHECK(setup.mass == 0.2);
    REQUIRE(setup.balls.size() == 2);
    CHECK(setup.balls[1].position == TableVector(2, 0.75));
  }
  SECTION("an unknown directive names the file and line") {
    std::istringstream in("table 3 1.5\nballs 1 1 0 0\n");
    CHECK_THROWS_WITH(
        read_setup(in, "bad.setup"),
        Catch::Contains("bad.setup:2: unknown directive 'balls'") && Catch::Contains("expected"));
  }
  SECTION("a wrong number of numbers") {
    std::istringstream in("ball 1 1 0\n");
    CHECK_THROWS_WITH(read_setup(in, "bad.setup"),
                      Catch::Contains("bad.setup:1: ball: 3 numbers, expected 4"));
  }
  SECTION("something that is not a number") {
    std::istringstream in("radius big\n");
    CHECK_THROWS_WITH(read_setup(in, "bad.setup"), Catch::Contains("'big' is not a finite number"));
  }
  SECTION("an invalid table names the file and the line") {
    std::istringstream in("ball 1 0.5 0 0\nball 1.01 0.5 0 0\n");
    CHECK_THROWS_WITH(read_setup(in, "bad.setup"), Catch::Contains("bad.setup:2: balls 0 and 1 overlap"));
  }
  SECTION("every validation error names the line it comes from") {
    std::istringstream off("# a comment\nball 1 0.5 0 0\n\nball 3 0.5 0 0\n");
    CHECK_THROWS_WITH(read_setup(off, "bad.setup"),
                      Catch::StartsWith("bad.setup:4: ball 1 at (3, 0.5) is outside"));
    std::istringstream radius("ball 1 0.5 0 0\nradius -1\n");
    CHECK_THROWS_WITH(read_setup(radius, "bad.setup"), Catch::StartsWith("bad.setup:2: radius is -1"));
    std::istringstream mass("mass 0\nball 1 0.5 0 0\n");
    CHECK_THROWS_WITH(read_setup(mass, "bad.setup"), Catch::StartsWith("bad.setup:1: mass is 0"));
    std::istringstream table("table 0.01 1\nball 1 0.5 0 0\n");
    CHECK_THROWS_WITH(read_setup(table, "bad.setup"), Catch::StartsWith("bad.setup:1: radius is"));
    std::istringstream none("# nothing\n");
    CHECK_THROWS_WITH(read_setup(none, "bad.setup"), Catch::StartsWith("bad.setup: no balls"));
  }
  SECTION("numbers: subnormal values are numbers, underflow and overflow are named") {
    std::istringstream tiny("ball 1 0.5 1e-310 0\n");
    CHECK(read_setup(tiny, "tiny.setup").balls[0].velocity.x() == 1e-310);
    std::istringstream zero("ball 1 0.5 1e-400 0\n");
    CHECK_THROWS_WITH(read_setup(zero, "bad.setup"),
                      Catch::Contains("'1e-400' is below the smallest subnormal"));
    std::istringstream huge("ball 1 0.5 1e400 0\n");
    CHECK_THROWS_WITH(read_setup(huge, "bad.setup"), Catch::Contains("'1e400' is not a finite number"));
  }
  SECTION("a hostile file: an endless line is cut short, and so is its quote") {
    std::istringstream endless("ball " + std::string(1 << 20, '7') + "\n");
    try {
      (void)read_setup(endless, "zero.setup");
      FAIL("accepted");
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      CHECK_THAT(message, Catch::StartsWith("zero.setup:1: the line is longer than 4096 characters"));
      CHECK(message.size() < 300);
    }
    std::istringstream word("radius " + std::string(3000, 'x') + "\n");
    try {
      (void)read_setup(word, "word.setup");
      FAIL("accepted");
    } catch (const std::invalid_argument& error) {
      CHECK(std::string(error.what()).size() < 300);
    }
  }
  SECTION("a file that cannot be opened says why") {
    CHECK_THROWS_WITH(
        read_setup_file("/nonexistent/table.setup"),
        Catch::Contains("/nonexistent/table.setup: cannot open the setup file: No such file or directory"));
    CHECK_THROWS_WITH(read_setup_file("/tmp"), Catch::Contains("is a folder"));
  }
}

TEST_CASE("Trajectories as SVG", "[examples][table]") {
  Table simulation(break_setup(TableSetup{}));
  Trajectories trajectories(simulation.setup());
  for (int i = 0; i < 40; ++i) trajectories.record(simulation.step().value(), simulation.balls());
  trajectories.finish(simulation.balls());
  const std::string svg = trajectories.svg("the break");
  CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
  CHECK(svg.find("</svg>\n") == svg.size() - 7);
  std::size_t polylines = 0;
  for (std::size_t at = svg.find("<polyline"); at != std::string::npos; at = svg.find("<polyline", at + 1))
    ++polylines;
  CHECK(polylines == 16);
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "billiards_test_break.svg";
  write_file_atomically(path, svg);
  std::ifstream in(path);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(written == svg);
  CHECK_FALSE(std::filesystem::exists(path.string() + ".tmp"));
  std::filesystem::remove(path);
  CHECK_THROWS_WITH(write_file_atomically("/nonexistent-folder/x.svg", svg),
                    Catch::Contains("/nonexistent-folder/x.svg"));
}
