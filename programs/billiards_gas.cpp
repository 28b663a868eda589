// billiards-gas: the hard-sphere gas of billiards::simulation (billiards/simulation/gas.hpp): N balls of
// diameter 1 and mass 1 at kT = 1 in a periodic box, or a snapshot's; prints one JSON object with the
// compressibility factor and the pressure from the collision virial, the mean free time, the equation of
// state and the checks of energy, momentum and overlap.
//
//   billiards-gas [--dimension 2|3] [--balls N] [--packing-fraction η] [--events E] [--equilibrate E0]
//                 [--seed S] [--json FILE] [--read SNAPSHOT] [--write SNAPSHOT] [--blocks B]
//                 [--series CSV] [--snapshots XYZ --snapshot-every T] [--method automatic|cells|lists]
//
// --read starts from a snapshot (.sph, or extended XYZ: .xyz or .extxyz; billiards/io/snapshots.hpp)
// instead of the lattice: its dimension, balls and box, each ball's radius and mass, and its velocities
// (or Gaussian ones at kT = 1, --seed, where it has none). --write writes the state at the end as a snapshot,
// each ball's species as it was read. --series writes the measured span's time series, one CSV row a block:
// time, collisions, Z, pressure, kT, mean squared displacement (unwrapped positions), collisions a ball
// a unit of time. --snapshots writes extended XYZ frames every --snapshot-every of the gas's time over
// the measured span, from its start.
//
// Exit status: 0 on success; 2 on a bad command line or a bad snapshot (one line on stderr naming the
// argument or the file and line, its value and what was expected, or --balls beyond the memory it can
// have); 3 when the JSON file, the snapshot or standard output cannot be written; 4 when the run stops
// because the balls' paths do not meet.
#include <billiards/io/gas.hpp>
#include <billiards/io/snapshots.hpp>

#include <billiards/simulation/gas.hpp>
#include <billiards_support/cli_checks.hpp>
#include <billiards_support/standard_output.hpp>

#include <billiards/io/atomic_file.hpp>

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

// The most frames, and particle lines, --snapshots writes over a run.
constexpr std::uint64_t frames_at_most = 100000, frame_lines_at_most = 100000000;

// What the command line asks for.
struct Command {
  billiards::simulation::gas::Options options;
  std::string json_file, read_file, write_file, series_file, snapshots_file, method = "automatic";
};

// Parses the command line into `c`; an exit status where the program ends here (--help, a usage error).
std::optional<int> parse(int argc, char** argv, Command& c) {
  CLI::App app{
      "A hard-sphere gas, event-driven on billiards::runtime: prints Z = PV/(N kT) and its checks as JSON.",
      "billiards-gas"};
  const auto count = [](std::uint64_t smallest) { return billiards_support::count_at_least(smallest); };
  app.add_option("--dimension", c.options.dimension, "2 (disks) or 3 (spheres); default 3")->check(count(0));
  app.add_option("--balls", c.options.balls, "Number of balls N (default 1000)")->check(count(0));
  app.add_option("--packing-fraction", c.options.packing_fraction,
                 "η, the fraction of the volume the balls fill: π ρ σ²/4 (2-D), π ρ σ³/6 (3-D); default 0.3")
      ->check(billiards_support::finite_number(true));
  app.add_option("--events", c.options.events, "Collisions measured (default 100000)")->check(count(1));
  app.add_option("--equilibrate", c.options.equilibrate, "Collisions run first, not measured (default 10000)")
      ->check(count(0));
  app.add_option("--seed", c.options.seed, "Seed of the initial velocities (default 1)")->check(count(0));
  app.add_option("--json", c.json_file, "Write the JSON object to FILE (default: standard output)")
      ->check(billiards_support::path_given("a file's path"));
  CLI::Option* read =
      app.add_option("--read", c.read_file,
                     "Start from the snapshot FILE (.sph, .xyz or .extxyz) instead of the lattice")
          ->check(billiards_support::path_given("a snapshot file's path"));
  app.add_option("--write", c.write_file,
                 "Write the state at the end to the snapshot FILE (.sph, .xyz or .extxyz)")
      ->check(billiards_support::path_given("a snapshot file's path"));
  for (const char* lattice : {"--dimension", "--balls", "--packing-fraction"})
    read->excludes(app.get_option(lattice));
  app.add_option("--blocks", c.options.blocks,
                 "Blocks the measured collisions are cut into, for the errors and the time series (default "
                 "10; at most "
                 "--events)")
      ->check(count(1));
  app.add_option("--series", c.series_file, "Write the time series, one CSV row a block, to FILE")
      ->check(billiards_support::path_given("a file's path"));
  CLI::Option* snapshots =
      app.add_option("--snapshots", c.snapshots_file,
                     "Write extended XYZ frames (.xyz or .extxyz) every --snapshot-every to FILE")
          ->check(billiards_support::path_given("a snapshot file's path"));
  CLI::Option* every = app.add_option("--snapshot-every", c.options.snapshot_interval,
                                      "The gas's time between the frames of --snapshots (positive)")
                           ->check(billiards_support::finite_number(false));
  snapshots->needs(every);
  every->needs(snapshots);
  app.add_option("--method", c.method,
                 "How pairs are found: automatic (default), cells or lists (neighbour lists)")
      ->check(CLI::IsMember({"automatic", "cells", "lists"}));
  if (const std::optional<int> code = billiards_support::parse_command_line(app, argc, argv)) return code;
  c.options.method = c.method == "cells"   ? billiards::simulation::GasMethod::cells
                     : c.method == "lists" ? billiards::simulation::GasMethod::neighbour_lists
                                           : billiards::simulation::GasMethod::automatic;
  return std::nullopt;
}

// The files named, and the snapshot to start from (`start`) or the lattice's options, checked; an exit
// status where they are refused.
std::optional<int> check(Command& c, billiards::io::Snapshot& start) {
  std::error_code folder_error;
  for (const auto& [name, file] : {std::pair<const char*, const std::string&>{"--json", c.json_file},
                                   {"--write", c.write_file},
                                   {"--series", c.series_file},
                                   {"--snapshots", c.snapshots_file}}) {
    if (!file.empty() && std::filesystem::is_directory(file, folder_error)) {
      std::cerr << "billiards-gas: " << name << ": '" << file << "' is a folder, expected a file name\n";
      return 2;
    }
  }
  try {
    if (!c.write_file.empty()) static_cast<void>(billiards::io::is_extended_xyz(c.write_file));
  } catch (const std::invalid_argument& error) {
    std::cerr << "billiards-gas: --write: " << error.what() << "\n";
    return 2;
  }
  try {
    if (!c.snapshots_file.empty() && !billiards::io::is_extended_xyz(c.snapshots_file))
      throw std::invalid_argument(c.snapshots_file +
                                  ": frames are written as extended XYZ, expected .xyz or .extxyz");
  } catch (const std::invalid_argument& error) {
    std::cerr << "billiards-gas: --snapshots: " << error.what() << "\n";
    return 2;
  }

  try {
    if (c.read_file.empty()) {
      billiards::simulation::gas::validate(c.options);
    } else {
      start = billiards::io::read_snapshot_file(c.read_file);
      c.options.dimension = start.dimension;
      c.options.balls = start.particles.size();
    }
  } catch (const std::invalid_argument& error) {
    std::cerr << "billiards-gas: " << (c.read_file.empty() ? "" : "--read: ") << error.what() << "\n";
    return 2;
  }
  if (c.options.dimension == 2 && !c.write_file.empty() && !billiards::io::is_extended_xyz(c.write_file)) {
    std::cerr << "billiards-gas: --write: " << c.write_file
              << ": a .sph snapshot is 3-D, expected .xyz or .extxyz for disks\n";
    return 2;
  }
  return std::nullopt;
}

// The gas of the snapshot or of the lattice, measured; its frames, its state at the end and its series
// written where asked.
template <int D>
billiards::simulation::gas::Result measure(const Command& c, const billiards::io::Snapshot& start) {
  std::optional<billiards::simulation::Gas<D>> gas;
  if (c.read_file.empty()) {
    gas.emplace(billiards::simulation::gas::lattice<D>(c.options), c.options.max_events_without_collision,
                c.options.method);
  } else {
    // The snapshot's own checks name the file and line; the gas's (overlaps, the box's size) the file.
    try {
      const billiards::simulation::GasSetup<D> setup =
          billiards::io::gas_setup<D>(start, c.read_file, c.options.seed);
      gas.emplace(setup, c.options.max_events_without_collision, c.options.method);
    } catch (const std::invalid_argument& error) {
      const std::string what = error.what();
      throw std::invalid_argument(what.rfind(c.read_file, 0) == 0 ? what : c.read_file + ": " + what);
    }
  }
  std::vector<std::string> species;
  for (const billiards::io::SnapshotParticle& p : start.particles) species.push_back(p.species);
  std::optional<billiards::io::AtomicFile> frames;
  if (!c.snapshots_file.empty()) frames.emplace(c.snapshots_file);
  std::uint64_t count = 0, lines = 0;
  const billiards::simulation::gas::Result r =
      billiards::simulation::gas::measure(*gas, c.options, [&](const billiards::simulation::Gas<D>& now) {
        // Every run ends soon after its collisions, and its file fits a disk.
        lines += now.size();
        if (++count > frames_at_most || lines > frame_lines_at_most) {
          std::ostringstream text;
          text << "--snapshot-every is " << c.options.snapshot_interval
               << ": more than 100000 frames or 10^8 particle lines, expected a longer interval";
          throw std::invalid_argument(text.str());
        }
        frames->append(
            billiards::io::extended_xyz_text(billiards::io::snapshot_of(now.setup(), now.time(), species)));
      });
  if (frames) frames->commit();
  if (!c.write_file.empty()) {
    billiards::io::write_snapshot_file(c.write_file,
                                       billiards::io::snapshot_of(gas->setup(), gas->time(), species));
  }
  if (!c.series_file.empty())
    billiards::io::write_file_atomically(c.series_file, billiards::io::series_csv(r));
  return r;
}

// Measures the gas and writes its JSON; the exit status.
int run(const Command& c, const billiards::io::Snapshot& start) {
  billiards::simulation::gas::Result result;
  try {
    result = c.options.dimension == 2 ? measure<2>(c, start) : measure<3>(c, start);
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
    std::cerr << "billiards-gas: --balls is " << c.options.balls
              << ": not enough memory for the gas on this machine (std::bad_alloc), expected fewer balls\n";
    return 2;
  } catch (const std::runtime_error& error) {
    std::cerr << "billiards-gas: " << error.what() << "\n";
    return 3;
  }
  const std::string text = billiards::io::measurement_json(result);
  if (c.json_file.empty()) {
    std::cout << text;
    if (billiards_support::standard_output_failed("billiards-gas")) return 3;
    return 0;
  }
  try {
    billiards::io::write_file_atomically(c.json_file, text);
  } catch (const std::runtime_error& error) {
    std::cerr << "billiards-gas: " << error.what() << "\n";
    return 3;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Command command;
  if (const std::optional<int> code = parse(argc, argv, command)) return *code;
  billiards::io::Snapshot start;
  if (const std::optional<int> code = check(command, start)) return *code;
  return run(command, start);
}
