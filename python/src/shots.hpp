// What the shot bindings and the batch share: balls and events to and from the columns the pure-Python
// layer turns into numpy structured arrays (billiards/_shot.py), and the cue from its seven numbers.
#pragma once

#include "arrays.hpp"

#include <billiards/shot.hpp>
#include <billiards/simulation/shot.hpp>

#include <cstdint>
#include <cstring>
#include <mutex>
#include <vector>

namespace billiards::python {

using simulation::PoolBall;
using simulation::PoolPhysics;
using simulation::PoolTable;
using simulation::ShotEvent;
using simulation::ShotOptions;

/// The balls of a layout from their columns: positions, velocities and angular velocities (N, 3),
/// pocketed (N,).
[[nodiscard]] inline std::vector<PoolBall> balls_from(const double* position, const double* velocity,
                                                      const double* angular_velocity, const bool* pocketed,
                                                      std::size_t count) {
  std::vector<PoolBall> balls(count);
  for (std::size_t i = 0; i < count; ++i) {
    balls[i].position = Eigen::Map<const Eigen::Vector3d>(position + 3 * i);
    balls[i].velocity = Eigen::Map<const Eigen::Vector3d>(velocity + 3 * i);
    balls[i].angular_velocity = Eigen::Map<const Eigen::Vector3d>(angular_velocity + 3 * i);
    balls[i].pocketed = pocketed[i];
  }
  return balls;
}

/// The balls of a layout from its records (billiards.ball_dtype: position, velocity and angular_velocity
/// as three float64 each, then pocketed as one byte; 73 bytes a ball, packed), checked for that layout.
[[nodiscard]] inline std::vector<PoolBall> balls_from_records(const py::array& records) {
  constexpr py::ssize_t size = 9 * sizeof(double) + 1;
  if (records.ndim() != 1 || records.itemsize() != size || !(records.flags() & py::array::c_style))
    throw py::value_error("balls must be a one-dimensional C-contiguous array of billiards.ball_dtype");
  const auto* bytes = static_cast<const unsigned char*>(records.data());
  std::vector<PoolBall> balls(static_cast<std::size_t>(records.shape(0)));
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const unsigned char* record = bytes + static_cast<std::size_t>(size) * i;
    double values[9];
    std::memcpy(values, record, sizeof values);
    balls[i].position = Eigen::Map<const Eigen::Vector3d>(values);
    balls[i].velocity = Eigen::Map<const Eigen::Vector3d>(values + 3);
    balls[i].angular_velocity = Eigen::Map<const Eigen::Vector3d>(values + 6);
    balls[i].pocketed = record[9 * sizeof(double)] != 0;
  }
  return balls;
}

/// Writes `ball`'s state into row `i` of the columns (whether it is pocketed: the caller's).
inline void store_state(const PoolBall& ball, double* position, double* velocity, double* angular_velocity,
                        std::size_t i) {
  Eigen::Map<Eigen::Vector3d>(position + 3 * i) = ball.position;
  Eigen::Map<Eigen::Vector3d>(velocity + 3 * i) = ball.velocity;
  Eigen::Map<Eigen::Vector3d>(angular_velocity + 3 * i) = ball.angular_velocity;
}

/// The balls' columns: (position, velocity, angular_velocity, pocketed).
[[nodiscard]] inline py::tuple ball_columns(const std::vector<PoolBall>& balls) {
  const auto n = static_cast<py::ssize_t>(balls.size());
  Array<double> position = new_rows<double>(n, 3), velocity = new_rows<double>(n, 3),
                angular_velocity = new_rows<double>(n, 3);
  py::array_t<bool> pocketed(std::vector<py::ssize_t>{n});
  for (std::size_t i = 0; i < balls.size(); ++i) {
    store_state(balls[i], position.mutable_data(), velocity.mutable_data(), angular_velocity.mutable_data(),
                i);
    pocketed.mutable_data()[i] = balls[i].pocketed;
  }
  return py::make_tuple(position, velocity, angular_velocity, pocketed);
}

/// The events' columns: time, kind, first, second, from, to (E,), and the states after of the first
/// and the second body, each as (position, velocity, angular_velocity, pocketed) columns. Kinds and
/// motions are their enumerations' values (ShotEvent::Kind, billiards::Motion).
[[nodiscard]] inline py::tuple event_columns(const std::vector<ShotEvent>& events, std::size_t begin = 0) {
  const std::size_t count = events.size() > begin ? events.size() - begin : 0;
  const auto n = static_cast<py::ssize_t>(count);
  Array<double> time = new_rows<double>(n);
  py::array_t<std::int8_t> kind(std::vector<py::ssize_t>{n}), from(std::vector<py::ssize_t>{n}),
      to(std::vector<py::ssize_t>{n});
  py::array_t<std::int64_t> first(std::vector<py::ssize_t>{n}), second(std::vector<py::ssize_t>{n});
  std::array<Array<double>, 6> states;
  for (auto& s : states) s = new_rows<double>(n, 3);
  std::array<py::array_t<bool>, 2> pocketed{py::array_t<bool>(std::vector<py::ssize_t>{n}),
                                            py::array_t<bool>(std::vector<py::ssize_t>{n})};
  for (std::size_t k = 0; k < count; ++k) {
    const ShotEvent& e = events[begin + k];
    time.mutable_data()[k] = e.time;
    kind.mutable_data()[k] = static_cast<std::int8_t>(e.kind);
    first.mutable_data()[k] = static_cast<std::int64_t>(e.first);
    second.mutable_data()[k] = static_cast<std::int64_t>(e.second);
    from.mutable_data()[k] = static_cast<std::int8_t>(e.from);
    to.mutable_data()[k] = static_cast<std::int8_t>(e.to);
    store_state(e.first_after, states[0].mutable_data(), states[1].mutable_data(), states[2].mutable_data(),
                k);
    store_state(e.second_after, states[3].mutable_data(), states[4].mutable_data(), states[5].mutable_data(),
                k);
    pocketed[0].mutable_data()[k] = e.first_after.pocketed;
    pocketed[1].mutable_data()[k] = e.second_after.pocketed;
  }
  return py::make_tuple(time, kind, first, second, from, to,
                        py::make_tuple(states[0], states[1], states[2], pocketed[0]),
                        py::make_tuple(states[3], states[4], states[5], pocketed[1]));
}

/// The cue from its numbers in the Python layer's order: mass, speed, azimuth, elevation, side_offset,
/// up_offset, tip_restitution.
[[nodiscard]] inline Cue<double> cue_from(const double* c) {
  return {c[0], c[1], c[2], c[3], c[4], c[5], c[6]};
}

// simulation::Shot behind a mutex: the runs release the GIL, and one Shot is played by one thread at a
// time.
class PyShot {
 public:
  PyShot(const PoolTable& table, const PoolPhysics& physics, const py::array& balls,
         const ShotOptions& options)
      : shot_(table, physics, balls_from_records(balls), options) {}
  // A copy of a shot played elsewhere (a game's last shot).
  explicit PyShot(const simulation::Shot& shot) : shot_(shot) {}

  // Runs `run` without the GIL, this Shot locked.
  template <typename Run>
  auto unlocked(Run&& run) {
    py::gil_scoped_release released;
    const std::lock_guard lock(mutex_);
    return run();
  }
  void strike(std::size_t index, double mass, double speed, double azimuth, double elevation,
              double side_offset, double up_offset, double tip_restitution) {
    const std::lock_guard lock(mutex_);
    shot_.strike(index, {mass, speed, azimuth, elevation, side_offset, up_offset, tip_restitution});
  }
  std::uint64_t play() {
    return unlocked([&] { return shot_.play(); });
  }
  bool step() {
    return unlocked([&] { return shot_.step().has_value(); });
  }
  std::uint64_t run_events(std::uint64_t count) {
    return unlocked([&] { return shot_.run_events(count); });
  }
  std::uint64_t run_until(double until) {
    return unlocked([&] { return shot_.run_until(until); });
  }
  // The centres at each of `times` (T,): (T, N, 3).
  Array<double> positions_at(const Array<double>& times) {
    const py::ssize_t count = times.ndim() == 1 ? times.shape(0) : -1;
    const double* t = rows_of(times, "times", count);
    const auto n = static_cast<py::ssize_t>(shot_.placed().size());
    Array<double> out(std::vector<py::ssize_t>{count, n, 3});
    double* o = out.mutable_data();
    for (py::ssize_t k = 0; k < count; ++k) {
      if (!(t[k] >= 0) || !std::isfinite(t[k]))
        throw py::value_error("times[" + std::to_string(k) + "] is " + std::to_string(t[k]) +
                              ", expected a finite time >= 0 (s)");
    }
    py::gil_scoped_release released;
    for (py::ssize_t k = 0; k < count; ++k) {
      const auto balls = shot_.balls_at(t[k]);
      for (py::ssize_t i = 0; i < n; ++i)
        Eigen::Map<Eigen::Vector3d>(o + 3 * (k * n + i)) = balls[static_cast<std::size_t>(i)].position;
    }
    return out;
  }
  [[nodiscard]] const simulation::Shot& shot() const { return shot_; }

 private:
  simulation::Shot shot_;
  std::mutex mutex_;
};

}  // namespace billiards::python
