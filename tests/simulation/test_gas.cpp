// The hard-sphere gas of billiards/simulation/gas.hpp against results no one here wrote: the equations of
// state of Henderson (disks) and Carnahan and Starling (spheres), the virial series at low density, the
// identity that ties the virial to the collision rate; conservation of energy and momentum; no overlap,
// checked over every pair at the end; every collision taken at contact; and the arguments it rejects.
#include <billiards/simulation/gas.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace gas = billiards::simulation::gas;
using billiards::simulation::Gas;

namespace {

gas::Options options(int dimension, std::size_t balls, double eta, std::uint64_t events,
                     std::uint64_t equilibrate) {
  gas::Options o;
  o.dimension = dimension;
  o.balls = balls;
  o.packing_fraction = eta;
  o.events = events;
  o.equilibrate = equilibrate;
  o.seed = 3;
  return o;
}

// Z within `relative` of `expected` plus five standard errors (the block estimate's).
void check_z(const gas::Result& r, double expected, double relative) {
  INFO("Z = " << r.compressibility_factor << " ± " << r.compressibility_factor_error << ", expected "
              << expected << " (η = " << r.packing_fraction << ", " << r.dimension << "-D)");
  CHECK(r.compressibility_factor_error > 0);
  CHECK(std::fabs(r.compressibility_factor - expected) <=
        relative * expected + 5 * r.compressibility_factor_error);
}

// Z − 1 = σ √(π m/kT)/(2 d τ): the virial and the collision rate agree within their errors.
void check_identity(const gas::Result& r) {
  const double error =
      std::hypot(r.compressibility_factor_error, r.compressibility_factor_from_collision_rate_error);
  INFO("virial Z = " << r.compressibility_factor << ", from the collision rate "
                     << r.compressibility_factor_from_collision_rate << ", error " << error);
  CHECK(std::fabs(r.compressibility_factor - r.compressibility_factor_from_collision_rate) <= 5 * error);
}

void check_conservation(const gas::Result& r) {
  CHECK(std::fabs(r.temperature - 1) < 1e-12);
  CHECK(r.largest_temperature_change < 1e-12);
  CHECK(r.momentum < 1e-10);
  CHECK(r.largest_overlap < 1e-9);
  CHECK(r.largest_gap < 1e-9);  // no collision taken before the balls touch (a stale one)
}

}  // namespace

TEST_CASE("spheres follow Carnahan-Starling from dilute to dense fluid", "[gas]") {
  for (const double eta : {0.1, 0.3, 0.45}) {
    const gas::Result r = gas::measure(options(3, 500, eta, 150000, 50000));
    check_z(r, gas::carnahan_starling(eta), 0.01);
    check_identity(r);
    check_conservation(r);
  }
}

TEST_CASE("disks follow Henderson's equation of state up to the dense fluid", "[gas]") {
  for (const double eta : {0.1, 0.4, 0.6}) {
    const gas::Result r = gas::measure(options(2, 400, eta, 150000, 50000));
    check_z(r, gas::henderson(eta), 0.015);
    check_identity(r);
    check_conservation(r);
  }
}

TEST_CASE("at low density Z follows the virial series", "[gas]") {
  // Spheres: B2..B5 in powers of η, 4, 10, 18.365, 28.224; disks: 2, 3.1280, 4.2579.
  const double eta = 0.05;
  const gas::Result spheres = gas::measure(options(3, 500, eta, 100000, 20000));
  check_z(spheres, 1 + 4 * eta + 10 * eta * eta + 18.365 * std::pow(eta, 3) + 28.224 * std::pow(eta, 4),
          0.005);
  const gas::Result disks = gas::measure(options(2, 400, eta, 100000, 20000));
  check_z(disks, 1 + 2 * eta + 3.128 * eta * eta + 4.2579 * std::pow(eta, 3), 0.005);
}

TEST_CASE("a million collisions keep the energy, the momentum and the spheres apart", "[gas]") {
  const gas::Result r = gas::measure(options(3, 1000, 0.3, 1000000, 10000));
  CHECK(r.collisions == 1000000);
  check_conservation(r);
}

TEST_CASE("a gas beyond the caches, where each event prefetches the next ones, keeps its laws", "[gas]") {
  // 40000 disks: above the 2^15 balls from which the gas looks ahead in its calendar (and above the
  // 4096 from which it renumbers the balls by cell), so these paths run here and under the sanitizers.
  for (const int dimension : {2, 3}) {
    const gas::Result r = gas::measure(options(dimension, 40000, 0.3, 120000, 40000));
    INFO(dimension << "-D");
    CHECK(r.collisions == 120000);
    check_conservation(r);
    check_identity(r);
  }
}

TEST_CASE("no pair overlaps at the end: no collision was missed", "[gas]") {
  for (const int dimension : {2, 3}) {
    const auto check = [&](auto gas_of_dimension) {
      auto& g = gas_of_dimension;
      (void)gas::measure(g, options(dimension, 300, dimension == 2 ? 0.5 : 0.4, 20000, 1000));
      const auto positions = g.positions();
      double closest = g.side();
      for (std::size_t i = 0; i < positions.size(); ++i) {
        for (std::size_t j = i + 1; j < positions.size(); ++j) {
          closest = std::min(closest, g.nearest_image(positions[i], positions[j]).norm());
        }
      }
      INFO(dimension << "-D: the closest pair is " << closest << " diameters apart");
      CHECK(closest > 1 - 1e-9);
    };
    if (dimension == 2)
      check(Gas<2>(gas::lattice<2>(options(2, 300, 0.5, 20000, 1000))));
    else
      check(Gas<3>(gas::lattice<3>(options(3, 300, 0.4, 20000, 1000))));
  }
}

TEST_CASE("arguments the gas rejects, with what was expected", "[gas]") {
  const auto rejects = [](const gas::Options& o, const std::string& words) {
    try {
      gas::validate(o);
      FAIL("accepted, expected a rejection saying: " << words);
    } catch (const std::invalid_argument& error) {
      INFO(error.what());
      CHECK(std::string(error.what()).find(words) != std::string::npos);
    }
  };
  rejects(options(4, 1000, 0.3, 1, 0), "--dimension is 4, expected 2 or 3");
  rejects(options(3, 1, 0.3, 1, 0), "--balls is 1, expected at least 2");
  rejects(options(3, 1000, gas::close_packing(3), 1, 0), "less than close packing");
  rejects(options(2, 1000, 0.95, 1, 0), "less than close packing");
  rejects(options(3, 1000, 0, 1, 0), "--packing-fraction is 0");
  rejects(options(3, 10, 0.3, 1, 0), "too few for the box");
  rejects(options(3, 1000, 0.72, 1, 0), "too dense for a FCC lattice start");
  // So dilute that positions in the box round by more than 1e-9 of a diameter (16 ε side): the side
  // (N v/η)^(1/D) may be at most 1e-9/(16 ε) = 281 475 diameters.
  rejects(options(3, 100, 1e-300, 1, 0), "--packing-fraction is 1e-300, expected at least 2.3479e-15");
  rejects(options(2, 20, 1e-10, 1, 0), "expected at least 1.98262e-10 for 20 balls in 2-D");
  const double side = 1e-9 / (16 * std::numeric_limits<double>::epsilon());
  CHECK_NOTHROW(
      gas::validate(options(3, 100, 100 * (std::numbers::pi / 6) / std::pow(side, 3) * 1.001, 1, 0)));
  CHECK_NOTHROW(gas::validate(options(3, 1000, 0.3, 1, 0)));
}

TEST_CASE("a dilute gas's cell grid follows the balls, not the box", "[gas]") {
  // One cell a diameter while the grid stays within max(2^24, 4 N) cells: every run the guides and
  // the figures show keeps that grid; 1000 balls at η = 1e-12 (a box of 8e4 diameters, 5e14 cells
  // of one diameter) get 256^3 = 2^24 cells of 314 diameters.
  CHECK(gas::grid_cells_per_side(3, 1000, gas::box_side(3, 1000, 0.3)) == 12);
  CHECK(gas::grid_cells_per_side(2, 400, gas::box_side(2, 400, 0.05)) == 79);
  CHECK(gas::grid_cells_per_side(3, 1000, gas::box_side(3, 1000, 1e-12)) == 256);
  CHECK(gas::grid_cells_per_side(2, 1000, gas::box_side(2, 1000, 1e-8)) == 4096);
  CHECK(gas::grid_cells_per_side(3, std::size_t(1) << 31, gas::box_side(3, std::size_t(1) << 31, 0.3)) ==
        1290);
  const Gas<3> dilute(gas::lattice<3>(options(3, 1000, 1e-12, 1, 0)));
  CHECK(dilute.cells_per_side() == 256);
}
