// billiards-table: the event-driven table of billiards::simulation (billiards/simulation/table.hpp), run for
// a number of ball–ball collisions; prints the relative drift of the kinetic energy and the events per
// second, and can draw the trajectories as SVG.
//
//   billiards-table [--balls N] [--width W] [--height H] [--radius R] [--seed S] [--collisions C]
//                   [--setup FILE | --break] [--svg FILE] [--max-drift X] [--check-every-pair true|false]
//                   [--max-events-without-collision K]
//
// Exit status: 0 on success; 1 when the drift exceeds --max-drift (or is NaN) or two balls overlapped;
// 2 on a bad command line or setup (one line on stderr naming what and why); 3 when the SVG or standard
// output cannot be written; 4 when the run stops because no ball–ball collision can happen (fewer than
// two balls, every ball at rest or too slow for the table, or K events in a row without one).
#include <billiards/io/table.hpp>
#include <billiards_support/cli_checks.hpp>
#include <billiards_support/standard_output.hpp>

#include <billiards/simulation/table.hpp>

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <string>

namespace {

using namespace billiards::simulation;

// What the command line asks for.
struct Options {
  std::size_t balls = 16;
  TableSetup table;
  std::uint64_t seed = 1;
  std::uint64_t collisions = 1000000;
  std::string setup_file, svg_file;
  bool break_shot = false, check_every_pair = true;
  std::optional<double> max_drift;
  std::uint64_t svg_events = 120;
  std::uint64_t max_quiet_events = 1000000;
};

// Parses the command line into `o`; an exit status where the program ends here (--help, a usage error).
std::optional<int> parse(int argc, char** argv, Options& o) {
  using billiards_support::count_at_least, billiards_support::finite_number, billiards_support::path_given;
  CLI::App app{
      "An event-driven billiards table on billiards::runtime: runs C ball-ball collisions and reports "
      "the drift of the kinetic energy.",
      "billiards-table"};
  const CLI::Validator whole_number = count_at_least(0), positive_count = count_at_least(1);
  app.add_option("--balls", o.balls, "Number of balls placed at random (default 16)")->check(positive_count);
  app.add_option("--width", o.table.width, "Table width in metres (default 2.54)")
      ->check(finite_number(true));
  app.add_option("--height", o.table.height, "Table height in metres (default 1.27)")
      ->check(finite_number(true));
  app.add_option("--radius", o.table.radius, "Ball radius in metres (default 0.028575)")
      ->check(finite_number(true));
  app.add_option("--seed", o.seed, "Seed of the random placement (default 1)")->check(whole_number);
  app.add_option("--collisions", o.collisions, "Ball-ball collisions to run (default 1000000)")
      ->check(whole_number);
  auto* setup_option = app.add_option("--setup", o.setup_file,
                                      "Read the table and balls from FILE (format: programs/README.md)")
                           ->check(path_given("a setup file's path"));
  app.add_flag("--break", o.break_shot, "Rack 15 balls and strike the cue ball at the apex")
      ->excludes(setup_option);
  app.add_option("--svg", o.svg_file, "Write the trajectories of the first --svg-events events to FILE")
      ->check(path_given("a file's path"));
  app.add_option("--svg-events", o.svg_events, "Events drawn in the SVG (default 120)")
      ->check(positive_count);
  app.add_option("--max-drift", o.max_drift,
                 "Exit 1 if the relative drift of the kinetic energy exceeds this (or is NaN)")
      ->check(finite_number(false));
  app.add_option(
         "--max-events-without-collision", o.max_quiet_events,
         "Stop (exit 4) after this many events in a row without a ball-ball collision (default 1000000)")
      ->check(positive_count);
  app.add_option("--check-every-pair", o.check_every_pair,
                 "Check every pair for overlap at each event (default true; false: the event's balls only)");
  if (const std::optional<int> code = billiards_support::parse_command_line(app, argc, argv)) return code;

  return std::nullopt;
}

// The setup the options name (a file, the break or balls at random), validated; an exit status where
// there is none to run.
std::optional<int> make_setup(const Options& o, TableSetup& setup) {
  using billiards::io::read_setup_file;
  std::error_code folder_error;
  if (!o.svg_file.empty() && std::filesystem::is_directory(o.svg_file, folder_error)) {
    std::cerr << "billiards-table: --svg: '" << o.svg_file << "' is a folder, expected a file name\n";
    return 2;
  }

  try {
    if (!o.setup_file.empty()) {
      setup = read_setup_file(o.setup_file);
    } else if (o.break_shot) {
      setup = break_setup(o.table);
    } else {
      setup = random_setup(o.table, o.balls, o.seed);
    }
    validate(setup);
  } catch (const std::invalid_argument& error) {
    std::cerr << "billiards-table: bad setup: " << error.what() << "\n";
    return 2;
  }

  if (setup.balls.size() < 2 && o.collisions > 0) {
    std::cerr << "billiards-table: no ball-ball collision can happen with " << setup.balls.size()
              << " ball; --collisions " << o.collisions << " needs at least two\n";
    return 4;
  }

  return std::nullopt;
}

// Runs the table for the collisions asked, draws the SVG and reports; the exit status.
int run(const Options& o, const TableSetup& setup) {
  using billiards::io::Trajectories, billiards::io::write_file_atomically;
  Table simulation(setup, o.check_every_pair);
  Trajectories trajectories(setup);
  const double initial_energy = simulation.energy();
  const auto start = std::chrono::steady_clock::now();
  try {
    for (std::uint64_t quiet = 0; simulation.ball_collisions() < o.collisions;) {
      const std::uint64_t before = simulation.ball_collisions();
      const std::optional<TableEvent> event = simulation.step();
      if (!event) {
        std::cerr << "billiards-table: stopped after " << simulation.ball_collisions() << " of "
                  << o.collisions << " ball-ball collisions: " << simulation.why_no_event() << "\n";
        return 4;
      }
      quiet = simulation.ball_collisions() == before ? quiet + 1 : 0;
      if (quiet >= o.max_quiet_events) {
        std::cerr << "billiards-table: stopped after " << quiet
                  << " events in a row without a ball-ball collision (" << simulation.ball_collisions()
                  << " of " << o.collisions
                  << " done): the balls' paths do not meet (--max-events-without-collision)\n";
        return 4;
      }
      if (!o.svg_file.empty() && simulation.event_count() <= o.svg_events) {
        trajectories.record(*event, simulation.balls());
        if (simulation.event_count() == o.svg_events) trajectories.finish(simulation.balls());
      }
    }
  } catch (const billiards::simulation::BrokenInvariant& error) {
    std::cerr << "billiards-table: " << error.what() << "\n";
    return 1;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double final_energy = simulation.energy();
  // Relative to the initial energy; NaN (which fails any --max-drift) when there was none.
  const double drift = initial_energy > 0 ? std::fabs(final_energy - initial_energy) / initial_energy
                                          : std::numeric_limits<double>::quiet_NaN();

  std::printf("billiards-table: %zu balls on a %g x %g table (radius %g)\n", setup.balls.size(), setup.width,
              setup.height, setup.radius);
  std::printf("events: %llu (ball-ball collisions %llu, cushion %llu) over %.6g s of table time\n",
              static_cast<unsigned long long>(simulation.event_count()),
              static_cast<unsigned long long>(simulation.ball_collisions()),
              static_cast<unsigned long long>(simulation.cushion_collisions()), simulation.time());
  std::printf("kinetic energy: initial %.17g, final %.17g\n", initial_energy, final_energy);
  std::printf("relative drift of the kinetic energy: %.3e\n", drift);
  std::printf("largest overlap at an event: %.3e of a radius (allowed %.0e)\n", simulation.largest_overlap(),
              billiards::simulation::overlap_tolerance);
  std::printf("events per second: %.4g (%.3f s)\n", static_cast<double>(simulation.event_count()) / seconds,
              seconds);

  if (!o.svg_file.empty()) {
    if (simulation.event_count() < o.svg_events) trajectories.finish(simulation.balls());
    try {
      write_file_atomically(o.svg_file, trajectories.svg("billiards-table: the first " +
                                                         std::to_string(o.svg_events) + " events"));
      std::printf("wrote %s\n", o.svg_file.c_str());
    } catch (const std::runtime_error& error) {
      std::cerr << "billiards-table: " << error.what() << "\n";
      return 3;
    }
  }
  if (billiards_support::standard_output_failed("billiards-table")) return 3;
  if (o.max_drift && !(drift <= *o.max_drift)) {  // a NaN drift fails any bound
    std::cerr << "billiards-table: the relative drift " << drift << " exceeds --max-drift " << *o.max_drift
              << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const std::optional<int> code = parse(argc, argv, options)) return *code;
  TableSetup setup;
  if (const std::optional<int> code = make_setup(options, setup)) return *code;
  return run(options, setup);
}
