// billiards-gas: the hard-sphere gas of billiards::simulation (billiards/simulation/gas.hpp): N balls of
// diameter 1 and mass 1 at kT = 1 in a periodic box; prints one JSON object with the compressibility
// factor from the collision virial, the mean free time and the checks of energy, momentum and overlap.
//
//   billiards-gas [--dimension 2|3] [--balls N] [--packing-fraction η] [--events E] [--equilibrate E0]
//                 [--seed S] [--json FILE]
//
// Exit status: 0 on success; 2 on a bad command line (one line on stderr naming the argument, its value
// and what was expected, or --balls beyond the memory it can have); 3 when the JSON file or standard
// output cannot be written; 4 when the run stops because the balls' paths do not meet.
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::cerr << "billiards-gas: " << error.what() << " (run with --help for usage)\n";
    return 2;
  }
  std::error_code folder_error;
  if (!json_file.empty() && std::filesystem::is_directory(json_file, folder_error)) {
    std::cerr << "billiards-gas: --json: '" << json_file << "' is a folder, expected a file name\n";
    return 2;
  }
  try {
    billiards::simulation::gas::validate(options);
  } catch (const std::invalid_argument& error) {
    std::cerr << "billiards-gas: " << error.what() << "\n";
    return 2;
  }
  billiards::simulation::gas::Result result;
  try {
    result = billiards::simulation::gas::measure(options);
  } catch (const billiards::simulation::NoCollisions& error) {
    std::cerr << "billiards-gas: " << error.what() << "\n";
    return 4;
  } catch (const std::bad_alloc&) {
    // The gas's arrays grow with --balls (at most 2^31): where the machine cannot hold them, say which
    // argument asked for them, rather than abort on an uncaught std::bad_alloc.
    std::cerr << "billiards-gas: --balls is " << options.balls
              << ": not enough memory for the gas on this machine (std::bad_alloc), expected fewer balls\n";
    return 2;
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
