// billiards-gas: the hard-sphere gas of billiards::simulation (billiards/simulation/gas.hpp): N balls of
// diameter 1 and mass 1 at kT = 1 in a periodic box; prints one JSON object with the compressibility
// factor from the collision virial, the mean free time and the checks of energy, momentum and overlap.
//
//   billiards-gas [--dimension 2|3] [--balls N] [--packing-fraction η] [--events E] [--equilibrate E0]
//                 [--seed S] [--json FILE] [--read SNAPSHOT] [--write SNAPSHOT]
//
// --read starts from a snapshot (.sph, or extended XYZ: .xyz or .extxyz; see snapshot_io.hpp) instead of
// the lattice: its dimension, balls and box, equal radii and masses, and its velocities (or Gaussian ones
// at kT = 1, --seed, where it has none). --write writes the state at the end as a snapshot.
//
// Exit status: 0 on success; 2 on a bad command line or a bad snapshot (one line on stderr naming the
// argument or the file and line, its value and what was expected, or --balls beyond the memory it can
// have); 3 when the JSON file, the snapshot or standard output cannot be written; 4 when the run stops
// because the balls' paths do not meet.
#include "snapshot_io.hpp"

#include <billiards/simulation/gas.hpp>
#include <billiards_support/cli_checks.hpp>
#include <billiards_support/standard_output.hpp>

#include <billiards_support/atomic_file.hpp>

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <new>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

namespace {

std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

std::string json(const billiards::simulation::gas::Result& r) {
  std::ostringstream out;
  out << "{\n"
      << "  \"dimension\": " << r.dimension << ",\n"
      << "  \"balls\": " << r.balls << ",\n"
      << "  \"packing_fraction\": " << json_number(r.packing_fraction) << ",\n"
      << "  \"collisions\": " << r.collisions << ",\n"
      << "  \"time\": " << json_number(r.time) << ",\n"
      << "  \"compressibility_factor\": " << json_number(r.compressibility_factor) << ",\n"
      << "  \"compressibility_factor_error\": " << json_number(r.compressibility_factor_error) << ",\n"
      << "  \"compressibility_factor_from_collision_rate\": "
      << json_number(r.compressibility_factor_from_collision_rate) << ",\n"
      << "  \"compressibility_factor_from_collision_rate_error\": "
      << json_number(r.compressibility_factor_from_collision_rate_error) << ",\n"
      << "  \"equation_of_state\": "
      << json_number(billiards::simulation::gas::equation_of_state(r.dimension, r.packing_fraction)) << ",\n"
      << "  \"mean_free_time\": " << json_number(r.mean_free_time) << ",\n"
      << "  \"temperature\": " << json_number(r.temperature) << ",\n"
      << "  \"largest_temperature_change\": " << json_number(r.largest_temperature_change) << ",\n"
      << "  \"momentum\": " << json_number(r.momentum) << ",\n"
      << "  \"largest_overlap\": " << json_number(r.largest_overlap) << ",\n"
      << "  \"largest_gap\": " << json_number(r.largest_gap) << ",\n"
      << "  \"cell_crossings\": " << r.cell_crossings << ",\n"
      << "  \"events_per_second\": " << json_number(r.events_per_second) << "\n"
      << "}\n";
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  using billiards::simulation::gas::Options;
  CLI::App app{
      "A hard-sphere gas, event-driven on billiards::runtime: prints Z = PV/(N kT) and its checks as JSON.",
      "billiards-gas"};
  Options options;
  std::string json_file;
  const auto count = [](std::uint64_t smallest) { return billiards_support::count_at_least(smallest); };
  app.add_option("--dimension", options.dimension, "2 (disks) or 3 (spheres); default 3")->check(count(0));
  app.add_option("--balls", options.balls, "Number of balls N (default 1000)")->check(count(0));
  app.add_option("--packing-fraction", options.packing_fraction,
                 "η, the fraction of the volume the balls fill: π ρ σ²/4 (2-D), π ρ σ³/6 (3-D); default 0.3")
      ->check(billiards_support::finite_number(true));
  app.add_option("--events", options.events, "Collisions measured (default 100000)")->check(count(1));
  app.add_option("--equilibrate", options.equilibrate, "Collisions run first, not measured (default 10000)")
      ->check(count(0));
  app.add_option("--seed", options.seed, "Seed of the initial velocities (default 1)")->check(count(0));
  app.add_option("--json", json_file, "Write the JSON object to FILE (default: standard output)")
      ->check(billiards_support::path_given("a file's path"));
  std::string read_file, write_file;
  CLI::Option* read = app.add_option("--read", read_file,
                                     "Start from the snapshot FILE (.sph, .xyz or .extxyz) instead of the lattice")
                          ->check(billiards_support::path_given("a snapshot file's path"));
  app.add_option("--write", write_file, "Write the state at the end to the snapshot FILE (.sph, .xyz or .extxyz)")
      ->check(billiards_support::path_given("a snapshot file's path"));
  for (const char* lattice : {"--dimension", "--balls", "--packing-fraction"}) read->excludes(app.get_option(lattice));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::cerr << "billiards-gas: " << error.what() << " (run with --help for usage)\n";
    return 2;
  }
  std::error_code folder_error;
  for (const auto& [name, file] : {std::pair<const char*, const std::string&>{"--json", json_file}, {"--write", write_file}}) {
    if (!file.empty() && std::filesystem::is_directory(file, folder_error)) {
      std::cerr << "billiards-gas: " << name << ": '" << file << "' is a folder, expected a file name\n";
      return 2;
    }
  }
  try {
    if (!write_file.empty()) static_cast<void>(billiards_example::is_extended_xyz(write_file));
  } catch (const std::invalid_argument& error) {
    std::cerr << "billiards-gas: --write: " << error.what() << "\n";
    return 2;
  }
  billiards_example::Snapshot start;
  try {
    if (read_file.empty()) {
      billiards::simulation::gas::validate(options);
    } else {
      start = billiards_example::read_snapshot_file(read_file);
      options.dimension = start.dimension;
      options.balls = start.particles.size();
    }
  } catch (const std::invalid_argument& error) {
    std::cerr << "billiards-gas: " << (read_file.empty() ? "" : "--read: ") << error.what() << "\n";
    return 2;
  }
  if (options.dimension == 2 && !write_file.empty() && !billiards_example::is_extended_xyz(write_file)) {
    std::cerr << "billiards-gas: --write: " << write_file << ": a .sph snapshot is 3-D, expected .xyz or .extxyz for disks\n";
    return 2;
  }
  // The gas of the snapshot or of the lattice, measured; its state at the end written where asked.
  const auto run = [&]<int D>() {
    std::optional<billiards::simulation::Gas<D>> gas;
    if (read_file.empty()) {
      gas.emplace(billiards::simulation::gas::lattice<D>(options), options.max_events_without_collision);
    } else {
      // The snapshot's own checks name the file and line; the gas's (overlaps, the box's size) the file.
      try {
        const billiards::simulation::GasSetup<D> setup = billiards_example::gas_setup<D>(start, read_file, options.seed);
        gas.emplace(setup, options.max_events_without_collision);
        const double r = setup.radius, ball = D == 2 ? std::numbers::pi * r * r : 4 * std::numbers::pi / 3 * r * r * r;
        options.packing_fraction = static_cast<double>(setup.balls.size()) * ball / std::pow(setup.side, D);
      } catch (const std::invalid_argument& error) {
        const std::string what = error.what();
        throw std::invalid_argument(what.rfind(read_file, 0) == 0 ? what : read_file + ": " + what);
      }
    }
    const billiards::simulation::gas::Result r = billiards::simulation::gas::measure(*gas, options);
    if (!write_file.empty())
      billiards_example::write_snapshot_file(write_file, billiards_example::snapshot_of(gas->setup(), gas->time()));
    return r;
  };
  billiards::simulation::gas::Result result;
  try {
    result = options.dimension == 2 ? run.operator()<2>() : run.operator()<3>();
  } catch (const billiards::simulation::NoCollisions& error) {
    std::cerr << "billiards-gas: " << error.what() << "\n";
    return 4;
  } catch (const std::invalid_argument& error) {
    std::cerr << "billiards-gas: --read: " << error.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    // The gas's arrays grow with --balls (at most 2^31): where the machine cannot hold them, say which
    // argument asked for them, rather than abort on an uncaught std::bad_alloc.
    std::cerr << "billiards-gas: --balls is " << options.balls
              << ": not enough memory for the gas on this machine (std::bad_alloc), expected fewer balls\n";
    return 2;
  } catch (const std::runtime_error& error) {
    std::cerr << "billiards-gas: --write: " << error.what() << "\n";
    return 3;
  }
  const std::string text = json(result);
  if (json_file.empty()) {
    std::cout << text;
    if (billiards_support::standard_output_failed("billiards-gas")) return 3;
    return 0;
  }
  try {
    billiards_support::write_file_atomically(json_file, text);
  } catch (const std::runtime_error& error) {
    std::cerr << "billiards-gas: " << error.what() << "\n";
    return 3;
  }
  return 0;
}
