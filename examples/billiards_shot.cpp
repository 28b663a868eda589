// billiards-shot: a shot on a pool table played from the cue to rest by billiards::simulation::Shot
// (billiards/simulation/shot.hpp); prints the events' count, the time, the pocketed balls and where the
// balls stopped, and writes the events as JSON, the trajectories as CSV, the shot as SVG and an HTML page
// that animates it.
//
//   billiards-shot [--table 7ft|8ft|9ft] [--rack 9ball|8ball] [--jitter J] [--seed S] [--setup FILE]
//                  [--ball N] [--speed V] [--azimuth DEG] [--elevation DEG] [--offset A,B]
//                  [--cue-mass M] [--tip-restitution E] [--event-limit N] [--check-invariants true|false]
//                  [--json FILE] [--svg FILE] [--html FILE] [--trajectories FILE] [--rate HZ]
//
// Exit status: 0 when the shot came to rest; 1 when it did not (more than --event-limit events) or an
// invariant broke; 2 on a bad command line or setup (one line on stderr naming what and why); 3 when an
// output file or standard output cannot be written.
#include <billiards_support/cli_checks.hpp>
#include <billiards_support/standard_output.hpp>
#include "shot_io.hpp"

#include <billiards/simulation/shot.hpp>

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace {

// "A,B": two finite numbers; throws std::invalid_argument naming the option.
std::pair<double, double> parse_offset(const std::string& text) {
  const auto comma = text.find(',');
  const std::string expected = ", expected A,B: the side and up offsets in units of the radius, a^2 + b^2 < 1";
  if (comma == std::string::npos)
    throw std::invalid_argument("--offset: '" + billiards_example::excerpt(text) + "' has no comma" + expected);
  const double a = billiards_example::parse_number(text.substr(0, comma), "--offset: ", "a number");
  const double b = billiards_example::parse_number(text.substr(comma + 1), "--offset: ", "a number");
  if (!(a * a + b * b < 1))
    throw std::invalid_argument("--offset: '" + billiards_example::excerpt(text) + "' is off the ball" + expected);
  return {a, b};
}

}  // namespace

int main(int argc, char** argv) {
  using namespace billiards::simulation;
  using billiards_support::count_at_least, billiards_support::finite_number, billiards_support::path_given;
  CLI::App app{"A shot on a pool table played from the cue to rest, event by event.", "billiards-shot"};
  std::string table_name = "9ft", rack_name = "9ball", setup_file, offset_text = "0,0";
  std::string json_file, svg_file, html_file, trajectories_file;
  double jitter = 0, speed = 8, azimuth = 0, elevation = 0, cue_mass = 0.567, tip_restitution = 1, rate = 100;
  std::uint64_t seed = 0, ball = 0, event_limit = ShotOptions{}.event_limit;
  bool check_invariants = true;
  app.add_option("--table", table_name, "The table: 7ft, 8ft or 9ft (default 9ft)")
      ->check(CLI::IsMember({"7ft", "8ft", "9ft"}));
  auto* rack_option = app.add_option("--rack", rack_name, "The rack: 9ball or 8ball (default 9ball)")
                          ->check(CLI::IsMember({"9ball", "8ball"}));
  app.add_option("--jitter", jitter, "The rack's gaps as a fraction of the radius, in [0, 1] (default 0)")
      ->check(finite_number(false));
  app.add_option("--seed", seed, "The seed of the rack's jitter (default 0)")->check(count_at_least(0));
  app.add_option("--setup", setup_file, "Read the balls (and the table) from FILE (format: examples/README.md)")
      ->check(path_given("a setup file's path"))
      ->excludes(rack_option);
  app.add_option("--ball", ball, "The ball the cue strikes (default 0, the cue ball)")->check(count_at_least(0));
  app.add_option("--speed", speed, "The cue's speed in m/s (default 8)")->check(finite_number(false));
  app.add_option("--azimuth", azimuth, "The cue's direction in degrees from +x, the table's length (default 0)");
  app.add_option("--elevation", elevation, "The cue's elevation in degrees, in [0, 90) (default 0)")
      ->check(finite_number(false));
  app.add_option("--offset", offset_text,
                 "The tip's offsets A,B from the ball's centre in units of the radius: A to the right, B up "
                 "(default 0,0)");
  app.add_option("--cue-mass", cue_mass, "The cue's mass in kg (default 0.567)")->check(finite_number(true));
  app.add_option("--tip-restitution", tip_restitution, "The tip's restitution in [0, 1] (default 1)")
      ->check(finite_number(false));
  app.add_option("--event-limit", event_limit, "Stop with exit status 1 beyond this many events (default 100000)")
      ->check(count_at_least(1));
  app.add_option("--check-invariants", check_invariants,
                 "Check overlaps, the cloth and the energy at every event (default true)");
  app.add_option("--json", json_file, "Write the events as JSON to FILE")->check(path_given("a file's path"));
  app.add_option("--svg", svg_file, "Write the shot as SVG to FILE")->check(path_given("a file's path"));
  app.add_option("--html", html_file, "Write a page that animates the shot to FILE")->check(path_given("a file's path"));
  app.add_option("--trajectories", trajectories_file, "Write the trajectories as CSV to FILE")
      ->check(path_given("a file's path"));
  app.add_option("--rate", rate, "Samples per second of the trajectories and the page (default 100, at most 10000)")
      ->check(finite_number(true));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::cerr << "billiards-shot: " << error.what() << " (run with --help for usage)\n";
    return 2;
  }
  const auto bad = [](const std::string& what) {
    std::cerr << "billiards-shot: " << what << "\n";
    return 2;
  };
  if (!std::isfinite(azimuth)) return bad("--azimuth: " + std::to_string(azimuth) + " is not a finite angle");
  if (!(elevation < 90)) return bad("--elevation: " + std::to_string(elevation) + " is not below 90 degrees");
  if (!(rate <= 10000)) return bad("--rate: " + std::to_string(rate) + " is above 10000 samples per second");
  if (!(jitter <= 1)) return bad("--jitter: " + std::to_string(jitter) + " is above 1, expected [0, 1]");
  for (const std::string* file : {&json_file, &svg_file, &html_file, &trajectories_file}) {
    std::error_code error;
    if (!file->empty() && std::filesystem::is_directory(*file, error))
      return bad("'" + *file + "' is a folder, expected a file name");
  }

  const PoolPhysics physics;
  std::vector<PoolBall> balls;
  std::vector<std::string> origins;
  std::pair<double, double> offset;
  try {
    offset = parse_offset(offset_text);
    if (!setup_file.empty()) {
      billiards_example::ShotSetup setup = billiards_example::read_shot_setup_file(setup_file, physics.radius);
      if (setup.table) table_name = *setup.table;
      balls = std::move(setup.balls);
      origins = std::move(setup.origins);
    }
  } catch (const std::invalid_argument& error) {
    return bad(error.what());
  }
  const PoolTable table = pool_table(table_name);
  if (setup_file.empty()) balls = rack(table, physics, rack_name == "8ball" ? Rack::eight_ball : Rack::nine_ball, jitter, seed);
  if (ball >= balls.size())
    return bad("--ball: " + std::to_string(ball) + " is not a ball, expected 0 to " + std::to_string(balls.size() - 1));

  ShotOptions options;
  options.event_limit = event_limit;
  options.check_invariants = check_invariants;
  std::optional<Shot> shot;
  try {
    shot.emplace(table, physics, balls, options);
  } catch (const std::invalid_argument& error) {
    // Name the setup's line of the ball the table rejects.
    std::string what = error.what();
    if (!origins.empty() && what.rfind("ball ", 0) == 0) {
      const std::size_t index = std::stoul(what.substr(5));
      if (index < origins.size()) what = origins[index] + what;
    } else if (!origins.empty() && what.rfind("balls ", 0) == 0) {
      const std::size_t first = std::stoul(what.substr(6));
      const std::size_t second = std::stoul(what.substr(what.find(" and ") + 5));
      if (second < origins.size()) what = origins[second] + what + " (the other at " + origins[first].substr(0, origins[first].size() - 2) + ")";
    }
    return bad("bad setup: " + what);
  }
  const double degree = M_PI / 180;
  const billiards::Cue<double> cue{cue_mass,          speed,       azimuth * degree, elevation * degree,
                                   offset.first,      offset.second, tip_restitution};
  try {
    shot->strike(ball, cue);
  } catch (const std::invalid_argument& error) {
    return bad(std::string("bad cue: ") + error.what());
  }
  int status = 0;
  try {
    shot->play();
  } catch (const EventLimitReached& error) {
    std::cerr << "billiards-shot: " << error.what() << " (--event-limit)\n";
    status = 1;
  } catch (const BrokenInvariant& error) {
    std::cerr << "billiards-shot: " << error.what() << "\n";
    status = 1;
  }

  const std::vector<PoolBall> rest = shot->balls();
  std::size_t counts[6] = {0, 0, 0, 0, 0, 0};
  for (const ShotEvent& e : shot->events()) ++counts[static_cast<int>(e.kind)];
  std::printf("billiards-shot: %s table, %zu balls, ball %llu struck at %g m/s (azimuth %g, elevation %g degrees, "
              "offset %g,%g)\n",
              table_name.c_str(), rest.size(), static_cast<unsigned long long>(ball), speed, azimuth, elevation,
              offset.first, offset.second);
  std::printf("%s after %.6f s: %zu events (ball %zu, cushion %zu, jaw %zu, pocket %zu, transitions %zu)\n",
              status == 0 ? "at rest" : "stopped", shot->time(), shot->events().size(), counts[1], counts[2],
              counts[3], counts[4], counts[5]);
  std::printf("pocketed:");
  bool any = false;
  for (std::size_t i = 0; i < rest.size(); ++i) {
    if (rest[i].pocketed) {
      std::printf(" %zu", i);
      any = true;
    }
  }
  std::printf("%s\n", any ? "" : " none");
  for (std::size_t i = 0; i < rest.size(); ++i) {
    if (!rest[i].pocketed) std::printf("ball %zu at (%.4f, %.4f)\n", i, rest[i].position.x(), rest[i].position.y());
  }

  const std::string title = "billiards-shot: " + table_name + ", " + std::to_string(rest.size()) + " balls, " +
                            billiards_example::shot_detail::number(speed) + " m/s";
  try {
    if (!json_file.empty()) billiards_example::write_file_atomically(json_file, billiards_example::shot_json(*shot, table_name));
    if (!svg_file.empty()) billiards_example::write_file_atomically(svg_file, billiards_example::shot_svg(*shot, title));
    if (!html_file.empty())
      billiards_example::write_file_atomically(html_file, billiards_example::shot_html(*shot, title, std::min(rate, 120.0)));
    if (!trajectories_file.empty())
      billiards_example::write_file_atomically(trajectories_file, billiards_example::trajectories_csv(*shot, rate));
  } catch (const std::runtime_error& error) {
    std::cerr << "billiards-shot: " << error.what() << "\n";
    return 3;
  }
  for (const std::string* file : {&json_file, &svg_file, &html_file, &trajectories_file}) {
    if (!file->empty()) std::printf("wrote %s\n", file->c_str());
  }
  if (billiards_support::standard_output_failed("billiards-shot")) return 3;
  return status;
}
