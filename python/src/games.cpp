// The rules of the games for Python: a game's state in, the rules' decision on a Shot's events and the
// state after it out, as plain Python values (billiards/games.py wraps them).
#include "shots.hpp"

#include <billiards/simulation/games.hpp>

#include <pybind11/stl.h>

#include <string>
#include <vector>

namespace billiards::python {
namespace {

namespace games = simulation::games;

py::dict verdict_dict(const games::Verdict& v) {
  py::dict d;
  py::list fouls;
  for (const games::Foul f : v.fouls) fouls.append(games::foul_name(f));
  d["fouls"] = fouls;
  d["potted"] = v.potted;
  d["respotted"] = v.respotted;
  d["next_player"] = v.next_player;
  d["ball_in_hand"] = static_cast<int>(v.ball_in_hand);
  d["game_over"] = v.game_over;
  d["winner"] = v.winner ? py::cast(*v.winner) : py::none();
  d["reason"] = v.reason;
  d["points"] = v.points;
  d["penalty"] = v.penalty;
  return d;
}

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

template <typename State>
py::dict common_to(const State& s) {
  py::dict d;
  d["on_table"] = std::vector<bool>(s.on_table.begin(), s.on_table.end());
  d["player"] = s.player;
  d["breaking"] = s.breaking;
  d["ball_in_hand"] = static_cast<int>(s.ball_in_hand);
  d["over"] = s.over;
  d["winner"] = s.winner ? py::cast(*s.winner) : py::none();
  return d;
}

py::tuple nine_ball(const std::vector<bool>& on_table, std::size_t player, bool breaking,
                    const std::array<int, 2>& fouls, int ball_in_hand, const PyShot& shot) {
  games::NineBallState s;
  common_from(s, on_table, player, breaking, ball_in_hand);
  s.fouls_in_a_row = fouls;
  const auto d = games::nine_ball(s, shot.shot().events());
  py::dict next = common_to(d.next);
  next["fouls_in_a_row"] = d.next.fouls_in_a_row;
  return py::make_tuple(verdict_dict(d.verdict), next);
}

py::tuple eight_ball(const std::vector<bool>& on_table, std::size_t player, bool breaking,
                     const std::array<int, 2>& groups, int ball_in_hand, const PyShot& shot) {
  games::EightBallState s;
  common_from(s, on_table, player, breaking, ball_in_hand);
  s.groups = {static_cast<games::Group>(groups[0]), static_cast<games::Group>(groups[1])};
  const auto d = games::eight_ball(s, shot.shot().events());
  py::dict next = common_to(d.next);
  next["groups"] = std::array<int, 2>{static_cast<int>(d.next.groups[0]), static_cast<int>(d.next.groups[1])};
  return py::make_tuple(verdict_dict(d.verdict), next);
}

py::tuple three_cushion(const std::array<int, 2>& scores, std::size_t player, int target,
                        const PyShot& shot) {
  games::ThreeCushionState s;
  s.scores = scores;
  s.player = player;
  s.target = target;
  const auto d = games::three_cushion(s, shot.shot().events());
  py::dict next;
  next["scores"] = d.next.scores;
  next["player"] = d.next.player;
  next["target"] = d.next.target;
  next["over"] = d.next.over;
  next["winner"] = d.next.winner ? py::cast(*d.next.winner) : py::none();
  return py::make_tuple(verdict_dict(d.verdict), next);
}

py::tuple snooker(const std::vector<bool>& on_table, std::size_t player, const std::array<int, 2>& scores, int on,
                  int ball_in_hand, const PyShot& shot) {
  games::SnookerState s;
  table_from(s, on_table, player, ball_in_hand);
  s.scores = scores;
  s.on = static_cast<games::SnookerOn>(on);
  const auto d = games::snooker(s, shot.shot().events());
  py::dict next;
  next["on_table"] = std::vector<bool>(d.next.on_table.begin(), d.next.on_table.end());
  next["player"] = d.next.player;
  next["scores"] = d.next.scores;
  next["on"] = static_cast<int>(d.next.on);
  next["ball_in_hand"] = static_cast<int>(d.next.ball_in_hand);
  next["over"] = d.next.over;
  next["winner"] = d.next.winner ? py::cast(*d.next.winner) : py::none();
  return py::make_tuple(verdict_dict(d.verdict), next);
}

}  // namespace

void bind_games(py::module_& m) {
  m.def("snooker", &snooker);
  m.def("nine_ball", &nine_ball);
  m.def("eight_ball", &eight_ball);
  m.def("three_cushion", &three_cushion);
}

}  // namespace billiards::python
