// play_shots: a batch of shots, each its own layout and cue, played on a pool of threads without the GIL.
// Each shot is played exactly as a Shot played alone (its own engine, nothing shared but the read-only
// inputs), so the results are the same bits whatever the number of threads and whatever the order.
#include "shots.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace billiards::python {
namespace {

using simulation::PoolPhysics;
using simulation::PoolTable;
using simulation::ShotOptions;

// A shot's failure: whether its input was rejected (ValueError) or the run stopped (the engine's
// exceptions), and the message.
struct Failure {
  enum class Kind { input, event_limit, invariant, other } kind;
  std::string message;
};

struct Batch {
  std::size_t shots = 0, balls = 0;
  const double *position = nullptr, *velocity = nullptr, *angular_velocity = nullptr, *cue = nullptr;
  const bool* pocketed = nullptr;
  const std::int64_t* struck = nullptr;
};

struct Outcome {
  std::vector<double> position, velocity, angular_velocity, time;
  std::vector<std::uint8_t> pocketed;
  std::vector<std::uint64_t> event_count;
  std::vector<std::vector<simulation::ShotEvent>> events;
  std::vector<std::optional<Failure>> failure;
};

void play_one(const PoolTable& table, const PoolPhysics& physics, const ShotOptions& options, const Batch& b,
              std::size_t s, bool keep_events, Outcome& out) {
  const std::size_t offset = s * b.balls;
  try {
    simulation::Shot shot(table, physics,
                          balls_from(b.position + 3 * offset, b.velocity + 3 * offset,
                                     b.angular_velocity + 3 * offset, b.pocketed + offset, b.balls),
                          options);
    if (b.struck[s] < 0)
      throw std::invalid_argument("struck is " + std::to_string(b.struck[s]) + ", expected a ball's index");
    shot.strike(static_cast<std::size_t>(b.struck[s]), cue_from(b.cue + 7 * s));
    shot.play();
    const std::vector<PoolBall> balls = shot.balls();
    for (std::size_t i = 0; i < b.balls; ++i) {
      store_state(balls[i], out.position.data() + 3 * offset, out.velocity.data() + 3 * offset,
                  out.angular_velocity.data() + 3 * offset, i);
      out.pocketed[offset + i] = balls[i].pocketed;
    }
    out.time[s] = shot.time();
    out.event_count[s] = shot.event_count();
    if (keep_events) out.events[s] = shot.events();
  } catch (const std::invalid_argument& e) {
    out.failure[s] = Failure{Failure::Kind::input, e.what()};
  } catch (const simulation::EventLimitReached& e) {
    out.failure[s] = Failure{Failure::Kind::event_limit, e.what()};
  } catch (const simulation::BrokenInvariant& e) {
    out.failure[s] = Failure{Failure::Kind::invariant, e.what()};
  } catch (const std::exception& e) {
    out.failure[s] = Failure{Failure::Kind::other, e.what()};
  }
}

// Raises the failure of the first shot that failed, naming it.
void raise_first_failure(const Outcome& out) {
  const auto failed =
      std::find_if(out.failure.begin(), out.failure.end(), [](const auto& f) { return f.has_value(); });
  if (failed == out.failure.end()) return;
  const std::string message =
      "play_shots: shot " + std::to_string(failed - out.failure.begin()) + ": " + (*failed)->message;
  switch ((*failed)->kind) {
    case Failure::Kind::input: throw py::value_error(message);
    case Failure::Kind::event_limit: throw simulation::EventLimitReached(message);
    case Failure::Kind::invariant: throw simulation::BrokenInvariant(message);
    case Failure::Kind::other: throw std::runtime_error(message);
  }
}

py::dict play_shots(const PoolTable& table, const PoolPhysics& physics, const ShotOptions& options,
                    const Array<double>& position, const Array<double>& velocity,
                    const Array<double>& angular_velocity,
                    const py::array_t<bool, py::array::c_style>& pocketed, const Array<double>& cue,
                    const py::array_t<std::int64_t, py::array::c_style>& struck, std::size_t threads,
                    bool keep_events) {
  if (pocketed.ndim() != 2) throw py::value_error("pocketed must be two-dimensional (shots, balls)");
  Batch b;
  b.shots = static_cast<std::size_t>(pocketed.shape(0));
  b.balls = static_cast<std::size_t>(pocketed.shape(1));
  const auto rows = static_cast<py::ssize_t>(b.shots * b.balls), shots = static_cast<py::ssize_t>(b.shots);
  b.position = rows_of(position, "position", rows, 3);
  b.velocity = rows_of(velocity, "velocity", rows, 3);
  b.angular_velocity = rows_of(angular_velocity, "angular_velocity", rows, 3);
  b.pocketed = pocketed.data();
  b.cue = rows_of(cue, "cue", shots, 7);
  if (struck.ndim() != 1 || struck.shape(0) != shots)
    throw py::value_error("struck must have one value a shot");
  b.struck = struck.data();
  Outcome out;
  out.position.assign(3 * b.shots * b.balls, 0);
  out.velocity = out.angular_velocity = out.position;
  out.pocketed.assign(b.shots * b.balls, 0);
  out.time.assign(b.shots, 0);
  out.event_count.assign(b.shots, 0);
  out.events.resize(keep_events ? b.shots : 0);
  out.failure.resize(b.shots);
  {
    py::gil_scoped_release released;
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
      for (std::size_t s = next++; s < b.shots; s = next++)
        play_one(table, physics, options, b, s, keep_events, out);
    };
    const std::size_t count = std::clamp<std::size_t>(threads, 1, std::max<std::size_t>(b.shots, 1));
    std::vector<std::thread> pool;
    for (std::size_t k = 1; k < count; ++k) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
  }
  raise_first_failure(out);
  const auto copy = [](const auto& v, std::vector<py::ssize_t> shape) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    py::array_t<T> a(shape);
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
  };
  py::dict result;
  const auto n = static_cast<py::ssize_t>(b.balls);
  result["position"] = copy(out.position, {shots, n, 3});
  result["velocity"] = copy(out.velocity, {shots, n, 3});
  result["angular_velocity"] = copy(out.angular_velocity, {shots, n, 3});
  result["pocketed"] = copy(out.pocketed, {shots, n}).attr("astype")("bool");
  result["time"] = copy(out.time, {shots});
  result["event_count"] = copy(out.event_count, {shots});
  if (keep_events) {
    py::list events;
    for (const auto& e : out.events) events.append(event_columns(e));
    result["events"] = events;
  }
  return result;
}

}  // namespace

void bind_batch(py::module_& m) {
  m.def("play_shots", &play_shots, py::arg("table"), py::arg("physics"), py::arg("options"),
        py::arg("position"), py::arg("velocity"), py::arg("angular_velocity"), py::arg("pocketed"),
        py::arg("cue"), py::arg("struck"), py::arg("threads"), py::arg("keep_events"));
}

}  // namespace billiards::python
