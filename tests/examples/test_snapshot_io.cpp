// Snapshot files (billiards/io/snapshots.hpp): .sph as Smallenburg's code writes it and extended XYZ as
// OVITO reads it, read back bit for bit, and every bad file told by its name, line and what was expected.
#include <billiards/io/snapshots.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

using namespace billiards::io;
using Catch::Matchers::Contains;

namespace {

// Three particles of two species, unequal radii and masses, numbers that need all 17 digits.
Snapshot mixture() {
  Snapshot s;
  s.box = {10.5, 11.25, 0.1 + 0.2 + 12};
  s.time = 1.0 / 3;
  s.particles = {{"a", {0.1, 0.2, 0.3}, {1.0 / 7, -2, 0.5}, 0.5, 1},
                 {"b", {5, 6.000000000000001, 7}, {-1e-300, 0, 3}, 0.35, 0.343},
                 {"big", {9.999999999999998, 1, 2}, {0, 0, -1.0 / 3}, 0.6, std::ldexp(1.0, -20)}};
  return s;
}

}  // namespace

TEST_CASE("Extended XYZ keeps every property of a polydisperse snapshot, bit for bit", "[examples][snapshot]") {
  const Snapshot s = mixture();
  std::istringstream in(extended_xyz_text(s));
  const Snapshot back = read_extended_xyz(in, "mix.xyz");
  CHECK(back.dimension == 3);
  CHECK(back.box == s.box);
  CHECK(back.time == s.time);
  REQUIRE(back.particles.size() == 3);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(back.particles[i].species == s.particles[i].species);
    CHECK(back.particles[i].position == s.particles[i].position);
    CHECK(back.particles[i].velocity == s.particles[i].velocity);
    CHECK(back.particles[i].radius == s.particles[i].radius);
    CHECK(back.particles[i].mass == s.particles[i].mass);
  }
}

TEST_CASE("A .sph file keeps types, centres and radii, bit for bit", "[examples][snapshot]") {
  Snapshot s = mixture();
  s.particles[2].species = "c";
  std::istringstream in(sph_text(s));
  const Snapshot back = read_sph(in, "mix.sph");
  CHECK(back.box == s.box);
  REQUIRE(back.particles.size() == 3);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(back.particles[i].species == s.particles[i].species);
    CHECK(back.particles[i].position == s.particles[i].position);
    CHECK(back.particles[i].radius == s.particles[i].radius);
    // The format holds neither: read as at rest, of mass 1.
    CHECK(back.particles[i].velocity == Eigen::Vector3d::Zero());
    CHECK(back.particles[i].mass == 1);
  }
  SECTION("a 2-D snapshot cannot be written as .sph") {
    Snapshot disks = s;
    disks.dimension = 2;
    CHECK_THROWS_WITH(sph_text(disks), "a 2-D snapshot, expected a 3-D one for .sph (disks go in extended XYZ)");
  }
  SECTION("a species longer than one character cannot be written") {
    CHECK_THROWS_WITH(sph_text(mixture()), "particle 2's species is 'big', expected one character that is not a space (.sph)");
  }
}

TEST_CASE("Files as the peers write them", "[examples][snapshot]") {
  SECTION("Smallenburg's snapshot_end.sph: %c %.12lf  %.12lf  %.12lf  %lf") {
    std::istringstream in("2\n8.000000000000 8.000000000000 8.000000000000\n"
                          "a 0.250000000000  0.750000000000  1.250000000000  0.500000\n"
                          "b 7.500000000000  6.000000000000  -0.125000000000  0.400000\n");
    const Snapshot s = read_sph(in, "snapshot_end.sph");
    REQUIRE(s.particles.size() == 2);
    CHECK(s.box == Eigen::Vector3d(8, 8, 8));
    CHECK(s.particles[1].species == "b");
    CHECK(s.particles[1].position == Eigen::Vector3d(7.5, 6, -0.125));
    CHECK(s.particles[1].radius == 0.4);
  }
  SECTION("extended XYZ with other columns, keys in any case, no velocities, radii or masses") {
    std::istringstream in("2\r\nproperties=id:I:1:species:S:1:pos:R:3:color:R:3 LATTICE=\"4 0 0 0 5 0 0 0 6\" "
                          "Time=2.5 pbc=\"T T T\"\r\n"
                          "7 He 1 2 3 0.1 0.2 0.3\r\n8 Ne 3 2 1 1 1 1\r\n");
    const Snapshot s = read_extended_xyz(in, "ovito.xyz");
    REQUIRE(s.particles.size() == 2);
    CHECK(s.box == Eigen::Vector3d(4, 5, 6));
    CHECK(s.time == 2.5);
    CHECK(s.particles[0].species == "He");
    CHECK(s.particles[1].position == Eigen::Vector3d(3, 2, 1));
    CHECK(s.particles[1].velocity == Eigen::Vector3d::Zero());
    CHECK(s.particles[1].radius == 0.5);
    CHECK(s.particles[1].mass == 1);
  }
  SECTION("a 2-D snapshot: pbc=\"T T F\", in the plane z = 0") {
    Snapshot s = mixture();
    s.dimension = 2;
    for (SnapshotParticle& p : s.particles) p.position.z() = p.velocity.z() = 0;
    std::istringstream in(extended_xyz_text(s));
    const Snapshot back = read_extended_xyz(in, "disks.xyz");
    CHECK(back.dimension == 2);
    CHECK(back.particles[1].position == s.particles[1].position);
  }
}

TEST_CASE("A bad snapshot file is told by its name, line and what was expected", "[examples][snapshot]") {
  const auto sph = [](const std::string& text) {
    std::istringstream in(text);
    return read_sph(in, "bad.sph");
  };
  const auto xyz = [](const std::string& text) {
    std::istringstream in(text);
    return read_extended_xyz(in, "bad.xyz");
  };
  CHECK_THROWS_WITH(sph(""), "bad.sph:1: the file is empty, expected the particle count");
  CHECK_THROWS_WITH(sph("two\n"), Contains("bad.sph:1: 'two' is not a particle count, expected a whole number"));
  CHECK_THROWS_WITH(sph("0\n1 1 1\n"), Contains("bad.sph:1: '0' is not a particle count"));
  CHECK_THROWS_WITH(sph("-1\n1 1 1\n"), Contains("bad.sph:1: '-1' is not a particle count"));
  CHECK_THROWS_WITH(sph("1\n1 1\n"), "bad.sph:2: 2 numbers, expected the box's three sides 'Lx Ly Lz'");
  CHECK_THROWS_WITH(sph("1\n1 -1 1\n"), "bad.sph:2: the box's side is -1, expected a positive number");
  CHECK_THROWS_WITH(sph("1\n1 1 1\na 0 0 0\n"), "bad.sph:3: 'a 0 0 0', expected 'type x y z radius', the type one character");
  CHECK_THROWS_WITH(sph("1\n1 1 1\na 0 0 0 1 red\n"), "bad.sph:3: 'a 0 0 0 1 red', expected 'type x y z radius', the type one character");
  CHECK_THROWS_WITH(sph("1\n1 1 1\nab 0 0 0 1\n"), "bad.sph:3: 'ab 0 0 0 1', expected 'type x y z radius', the type one character");
  CHECK_THROWS_WITH(sph("1\n1 1 1\na 0 0 0 0\n"), "bad.sph:3: the radius is 0, expected a positive number");
  CHECK_THROWS_WITH(sph("1\n1 1 1\na 0 nan 0 1\n"), Contains("bad.sph:3: 'nan' is not a finite number"));
  CHECK_THROWS_WITH(sph("2\n1 1 1\na 0 0 0 1\n"), "bad.sph:4: the file ends after 1 particles, expected 2");
  CHECK_THROWS_WITH(sph("1\n1 1 1\na 0 0 0 1\n\na 0 0 0 1\n"),
                    "bad.sph:5: a line after the 1 particles the first line declares, expected the end of the file");
  CHECK_THROWS_WITH(sph("1\n1 1 1\n" + std::string(5000, 'x')), Contains("bad.sph:3: the line is longer than 4096 characters"));
  const std::string box = "Lattice=\"2 0 0 0 2 0 0 0 2\"";
  CHECK_THROWS_WITH(xyz("1\nTime=1\n"), Contains("bad.xyz:2: no Lattice=\"…\""));
  CHECK_THROWS_WITH(xyz("1\nLattice=\"2 0 0 0 2 1 0 0 2\"\n"), Contains("bad.xyz:2: Lattice=\"2 0 0 0 2 1 0 0 2\" is not diagonal"));
  CHECK_THROWS_WITH(xyz("1\nLattice=\"2 0 0 0 2 0 0 0\"\n"), "bad.xyz:2: Lattice has 8 numbers, expected 9");
  CHECK_THROWS_WITH(xyz("1\nLattice=\"2 0 0\n"), Contains("bad.xyz:2: lattice's value has no closing quote"));
  CHECK_THROWS_WITH(xyz("1\n" + box + " pbc=\"F F F\"\n"), Contains("bad.xyz:2: pbc=\"F F F\", expected \"T T T\" (3-D) or \"T T F\" (2-D)"));
  CHECK_THROWS_WITH(xyz("1\n" + box + " Properties=species:S:1:velo:R:3\n"), Contains("bad.xyz:2: Properties has no pos"));
  CHECK_THROWS_WITH(xyz("1\n" + box + " Properties=species:S:1:pos:R:2\n"), "bad.xyz:2: Properties: pos has 2 columns, expected 3");
  CHECK_THROWS_WITH(xyz("1\n" + box + " Properties=species:S:1:pos:R\n"), Contains("expected name:type:count triples"));
  CHECK_THROWS_WITH(xyz("1\n" + box + "\nH 0 0\n"), Contains("bad.xyz:3: 3 fields, expected 4"));
  CHECK_THROWS_WITH(xyz("1\n" + box + " Properties=species:S:1:pos:R:3:mass:R:1\nH 0 0 0 -2\n"),
                    "bad.xyz:3: the mass is -2, expected a positive number");
  CHECK_THROWS_WITH(xyz("1\n" + box + " pbc=\"T T F\"\nH 0 0 1\n"), Contains("bad.xyz:3: z or v_z is not 0"));
  CHECK_THROWS_WITH(xyz("2\n" + box + "\nH 0 0 0\n"), "bad.xyz:4: the file ends after 1 particles, expected 2");
}

TEST_CASE("Snapshot files by name: written atomically, read back", "[examples][snapshot]") {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "billiards_snapshot_io_test";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const Snapshot s = mixture();
  write_snapshot_file((folder / "state.extxyz").string(), s);
  const Snapshot back = read_snapshot_file((folder / "state.extxyz").string());
  CHECK(back.particles[2].mass == s.particles[2].mass);
  CHECK_THROWS_WITH(write_snapshot_file((folder / "state.txt").string(), s),
                    Contains("state.txt: not a snapshot file name, expected one ending in .sph, .xyz or .extxyz"));
  CHECK_THROWS_WITH(read_snapshot_file((folder / "missing.sph").string()), Contains("missing.sph: cannot open it"));
  std::filesystem::remove_all(folder);
}
