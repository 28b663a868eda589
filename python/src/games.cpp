// The rules of the games for Python: a game's state in, the rules' decision on a Shot's events and the
// state after it out, as plain Python values (billiards/games.py wraps them).
#include "shots.hpp"

#include <billiards/simulation/games.hpp>

#include <pybind11/numpy.h>

#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace billiards::python {
namespace {

namespace games = simulation::games;

// The balls on the table, whose turn and the cue ball in hand into a game's state.
template <typename State>
void table_from(State& s, const std::vector<bool>& on_table, std::size_t player, int ball_in_hand) {
  if (on_table.size() != s.on_table.size())
    throw py::value_error("on_table has " + std::to_string(on_table.size()) + " balls, expected " +
                          std::to_string(s.on_table.size()));
  std::copy(on_table.begin(), on_table.end(), s.on_table.begin());
  s.player = player;
  s.ball_in_hand = static_cast<games::BallInHand>(ball_in_hand);
}

template <typename State>
void common_from(State& s, const std::vector<bool>& on_table, std::size_t player, bool breaking,
                 int ball_in_hand) {
  table_from(s, on_table, player, ball_in_hand);
  s.breaking = breaking;
}

// A verdict as a tuple in the order of billiards.games.Verdict's fields.
py::tuple verdict_tuple(const games::Verdict& v) {
  py::list fouls;
  for (const games::Foul f : v.fouls) fouls.append(games::foul_name(f));
  static const char* const hands[] = {"none", "anywhere", "behind_head_string", "in_d"};
  return py::make_tuple(fouls, py::cast(v.potted), py::cast(v.respotted), v.next_player,
                        hands[static_cast<int>(v.ball_in_hand)], v.game_over,
                        v.winner ? py::cast(*v.winner) : py::none(), v.reason, v.points, v.penalty);
}

// A game's state as the dict billiards/games.py turns into its dataclass (_state_from).
template <typename State>
py::dict state_dict(const State& s) {
  py::dict d;
  if constexpr (requires { s.on_table; }) {
    d["on_table"] = std::vector<bool>(s.on_table.begin(), s.on_table.end());
    d["ball_in_hand"] = static_cast<int>(s.ball_in_hand);
  }
  if constexpr (requires { s.breaking; }) d["breaking"] = s.breaking;
  if constexpr (requires { s.scores; }) d["scores"] = s.scores;
  if constexpr (std::is_same_v<State, games::NineBallState>) d["fouls_in_a_row"] = s.fouls_in_a_row;
  if constexpr (std::is_same_v<State, games::EightBallState>)
    d["groups"] = std::array<int, 2>{static_cast<int>(s.groups[0]), static_cast<int>(s.groups[1])};
  if constexpr (std::is_same_v<State, games::SnookerState>) d["on"] = static_cast<int>(s.on);
  if constexpr (std::is_same_v<State, games::ThreeCushionState>) d["target"] = s.target;
  d["player"] = s.player;
  d["over"] = s.over;
  d["winner"] = s.winner ? py::cast(*s.winner) : py::none();
  return d;
}

// The rules' decision as the tuple (verdict, state after) billiards/games.py reads.
template <typename State>
py::tuple decision_tuple(const games::Decision<State>& d) {
  return py::make_tuple(verdict_tuple(d.verdict), state_dict(d.next));
}


py::tuple nine_ball(const std::vector<bool>& on_table, std::size_t player, bool breaking,
                    const std::array<int, 2>& fouls, int ball_in_hand, const PyShot& shot) {
  games::NineBallState s;
  common_from(s, on_table, player, breaking, ball_in_hand);
  s.fouls_in_a_row = fouls;
  return decision_tuple(games::nine_ball(s, shot.shot().events()));
}

py::tuple eight_ball(const std::vector<bool>& on_table, std::size_t player, bool breaking,
                     const std::array<int, 2>& groups, int ball_in_hand, const PyShot& shot) {
  games::EightBallState s;
  common_from(s, on_table, player, breaking, ball_in_hand);
  s.groups = {static_cast<games::Group>(groups[0]), static_cast<games::Group>(groups[1])};
  return decision_tuple(games::eight_ball(s, shot.shot().events()));
}

py::tuple three_cushion(const std::array<int, 2>& scores, std::size_t player, int target,
                        const PyShot& shot) {
  games::ThreeCushionState s;
  s.scores = scores;
  s.player = player;
  s.target = target;
  return decision_tuple(games::three_cushion(s, shot.shot().events()));
}

py::tuple snooker(const std::vector<bool>& on_table, std::size_t player, const std::array<int, 2>& scores, int on,
                  int ball_in_hand, const PyShot& shot) {
  games::SnookerState s;
  table_from(s, on_table, player, ball_in_hand);
  s.scores = scores;
  s.on = static_cast<games::SnookerOn>(on);
  return decision_tuple(games::snooker(s, shot.shot().events()));
}

// The observation as billiards.games.GameEnv returns it: the centres (NaN off the table), the balls on
// the table, whose turn, the cue ball in hand, and the game's own (pool: breaking, 8-ball's groups;
// snooker and three-cushion: the scores; snooker: what is on).
py::dict observation(const games::Game& game) {
  const auto& balls = game.balls();
  const auto n = static_cast<py::ssize_t>(balls.size());
  Array<double> positions = new_rows<double>(n, 2);
  py::array_t<bool> on_table(std::vector<py::ssize_t>{n});
  double* p = positions.mutable_data();
  bool* on = on_table.mutable_data();
  for (std::size_t i = 0; i < balls.size(); ++i) {
    on[i] = !balls[i].pocketed;
    p[2 * i] = on[i] ? balls[i].position.x() : std::nan("");
    p[2 * i + 1] = on[i] ? balls[i].position.y() : std::nan("");
  }
  py::dict d;
  d["positions"] = positions;
  d["on_table"] = on_table;
  d["player"] = game.player();
  d["ball_in_hand"] = static_cast<int>(game.ball_in_hand());
  const auto pair = [](int a, int b) {
    py::array_t<std::int64_t> out(std::vector<py::ssize_t>{2});
    out.mutable_data()[0] = a;
    out.mutable_data()[1] = b;
    return out;
  };
  std::visit(
      [&](const auto& s) {
        using State = std::decay_t<decltype(s)>;
        if constexpr (requires { s.breaking; }) d["breaking"] = s.breaking;
        if constexpr (std::is_same_v<State, games::EightBallState>)
          d["groups"] = pair(static_cast<int>(s.groups[0]), static_cast<int>(s.groups[1]));
        if constexpr (requires { s.scores; }) d["scores"] = pair(s.scores[0], s.scores[1]);
        if constexpr (std::is_same_v<State, games::SnookerState>) d["on"] = static_cast<int>(s.on);
      },
      game.state());
  return d;
}

// An action's numbers: speed, azimuth, side and up offsets, and the cue ball's place where given.
std::pair<std::array<double, 4>, std::optional<simulation::TableVector>> action_numbers(const py::object& action,
                                                                                       const std::string& who) {
  const auto refused = [&] {
    return py::value_error(who + ": action is " + py::repr(action).cast<std::string>() +
                           ", expected 4 finite numbers (speed, azimuth, side_offset, up_offset) and optionally "
                           "the cue ball's place x, y");
  };
  std::vector<double> numbers;
  try {
    if (py::isinstance<py::list>(action) || py::isinstance<py::tuple>(action)) {
      for (const py::handle item : action) numbers.push_back(py::float_(py::reinterpret_borrow<py::object>(item)));
    } else {
      const auto flat = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(action);
      if (!flat) throw refused();
      numbers.assign(flat.data(), flat.data() + flat.size());
    }
  } catch (const py::error_already_set&) {
    throw refused();
  } catch (const py::cast_error&) {
    throw refused();
  }
  if (numbers.size() != 4 && numbers.size() != 6) throw refused();
  for (int k = 0; k < 4; ++k)
    if (!std::isfinite(numbers[k])) throw refused();
  std::optional<simulation::TableVector> place;
  if (numbers.size() == 6) place = simulation::TableVector(numbers[4], numbers[5]);
  return {{numbers[0], numbers[1], numbers[2], numbers[3]}, place};
}

void bind_game(py::module_& m) {
  py::class_<games::Game>(m, "Game")
      .def(py::init([](const std::string& kind, const PoolTable& table, const PoolPhysics& physics,
                       const ShotOptions& options, int target) {
        return games::Game(games::game_kind(kind), table, physics, options, target);
      }))
      .def("reset", &games::Game::reset)
      .def("step",
           [](games::Game& game, const py::object& action, const std::string& who) {
             const auto [c, place] = action_numbers(action, who);
             const games::GameStep step = game.step({0.567, c[0], c[1], 0.0, c[2], c[3], 1.0}, place);
             return py::make_tuple(verdict_tuple(step.verdict), step.shooter, step.reward, step.events,
                                   observation(game));
           })
      .def("observation", &observation)
      .def("over", &games::Game::over)
      .def("state",
           [](const games::Game& game) {
             return std::visit([](const auto& s) { return state_dict(s); }, game.state());
           })
      .def("may_meet_first", &games::Game::may_meet_first)
      .def("balls", [](const games::Game& game) { return ball_columns(game.balls()); })
      .def("last_shot", [](const games::Game& game) -> py::object {
        if (!game.last_shot()) return py::none();
        return py::cast(new PyShot(*game.last_shot()), py::return_value_policy::take_ownership);
      });
}

}  // namespace

void bind_games(py::module_& m) {
  bind_game(m);
  m.def("snooker", &snooker);
  m.def("nine_ball", &nine_ball);
  m.def("eight_ball", &eight_ball);
  m.def("three_cushion", &three_cushion);
}

}  // namespace billiards::python
