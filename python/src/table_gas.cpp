// The event-driven table and the hard-sphere gas for Python, in the engines' vocabulary (step, run_events,
// run_until, time, energy, balls): their balls as arrays in and out, their events as columns that the
// pure-Python layer (billiards/_table_gas.py) turns into structured arrays.
#include "arrays.hpp"

#include <billiards/simulation/gas.hpp>
#include <billiards/simulation/table.hpp>

#include <pybind11/stl.h>

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace billiards::python {
namespace {

using simulation::Ball;

template <int D>
std::vector<Ball<D>> balls_from(const Array<double>& position, const Array<double>& velocity) {
  const py::ssize_t count = position.ndim() == 2 ? position.shape(0) : -1;
  const double *p = rows_of(position, "position", count, D), *v = rows_of(velocity, "velocity", count, D);
  std::vector<Ball<D>> balls(static_cast<std::size_t>(count));
  for (std::size_t i = 0; i < balls.size(); ++i) {
    balls[i].position = Eigen::Map<const Eigen::Matrix<double, D, 1>>(p + D * i);
    balls[i].velocity = Eigen::Map<const Eigen::Matrix<double, D, 1>>(v + D * i);
  }
  return balls;
}

template <int D>
Array<double> rows(const std::vector<Eigen::Matrix<double, D, 1>>& vectors) {
  Array<double> out = new_rows<double>(static_cast<py::ssize_t>(vectors.size()), D);
  for (std::size_t i = 0; i < vectors.size(); ++i)
    Eigen::Map<Eigen::Matrix<double, D, 1>>(out.mutable_data() + D * i) = vectors[i];
  return out;
}

// Events as they happen, kept as columns: time, kind (0 ball, 1 cushion), first, second, resolved.
struct EventLog {
  std::vector<double> time;
  std::vector<std::int8_t> kind;
  std::vector<std::int64_t> first, second;
  std::vector<std::uint8_t> resolved;
  void add(double t, int k, std::size_t a, std::size_t b, bool r) {
    time.push_back(t);
    kind.push_back(static_cast<std::int8_t>(k));
    first.push_back(static_cast<std::int64_t>(a));
    second.push_back(static_cast<std::int64_t>(b));
    resolved.push_back(r);
  }
  py::tuple columns() const {
    const auto copy = [](const auto& v) {
      py::array_t<typename std::decay_t<decltype(v)>::value_type> a(static_cast<py::ssize_t>(v.size()));
      std::copy(v.begin(), v.end(), a.mutable_data());
      return a;
    };
    return py::make_tuple(copy(time), copy(kind), copy(first), copy(second), copy(resolved));
  }
};

// Runs `engine` (locked, without the GIL) for at most `count` events, or every event up to `until` where
// it is finite; returns the count and, where `keep`, the events' columns (`add` logs one).
template <typename Engine, typename Add>
py::tuple run_engine(Engine& engine, std::mutex& mutex, std::uint64_t count, double until, bool keep,
                     Add add) {
  EventLog log;
  std::uint64_t done = 0;
  {
    py::gil_scoped_release released;
    const std::lock_guard lock(mutex);
    const auto note = [&](const auto& e) {
      if (keep) add(log, e);
    };
    done = std::isinf(until) ? engine.run_events(count, note) : engine.run_until(until, note);
  }
  return py::make_tuple(done, keep ? py::object(log.columns()) : py::none());
}

class PyTable {
 public:
  PyTable(const Array<double>& position, const Array<double>& velocity, double width, double height,
          double radius, double mass, bool check_every_pair)
      : table_(setup(position, velocity, width, height, radius, mass), check_every_pair) {}
  // Runs at most `count` events (until: +∞) or every event up to `until`; returns the count and, where
  // asked, the events' columns.
  py::tuple run(std::uint64_t count, double until, bool keep) {
    return run_engine(table_, mutex_, count, until, keep, [](EventLog& log, const simulation::TableEvent& e) {
      log.add(e.time, static_cast<int>(e.kind), e.first, e.second, e.resolved);
    });
  }
  [[nodiscard]] const simulation::Table& table() const { return table_; }

 private:
  static simulation::TableSetup setup(const Array<double>& position, const Array<double>& velocity,
                                      double width, double height, double radius, double mass) {
    simulation::TableSetup s;
    s.width = width;
    s.height = height;
    s.radius = radius;
    s.mass = mass;
    s.balls = balls_from<2>(position, velocity);
    return s;
  }
  simulation::Table table_;
  std::mutex mutex_;
};

template <int D>
class PyGas {
 public:
  PyGas(const Array<double>& position, const Array<double>& velocity, double side, double radius, double mass,
        const std::vector<double>& radii, const std::vector<double>& masses, std::uint64_t limit)
      : gas_(setup(position, velocity, side, radius, mass, radii, masses), limit) {}
  explicit PyGas(const simulation::GasSetup<D>& s) : gas_(s) {}
  py::tuple run(std::uint64_t count, double until, bool keep) {
    return run_engine(gas_, mutex_, count, until, keep, [](EventLog& log, const simulation::GasEvent& e) {
      log.add(e.time, 0, e.first, e.second, true);
    });
  }
  simulation::Gas<D>& gas() { return gas_; }

 private:
  static simulation::GasSetup<D> setup(const Array<double>& position, const Array<double>& velocity,
                                       double side, double radius, double mass,
                                       const std::vector<double>& radii, const std::vector<double>& masses) {
    simulation::GasSetup<D> s;
    s.side = side;
    s.radius = radius;
    s.mass = mass;
    s.balls = balls_from<D>(position, velocity);
    s.radii = radii;
    s.masses = masses;
    return s;
  }
  simulation::Gas<D> gas_;
  std::mutex mutex_;
};

void bind_table(py::module_& m) {
  py::class_<PyTable>(m, "Table")
      .def(py::init<const Array<double>&, const Array<double>&, double, double, double, double, bool>())
      .def("run", &PyTable::run)
      .def("time", [](const PyTable& t) { return t.table().time(); })
      .def("energy", [](const PyTable& t) { return t.table().energy(); })
      .def("event_count", [](const PyTable& t) { return t.table().event_count(); })
      .def("largest_overlap", [](const PyTable& t) { return t.table().largest_overlap(); })
      .def("balls", [](const PyTable& t) {
        std::vector<Eigen::Vector2d> p, v;
        for (const auto& b : t.table().balls()) {
          p.push_back(b.position);
          v.push_back(b.velocity);
        }
        return py::make_tuple(rows<2>(p), rows<2>(v));
      });
}

template <int D>
void bind_gas(py::module_& m, const char* name) {
  using G = PyGas<D>;
  py::class_<G>(m, name)
      .def(py::init<const Array<double>&, const Array<double>&, double, double, double,
                    const std::vector<double>&, const std::vector<double>&, std::uint64_t>())
      .def_static("lattice",
                  [](std::size_t balls, double packing_fraction, std::uint64_t seed) {
                    simulation::gas::Options o;
                    o.dimension = D;
                    o.balls = balls;
                    o.packing_fraction = packing_fraction;
                    o.seed = seed;
                    return std::make_unique<G>(simulation::gas::lattice<D>(o));
                  })
      .def("run", &G::run)
      .def("time", [](G& g) { return g.gas().time(); })
      .def("energy", [](G& g) { return g.gas().energy(); })
      .def("temperature", [](G& g) { return g.gas().temperature(); })
      .def("collisions", [](G& g) { return g.gas().collisions(); })
      .def("side", [](G& g) { return g.gas().side(); })
      .def("radii", [](G& g) { return g.gas().radii(); })
      .def("masses", [](G& g) { return g.gas().masses(); })
      .def("positions", [](G& g) { return rows<D>(g.gas().positions()); })
      .def("unwrapped_positions", [](G& g) { return rows<D>(g.gas().unwrapped_positions()); })
      .def("velocities", [](G& g) { return rows<D>(g.gas().velocities()); })
      .def("reset_measurements", [](G& g) { g.gas().reset_measurements(); })
      .def("measured", [](G& g) {
        const simulation::GasMeasurement r = g.gas().measured();
        py::dict d;
        d["time"] = r.time;
        d["collisions"] = r.collisions;
        d["virial"] = r.virial;
        d["temperature"] = r.temperature;
        d["compressibility_factor"] = r.compressibility_factor;
        d["compressibility_factor_from_collision_rate"] = r.compressibility_factor_from_collision_rate;
        d["mean_free_time"] = r.mean_free_time;
        return d;
      });
}

}  // namespace

void bind_table_and_gas(py::module_& m) {
  bind_table(m);
  bind_gas<2>(m, "Gas2");
  bind_gas<3>(m, "Gas3");
}

}  // namespace billiards::python
