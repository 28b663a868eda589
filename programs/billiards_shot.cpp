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
#include <billiards/io/shot.hpp>
#include <billiards_support/cli_checks.hpp>
#include <billiards_support/standard_output.hpp>

#include <billiards/simulation/games.hpp>
#include <billiards/simulation/shot.hpp>

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <type_traits>
#include <vector>

namespace {

// "A,B": two finite numbers; throws std::invalid_argument naming the option.
std::pair<double, double> parse_offset(const std::string& text) {
  const auto comma = text.find(',');
  const std::string expected =
      ", expected A,B: the side and up offsets in units of the radius, a^2 + b^2 < 1";
  if (comma == std::string::npos)
    throw std::invalid_argument("--offset: '" + billiards::io::excerpt(text) + "' has no comma" + expected);
  const double a = billiards::io::parse_number(text.substr(0, comma), "--offset: ", "a number");
  const double b = billiards::io::parse_number(text.substr(comma + 1), "--offset: ", "a number");
  if (!(a * a + b * b < 1))
    throw std::invalid_argument("--offset: '" + billiards::io::excerpt(text) + "' is off the ball" +
                                expected);
  return {a, b};
}

using namespace billiards::simulation;

// What the command line asks for.
struct Options {
  std::string table_name = "9ft", rack_name, setup_file, offset_text = "0,0";
  std::string json_file, svg_file, html_file, trajectories_file, game;
  double jitter = 0, speed = 8, azimuth = 0, elevation = 0, cue_mass = 0.567, tip_restitution = 1, rate = 100;
  std::uint64_t seed = 0, ball = 0, event_limit = ShotOptions{}.event_limit;
  bool check_invariants = true;
};

// The balls, and where a setup file placed them, the physics and the cue's offsets.
struct Loaded {
  PoolTable table;  // the table the options or the setup file name
  PoolPhysics physics;
  std::vector<PoolBall> balls;
  std::vector<std::string> origins;  // each ball's "FILE:LINE: " where a setup file placed them
  std::pair<double, double> offset;
};

// A usage error: one line on stderr, exit status 2.
int bad(const std::string& what) {
  std::cerr << "billiards-shot: " << what << "\n";
  return 2;
}

// Parses the command line into `o`; an exit status where the program ends here (--help, a usage error).
std::optional<int> parse(int argc, char** argv, Options& o) {
  using billiards_support::count_at_least, billiards_support::finite_number, billiards_support::path_given;
  CLI::App app{"A shot on a pool table played from the cue to rest, event by event.", "billiards-shot"};
  app.add_option("--table", o.table_name,
                 "The table and its balls: 7ft, 8ft or 9ft (pool), snooker or carom (default 9ft)")
      ->check(CLI::IsMember({"7ft", "8ft", "9ft", "snooker", "carom"}));
  auto* rack_option =
      app.add_option("--rack", o.rack_name,
                     "The starting position: 9ball, 8ball, snooker or 3cushion (default: 9ball on a pool table, "
                     "snooker on the snooker table, 3cushion on the carom table)")
          ->check(CLI::IsMember({"9ball", "8ball", "snooker", "3cushion"}));
  app.add_option("--jitter", o.jitter, "The rack's gaps as a fraction of the radius, in [0, 1] (default 0)")
      ->check(finite_number(false));
  app.add_option("--seed", o.seed, "The seed of the rack's jitter (default 0)")->check(count_at_least(0));
  app.add_option("--setup", o.setup_file,
                 "Read the balls (and the table) from FILE (format: programs/README.md)")
      ->check(path_given("a setup file's path"))
      ->excludes(rack_option);
  app.add_option("--ball", o.ball, "The ball the cue strikes (default 0, the cue ball)")
      ->check(count_at_least(0));
  app.add_option("--speed", o.speed, "The cue's speed in m/s (default 8)")->check(finite_number(false));
  app.add_option("--azimuth", o.azimuth,
                 "The cue's direction in degrees from +x, the table's length (default 0)");
  app.add_option("--elevation", o.elevation, "The cue's elevation in degrees, in [0, 90) (default 0)")
      ->check(finite_number(false));
  app.add_option("--offset", o.offset_text,
                 "The tip's offsets A,B from the ball's centre in units of the radius: A to the right, B up "
                 "(default 0,0)");
  app.add_option("--cue-mass", o.cue_mass, "The cue's mass in kg (default 0.567)")
      ->check(finite_number(true));
  app.add_option("--tip-restitution", o.tip_restitution, "The tip's restitution in [0, 1] (default 1)")
      ->check(finite_number(false));
  app.add_option("--event-limit", o.event_limit,
                 "Stop with exit status 1 beyond this many events (default 100000)")
      ->check(count_at_least(1));
  app.add_option("--check-invariants", o.check_invariants,
                 "Check overlaps, the cloth and the energy at every event (default true)");
  app.add_option("--game", o.game,
                 "Decide the shot by the rules of GAME: 9ball or 8ball (WPA), snooker (WPBSA) or 3cushion (UMB) "
                 "(docs/games.md): a rack's shot is the break, a setup's a shot of the game as it lies; the "
                 "striker is player 0, ball 0")
      ->check(CLI::IsMember({"9ball", "8ball", "snooker", "3cushion"}));
  app.add_option("--json", o.json_file, "Write the events as JSON to FILE")
      ->check(path_given("a file's path"));
  app.add_option("--svg", o.svg_file, "Write the shot as SVG to FILE")->check(path_given("a file's path"));
  app.add_option("--html", o.html_file, "Write a page that animates the shot to FILE")
      ->check(path_given("a file's path"));
  app.add_option("--trajectories", o.trajectories_file, "Write the trajectories as CSV to FILE")
      ->check(path_given("a file's path"));
  app.add_option("--rate", o.rate,
                 "Samples per second of the trajectories and the page (default 100, at most 10000)")
      ->check(finite_number(true));
  if (const std::optional<int> code = billiards_support::parse_command_line(app, argc, argv)) return code;
  if (!std::isfinite(o.azimuth))
    return bad("--azimuth: " + std::to_string(o.azimuth) + " is not a finite angle");
  if (!(o.elevation < 90))
    return bad("--elevation: " + std::to_string(o.elevation) + " is not below 90 degrees");
  if (!(o.rate <= 10000))
    return bad("--rate: " + std::to_string(o.rate) + " is above 10000 samples per second");
  if (!(o.jitter <= 1)) return bad("--jitter: " + std::to_string(o.jitter) + " is above 1, expected [0, 1]");
  for (const std::string* file : {&o.json_file, &o.svg_file, &o.html_file, &o.trajectories_file}) {
    std::error_code error;
    if (!file->empty() && std::filesystem::is_directory(*file, error))
      return bad("'" + *file + "' is a folder, expected a file name");
  }
  return std::nullopt;
}

// The balls the options name (a setup file, which may name the table, or a rack) and the cue's offsets.
std::optional<int> load(Options& o, Loaded& l) {
  try {
    l.offset = parse_offset(o.offset_text);
    if (!o.setup_file.empty()) {
      billiards::io::ShotSetup setup = billiards::io::read_shot_setup_file(o.setup_file, l.physics.radius);
      if (setup.table) o.table_name = *setup.table;
      l.balls = std::move(setup.balls);
      l.origins = std::move(setup.origins);
    }
  } catch (const std::invalid_argument& error) {
    return bad(error.what());
  }
  l.table = table_preset(o.table_name);
  l.physics = physics_preset(o.table_name);
  if (o.rack_name.empty())
    o.rack_name = o.table_name == "snooker" ? "snooker" : o.table_name == "carom" ? "3cushion" : "9ball";
  if (o.setup_file.empty()) {
    try {
      l.balls = o.rack_name == "snooker"    ? snooker_setup(l.table, l.physics, o.jitter, o.seed)
                : o.rack_name == "3cushion" ? three_cushion_setup(l.table, l.physics)
                                            : rack(l.table, l.physics,
                                                   o.rack_name == "8ball" ? Rack::eight_ball : Rack::nine_ball,
                                                   o.jitter, o.seed);
    } catch (const std::invalid_argument& error) {
      return bad("--rack " + o.rack_name + " on the " + o.table_name + " table: " + error.what());
    }
  }
  if (!o.game.empty()) {
    const std::size_t most = o.game == "9ball" ? 10 : o.game == "8ball" ? 16 : o.game == "snooker" ? 22 : 3;
    if (l.balls.size() > most || (o.game == "3cushion" && l.balls.size() != 3))
      return bad("--game " + o.game + ": " + std::to_string(l.balls.size()) + " balls, expected " +
                 (o.game == "3cushion" ? "3 (the white, the yellow and the red)"
                                       : "at most " + std::to_string(most) +
                                             " (the cue ball, 0, and the object balls by number)"));
    if (o.ball != 0)
      return bad("--game " + o.game + ": --ball is " + std::to_string(o.ball) + ", expected 0 (the cue ball)");
  }
  if (o.ball >= l.balls.size())
    return bad("--ball: " + std::to_string(o.ball) + " is not a ball, expected 0 to " +
               std::to_string(l.balls.size() - 1));

  return std::nullopt;
}

// The shot on the table, its ball struck: an exit status where the setup or the cue is refused (the
// setup's line of a ball the table refuses named).
std::optional<int> make_shot(const Options& o, const Loaded& l, std::optional<Shot>& shot) {
  ShotOptions options;
  options.event_limit = o.event_limit;
  options.check_invariants = o.check_invariants;
  try {
    shot.emplace(l.table, l.physics, l.balls, options);
  } catch (const std::invalid_argument& error) {
    // Name the setup's line of the ball the table rejects.
    std::string what = error.what();
    if (!l.origins.empty() && what.rfind("ball ", 0) == 0) {
      const std::size_t index = std::stoul(what.substr(5));
      if (index < l.origins.size()) what = l.origins[index] + what;
    } else if (!l.origins.empty() && what.rfind("balls ", 0) == 0) {
      const std::size_t first = std::stoul(what.substr(6));
      const std::size_t second = std::stoul(what.substr(what.find(" and ") + 5));
      if (second < l.origins.size())
        what = l.origins[second] + what + " (the other at " +
               l.origins[first].substr(0, l.origins[first].size() - 2) + ")";
    }
    return bad("bad setup: " + what);
  }
  const double degree = M_PI / 180;
  const billiards::Cue<double> cue{o.cue_mass,     o.speed,         o.azimuth * degree, o.elevation * degree,
                                   l.offset.first, l.offset.second, o.tip_restitution};
  try {
    shot->strike(o.ball, cue);
  } catch (const std::invalid_argument& error) {
    return bad(std::string("bad cue: ") + error.what());
  }
  return std::nullopt;
}

// Plays the shot to rest: exit status 1 where it stops at the event limit or an invariant breaks.
int play(Shot& shot) {
  int status = 0;
  try {
    shot.play();
  } catch (const EventLimitReached& error) {
    std::cerr << "billiards-shot: " << error.what() << " (--event-limit)\n";
    status = 1;
  } catch (const BrokenInvariant& error) {
    std::cerr << "billiards-shot: " << error.what() << "\n";
    status = 1;
  }

  return status;
}

// The summary on standard output: the events by kind, the pocketed balls, where the others stopped.
void report(const Options& o, const Loaded& l, const Shot& shot, int status) {
  const std::vector<PoolBall> rest = shot.balls();
  std::size_t counts[6] = {0, 0, 0, 0, 0, 0};
  for (const ShotEvent& e : shot.events()) ++counts[static_cast<int>(e.kind)];
  std::printf(
      "billiards-shot: %s table, %zu balls, ball %llu struck at %g m/s (azimuth %g, elevation %g degrees, "
      "offset %g,%g)\n",
      o.table_name.c_str(), rest.size(), static_cast<unsigned long long>(o.ball), o.speed, o.azimuth,
      o.elevation, l.offset.first, l.offset.second);
  std::printf("%s after %.6f s: %zu events (ball %zu, cushion %zu, jaw %zu, pocket %zu, transitions %zu)\n",
              status == 0 ? "at rest" : "stopped", shot.time(), shot.events().size(), counts[1], counts[2],
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
    if (!rest[i].pocketed)
      std::printf("ball %zu at (%.4f, %.4f)\n", i, rest[i].position.x(), rest[i].position.y());
  }
}

// The game's state before the shot: the balls of the layout on the table by number, the break where
// the balls are a rack (snooker: on a red while one is on the table, else on the colours in order).
template <typename State>
State game_before(const Options& o, const std::vector<PoolBall>& placed) {
  State state;
  state.on_table.fill(false);
  for (std::size_t b = 0; b < placed.size(); ++b) state.on_table[b] = !placed[b].pocketed;
  if constexpr (std::is_same_v<State, billiards::simulation::games::SnookerState>)
    state.on = state.reds() > 0 ? games::SnookerOn::red : games::SnookerOn::sequence;
  else
    state.breaking = o.setup_file.empty();
  return state;
}

// The rules' verdict on the shot (--game) and the game's name.
std::pair<billiards::simulation::games::Verdict, const char*> decide(const Options& o, const Shot& shot) {
  using namespace billiards::simulation::games;
  if (o.game == "9ball") return {nine_ball(game_before<NineBallState>(o, shot.placed()), shot.events()).verdict, "9-ball"};
  if (o.game == "8ball")
    return {eight_ball(game_before<EightBallState>(o, shot.placed()), shot.events()).verdict, "8-ball"};
  if (o.game == "snooker")
    return {snooker(game_before<SnookerState>(o, shot.placed()), shot.events()).verdict, "snooker"};
  return {three_cushion(ThreeCushionState{}, shot.events()).verdict, "three-cushion"};
}

// The rules' verdict on the shot, printed after the summary (--game).
void report_game(const Options& o, const Shot& shot) {
  using namespace billiards::simulation::games;
  const auto [v, game] = decide(o, shot);
  std::string fouls;
  for (const Foul f : v.fouls) fouls += std::string(fouls.empty() ? "" : ", ") + foul_name(f);
  std::printf("rules (%s%s): %s\n", game, o.setup_file.empty() ? ", the break" : "",
              v.legal() ? "legal" : ("foul: " + fouls).c_str());
  if (v.points != 0) std::printf("  %d point%s to the shooter\n", v.points, v.points == 1 ? "" : "s");
  if (v.penalty != 0) std::printf("  %d points to the opponent\n", v.penalty);
  std::printf("  %s\n", v.reason.c_str());
  std::printf("  next: %s%s\n", v.game_over ? "the game is over, won by " : "",
              (v.game_over ? (*v.winner == 0 ? "the shooter" : "the opponent")
                           : (v.next_player == 0 ? "the shooter again" : "the opponent")));
  if (v.ball_in_hand != BallInHand::none)
    std::printf("  cue ball in hand %s\n", v.ball_in_hand == BallInHand::anywhere             ? "anywhere"
                                            : v.ball_in_hand == BallInHand::behind_head_string ? "behind the head string"
                                                                                               : "in the D");
  for (const std::size_t b : v.respotted) std::printf("  ball %zu respotted\n", b);
}

// The files asked for; exit status 3 where one cannot be written.
std::optional<int> write_files(const Options& o, const Shot& shot) {
  const std::string title = "billiards-shot: " + o.table_name + ", " + std::to_string(shot.balls().size()) +
                            " balls, " + billiards::io::json_number(o.speed) + " m/s";
  try {
    if (!o.json_file.empty())
      billiards::io::write_file_atomically(o.json_file, billiards::io::shot_json(shot, o.table_name));
    if (!o.svg_file.empty())
      billiards::io::write_file_atomically(o.svg_file, billiards::io::shot_svg(shot, title));
    if (!o.html_file.empty())
      billiards::io::write_file_atomically(o.html_file,
                                           billiards::io::shot_html(shot, title, std::min(o.rate, 120.0)));
    if (!o.trajectories_file.empty())
      billiards::io::write_file_atomically(o.trajectories_file,
                                           billiards::io::trajectories_csv(shot, o.rate));
  } catch (const std::runtime_error& error) {
    std::cerr << "billiards-shot: " << error.what() << "\n";
    return 3;
  }
  for (const std::string* file : {&o.json_file, &o.svg_file, &o.html_file, &o.trajectories_file}) {
    if (!file->empty()) std::printf("wrote %s\n", file->c_str());
  }
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const std::optional<int> code = parse(argc, argv, options)) return *code;
  Loaded loaded;
  if (const std::optional<int> code = load(options, loaded)) return *code;
  std::optional<Shot> shot;
  if (const std::optional<int> code = make_shot(options, loaded, shot)) return *code;
  const int status = play(*shot);
  report(options, loaded, *shot, status);
  if (!options.game.empty() && status == 0) report_game(options, *shot);
  if (const std::optional<int> code = write_files(options, *shot)) return *code;
  if (billiards_support::standard_output_failed("billiards-shot")) return 3;
  return status;
}
