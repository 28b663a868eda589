// billiards-gas: the hard-sphere gas of billiards::simulation (billiards/simulation/gas.hpp): N balls of
// diameter 1 and mass 1 at kT = 1 in a periodic box, or a snapshot's; prints one JSON object with the
// compressibility factor and the pressure from the collision virial, the mean free time, the equation of
// state and the checks of energy, momentum and overlap.
//
//   billiards-gas [--dimension 2|3] [--balls N] [--packing-fraction η] [--events E] [--equilibrate E0]
//                 [--seed S] [--json FILE] [--read SNAPSHOT] [--write SNAPSHOT] [--blocks B]
//                 [--series CSV] [--snapshots XYZ --snapshot-every T] [--method automatic|cells|lists]
//
// --read starts from a snapshot (.sph, or extended XYZ: .xyz or .extxyz; see snapshot_io.hpp) instead of
// the lattice: its dimension, balls and box, each ball's radius and mass, and its velocities (or Gaussian
// ones at kT = 1, --seed, where it has none). --write writes the state at the end as a snapshot, each
// ball's species as it was read. --series writes the measured span's time series, one CSV row a block:
// time, collisions, Z, pressure, kT, mean squared displacement (unwrapped positions), collisions a ball
// a unit of time. --snapshots writes extended XYZ frames every --snapshot-every of the gas's time over
// the measured span, from its start.
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
      << "  \"pressure\": " << json_number(r.pressure) << ",\n"
      << "  \"pressure_error\": " << json_number(r.pressure_error) << ",\n"
      << "  \"equation_of_state\": " << json_number(r.equation_of_state) << ",\n"
      << "  \"mean_free_time\": " << json_number(r.mean_free_time) << ",\n"
      << "  \"temperature\": " << json_number(r.temperature) << ",\n"
      << "  \"largest_temperature_change\": " << json_number(r.largest_temperature_change) << ",\n"
      << "  \"momentum\": " << json_number(r.momentum) << ",\n"
      << "  \"largest_overlap\": " << json_number(r.largest_overlap) << ",\n"
      << "  \"largest_gap\": " << json_number(r.largest_gap) << ",\n"
      << "  \"cell_crossings\": " << r.cell_crossings << ",\n"
      << "  \"list_rebuilds\": " << r.list_rebuilds << ",\n"
      << "  \"events_per_second\": " << json_number(r.events_per_second) << "\n"
      << "}\n";
  return out.str();
}

// The most frames, and particle lines, --snapshots writes over a run.
constexpr std::uint64_t frames_at_most = 100000, frame_lines_at_most = 100000000;

// The time series as CSV: a header, then one row a block.
std::string series_csv(const billiards::simulation::gas::Result& r) {
  std::string out =
      "time,collisions,compressibility_factor,pressure,temperature,mean_squared_displacement,collision_rate\n";
  for (const billiards::simulation::gas::Block& b : r.blocks) {
    out += json_number(b.time) + "," + std::to_string(b.collisions) + "," + json_number(b.compressibility_factor) + "," +
           json_number(b.pressure) + "," + json_number(b.temperature) + "," + json_number(b.mean_squared_displacement) +
           "," + json_number(b.collision_rate) + "\n";
  }
  return out;
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
  app.add_option("--blocks", options.blocks,
                 "Blocks the measured collisions are cut into, for the errors and the time series (default 10; at most "
                 "--events)")
      ->check(count(1));
  std::string series_file, snapshots_file;
  app.add_option("--series", series_file, "Write the time series, one CSV row a block, to FILE")
      ->check(billiards_support::path_given("a file's path"));
  CLI::Option* snapshots = app.add_option("--snapshots", snapshots_file,
                                          "Write extended XYZ frames (.xyz or .extxyz) every --snapshot-every to FILE")
                               ->check(billiards_support::path_given("a snapshot file's path"));
  CLI::Option* every = app.add_option("--snapshot-every", options.snapshot_interval,
                                      "The gas's time between the frames of --snapshots (positive)")
                           ->check(billiards_support::finite_number(false));
  snapshots->needs(every);
  every->needs(snapshots);
  std::string method = "automatic";
  app.add_option("--method", method, "How pairs are found: automatic (default), cells or lists (neighbour lists)")
      ->check(CLI::IsMember({"automatic", "cells", "lists"}));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::cerr << "billiards-gas: " << error.what() << " (run with --help for usage)\n";
    return 2;
  }
  std::error_code folder_error;
  options.method = method == "cells"   ? billiards::simulation::GasMethod::cells
                   : method == "lists" ? billiards::simulation::GasMethod::neighbour_lists
                                       : billiards::simulation::GasMethod::automatic;
  for (const auto& [name, file] : {std::pair<const char*, const std::string&>{"--json", json_file},
                                   {"--write", write_file},
                                   {"--series", series_file},
                                   {"--snapshots", snapshots_file}}) {
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
  try {
    if (!snapshots_file.empty() && !billiards_example::is_extended_xyz(snapshots_file))
      throw std::invalid_argument(snapshots_file + ": frames are written as extended XYZ, expected .xyz or .extxyz");
  } catch (const std::invalid_argument& error) {
    std::cerr << "billiards-gas: --snapshots: " << error.what() << "\n";
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
      gas.emplace(billiards::simulation::gas::lattice<D>(options), options.max_events_without_collision, options.method);
    } else {
      // The snapshot's own checks name the file and line; the gas's (overlaps, the box's size) the file.
      try {
        const billiards::simulation::GasSetup<D> setup = billiards_example::gas_setup<D>(start, read_file, options.seed);
        gas.emplace(setup, options.max_events_without_collision, options.method);
      } catch (const std::invalid_argument& error) {
        const std::string what = error.what();
        throw std::invalid_argument(what.rfind(read_file, 0) == 0 ? what : read_file + ": " + what);
      }
    }
    std::vector<std::string> species;
    for (const billiards_example::SnapshotParticle& p : start.particles) species.push_back(p.species);
    std::optional<billiards_support::AtomicFile> frames;
    if (!snapshots_file.empty()) frames.emplace(snapshots_file);
    std::uint64_t count = 0, lines = 0;
    const billiards::simulation::gas::Result r =
        billiards::simulation::gas::measure(*gas, options, [&](const billiards::simulation::Gas<D>& now) {
          // Every run ends soon after its collisions, and its file fits a disk.
          lines += now.size();
          if (++count > frames_at_most || lines > frame_lines_at_most) {
            std::ostringstream text;
            text << "--snapshot-every is " << options.snapshot_interval
                 << ": more than 100000 frames or 10^8 particle lines, expected a longer interval";
            throw std::invalid_argument(text.str());
          }
          frames->append(billiards_example::extended_xyz_text(billiards_example::snapshot_of(now.setup(), now.time(), species)));
        });
    if (frames) frames->commit();
    if (!write_file.empty()) {
      billiards_example::write_snapshot_file(write_file,
                                             billiards_example::snapshot_of(gas->setup(), gas->time(), species));
    }
    if (!series_file.empty()) billiards_support::write_file_atomically(series_file, series_csv(r));
    return r;
  };
  billiards::simulation::gas::Result result;
  try {
    result = options.dimension == 2 ? run.operator()<2>() : run.operator()<3>();
  } catch (const billiards::simulation::EventLimitReached& error) {
    std::cerr << "billiards-gas: " << error.what() << "\n";
    return 4;
  } catch (const std::invalid_argument& error) {
    const std::string what = error.what();
    std::cerr << "billiards-gas: " << (what.rfind("--", 0) == 0 ? "" : "--read: ") << what << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    // The gas's arrays grow with --balls (at most 2^31): where the machine cannot hold them, say which
    // argument asked for them, rather than abort on an uncaught std::bad_alloc.
    std::cerr << "billiards-gas: --balls is " << options.balls
              << ": not enough memory for the gas on this machine (std::bad_alloc), expected fewer balls\n";
    return 2;
  } catch (const std::runtime_error& error) {
    std::cerr << "billiards-gas: " << error.what() << "\n";
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
