// billiards-gas-figure: the hard-sphere gas's equation of state as SVG, Z = PV/(N kT) against the
// packing fraction η from gas.hpp's runs (disks η = 0.05 … 0.6, spheres 0.05 … 0.45) over the
// equations of state of Henderson (disks) and Carnahan and Starling (spheres).
//
//   billiards-gas-figure [--out FOLDER] [--events E]
//
// Writes FOLDER/gas_equation_of_state.svg and prints each run's Z beside its equation of state. Exit
// status: 0; 1 when a run's Z is farther from its equation of state than 3 % plus five standard
// errors; 2 on a bad command line; 3 when the SVG cannot be written.
#include <billiards/io/plot.hpp>
#include <billiards/simulation/gas.hpp>

#include <billiards/io/atomic_file.hpp>
#include <billiards_support/cli_checks.hpp>
#include <billiards_support/standard_output.hpp>

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using namespace billiards::io;
  namespace gas = billiards::simulation::gas;
  CLI::App app{"Draws the hard-sphere gas's Z(eta) over its equations of state as SVG.",
               "billiards-gas-figure"};
  std::string out = ".";
  std::uint64_t events = 200000;
  app.add_option("--out", out, "Folder the SVG is written to (default: the current folder)");
  app.add_option("--events", events, "Collisions measured per run (default 200000)")
      ->check(CLI::PositiveNumber);
  if (const std::optional<int> code = billiards_support::parse_command_line(app, argc, argv)) return *code;
  std::error_code folder_error;
  if (!std::filesystem::is_directory(out, folder_error)) {
    std::cerr << "billiards-gas-figure: --out: '" << out
              << "' is not a folder, expected an existing folder\n";
    return 2;
  }

  Series henderson{"Henderson, disks: (1 + η²/8)/(1 − η)²", "#2e86c1", Series::Style::line, {}};
  Series carnahan{
      "Carnahan–Starling, spheres: (1 + η + η² − η³)/(1 − η)³", "#c0392b", Series::Style::line, {}};
  for (int step = 0; step <= 65; ++step) {
    const double eta = step / 100.0;
    henderson.points.emplace_back(eta, gas::henderson(eta));
    if (eta <= 0.5) carnahan.points.emplace_back(eta, gas::carnahan_starling(eta));
  }
  Series disks{"billiards-gas, 400 disks", "#2e86c1", Series::Style::markers, {}};
  Series spheres{"billiards-gas, 500 spheres", "#c0392b", Series::Style::markers, {}};
  bool agrees = true;
  const auto measure = [&](int dimension, std::size_t balls, double eta, Series& series) {
    gas::Options options;
    options.dimension = dimension;
    options.balls = balls;
    options.packing_fraction = eta;
    options.events = events;
    options.equilibrate = 50000;
    options.seed = 1;
    const gas::Result r = gas::measure(options);
    const double expected = gas::equation_of_state(dimension, eta);
    const bool close = std::fabs(r.compressibility_factor - expected) <=
                       0.03 * expected + 5 * r.compressibility_factor_error;
    std::printf(
        "%d-D, eta = %.2f: Z = %.4f +- %.4f (from the collision rate %.4f), equation of state %.4f%s\n",
        dimension, eta, r.compressibility_factor, r.compressibility_factor_error,
        r.compressibility_factor_from_collision_rate, expected, close ? "" : "  <- off");
    agrees = agrees && close;
    series.points.emplace_back(eta, r.compressibility_factor);
  };
  for (const double eta : {0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6}) measure(2, 400, eta, disks);
  for (const double eta : {0.05, 0.1, 0.2, 0.3, 0.4, 0.45}) measure(3, 500, eta, spheres);

  const std::filesystem::path path = std::filesystem::path(out) / "gas_equation_of_state.svg";
  try {
    billiards::io::write_file_atomically(
        path,
        line_plot_svg("Hard disks and spheres: Z = PV/(N kT) against the packing fraction",
                      Axis{"packing fraction η", 0, 0.65, 0.05}, Axis{"Z = PV/(N kT)", 0, 10, 1},
                      {henderson, carnahan, disks, spheres},
                      {"circles: the collision virial over " + std::to_string(events) + " collisions"}));
    std::printf("wrote %s\n", path.c_str());
  } catch (const std::runtime_error& error) {
    std::cerr << "billiards-gas-figure: " << error.what() << "\n";
    return 3;
  }
  if (billiards_support::standard_output_failed("billiards-gas-figure")) return 3;
  if (!agrees) {
    std::cerr << "billiards-gas-figure: a run's Z is off its equation of state by more than 3 % + 5 errors\n";
    return 1;
  }
  return 0;
}
