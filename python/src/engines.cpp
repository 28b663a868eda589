// The shot engine's vocabulary for Python: the table, the physics, the options (plain classes with
// their C++ defaults, picklable for Dask), the presets and layouts, and the Shot itself. The pure-Python
// layer (billiards/_shot.py) wraps Shot with numpy structured arrays and docstrings.
#include "shots.hpp"

#include <billiards/simulation/shot.hpp>

#include <pybind11/stl.h>

#include <mutex>
#include <string>

namespace billiards::python {
namespace {

using simulation::PoolPhysics;
using simulation::PoolTable;
using simulation::ShotOptions;

// A field-by-field __repr__ and pickling for the plain classes.
template <typename Class, typename... Fields>
void plain(py::class_<Class>& c, const char* name, std::pair<const char*, Fields Class::*>... fields) {
  (c.def_readwrite(fields.first, fields.second), ...);
  c.def("__repr__", [name, fields...](const Class& o) {
    std::string text = std::string(name) + "(";
    bool first = true;
    ((text += (first ? "" : ", ") + std::string(fields.first) + "=" +
              py::repr(py::cast(o.*(fields.second))).template cast<std::string>(),
      first = false),
     ...);
    return text + ")";
  });
  c.def(py::pickle([fields...](const Class& o) { return py::make_tuple(py::cast(o.*(fields.second))...); },
                   [fields...](const py::tuple& t) {
                     if (t.size() != sizeof...(Fields))
                       throw std::runtime_error("a pickled object of another version");
                     Class o;
                     std::size_t k = 0;
                     ((o.*(fields.second) = t[k++].template cast<Fields>()), ...);
                     return o;
                   }));
  c.def("__eq__", [fields...](const Class& a, const Class& b) {
    return ((a.*(fields.second) == b.*(fields.second)) && ...);
  });
}

void bind_settings(py::module_& m) {
  py::class_<Cloth<double>> cloth(
      m, "Cloth",
      "The cloth: sliding_friction μ_s, rolling_friction μ_r, spinning_friction μ_sp "
      "(dimensionless) and gravity g (m/s²); pooltool's defaults.");
  cloth.def(py::init([](double sliding, double rolling, double spinning, double gravity) {
              return Cloth<double>{sliding, rolling, spinning, gravity};
            }),
            py::arg("sliding_friction") = 0.2, py::arg("rolling_friction") = 0.01,
            py::arg("spinning_friction") = 0.0127, py::arg("gravity") = 9.81);
  plain(cloth, "Cloth", std::pair{"sliding_friction", &Cloth<double>::sliding_friction},
        std::pair{"rolling_friction", &Cloth<double>::rolling_friction},
        std::pair{"spinning_friction", &Cloth<double>::spinning_friction},
        std::pair{"gravity", &Cloth<double>::gravity});

  py::class_<PoolPhysics> physics(
      m, "PoolPhysics",
      "The physics of a shot: the balls' radius (m) and mass (kg), the cloth, and the "
      "ball–ball and ball–cushion restitution and friction; the defaults and their "
      "sources are in docs/shot.md.");
  const PoolPhysics d;
  physics.def(py::init([](double radius, double mass, const Cloth<double>& cloth, double ball_restitution,
                          double ball_friction, double cushion_restitution, double cushion_friction) {
                return PoolPhysics{radius,           mass,          cloth,
                                   ball_restitution, ball_friction, cushion_restitution,
                                   cushion_friction};
              }),
              py::arg("radius") = d.radius, py::arg("mass") = d.mass, py::arg("cloth") = d.cloth,
              py::arg("ball_restitution") = d.ball_restitution, py::arg("ball_friction") = d.ball_friction,
              py::arg("cushion_restitution") = d.cushion_restitution,
              py::arg("cushion_friction") = d.cushion_friction);
  plain(physics, "PoolPhysics", std::pair{"radius", &PoolPhysics::radius},
        std::pair{"mass", &PoolPhysics::mass}, std::pair{"ball_restitution", &PoolPhysics::ball_restitution},
        std::pair{"ball_friction", &PoolPhysics::ball_friction},
        std::pair{"cushion_restitution", &PoolPhysics::cushion_restitution},
        std::pair{"cushion_friction", &PoolPhysics::cushion_friction});
  // The cloth apart: a nested class is copied in and out (physics.cloth.gravity = … changes a copy).
  physics.def_readwrite("cloth", &PoolPhysics::cloth);
}

void bind_table(py::module_& m) {
  py::class_<PoolTable> table(
      m, "PoolTable",
      "A table (metres): the playing area between the cushions' noses, the pocket mouths, "
      "the nose height, the jaws' radii and the pockets' capture circles, or no pockets "
      "(has_pockets False: a carom table). table_preset(name) gives the presets.");
  const PoolTable d;
  table.def(
      py::init([](double length, double width, double corner_mouth, double side_mouth, double nose_height,
                  double corner_jaw_radius, double side_jaw_radius, double corner_pocket_radius,
                  double corner_pocket_depth, double side_pocket_radius, double side_pocket_depth,
                  bool has_pockets) {
        return PoolTable{length,
                         width,
                         corner_mouth,
                         side_mouth,
                         nose_height,
                         corner_jaw_radius,
                         side_jaw_radius,
                         corner_pocket_radius,
                         corner_pocket_depth,
                         side_pocket_radius,
                         side_pocket_depth,
                         has_pockets};
      }),
      py::arg("length") = d.length, py::arg("width") = d.width, py::arg("corner_mouth") = d.corner_mouth,
      py::arg("side_mouth") = d.side_mouth, py::arg("nose_height") = d.nose_height,
      py::arg("corner_jaw_radius") = d.corner_jaw_radius, py::arg("side_jaw_radius") = d.side_jaw_radius,
      py::arg("corner_pocket_radius") = d.corner_pocket_radius,
      py::arg("corner_pocket_depth") = d.corner_pocket_depth,
      py::arg("side_pocket_radius") = d.side_pocket_radius,
      py::arg("side_pocket_depth") = d.side_pocket_depth, py::arg("has_pockets") = d.has_pockets);
  plain(table, "PoolTable", std::pair{"length", &PoolTable::length}, std::pair{"width", &PoolTable::width},
        std::pair{"corner_mouth", &PoolTable::corner_mouth}, std::pair{"side_mouth", &PoolTable::side_mouth},
        std::pair{"nose_height", &PoolTable::nose_height},
        std::pair{"corner_jaw_radius", &PoolTable::corner_jaw_radius},
        std::pair{"side_jaw_radius", &PoolTable::side_jaw_radius},
        std::pair{"corner_pocket_radius", &PoolTable::corner_pocket_radius},
        std::pair{"corner_pocket_depth", &PoolTable::corner_pocket_depth},
        std::pair{"side_pocket_radius", &PoolTable::side_pocket_radius},
        std::pair{"side_pocket_depth", &PoolTable::side_pocket_depth},
        std::pair{"has_pockets", &PoolTable::has_pockets});
  table.def("foot_spot", [](const PoolTable& t) {
    const auto s = t.foot_spot();
    return py::make_tuple(s.x(), s.y());
  });
  table.def("head_spot", [](const PoolTable& t) {
    const auto s = t.head_spot();
    return py::make_tuple(s.x(), s.y());
  });
  m.def(
      "pool_table", [](const std::string& size) { return simulation::pool_table(size); }, py::arg("size"));
  m.def(
      "table_preset", [](const std::string& name) { return simulation::table_preset(name); }, py::arg("name"));
  m.def(
      "physics_preset", [](const std::string& name) { return simulation::physics_preset(name); },
      py::arg("name"));

  py::class_<ShotOptions> options(
      m, "ShotOptions",
      "How a shot plays: event_limit (EventLimitReached beyond it), pressing_speed "
      "(m/s, the tolerance of sustained contact) and check_invariants (at every event).");
  options.def(py::init([](std::uint64_t event_limit, double pressing_speed, bool check_invariants) {
                ShotOptions o;
                o.event_limit = event_limit;
                o.pressing_speed = pressing_speed;
                o.check_invariants = check_invariants;
                return o;
              }),
              py::arg("event_limit") = ShotOptions{}.event_limit,
              py::arg("pressing_speed") = ShotOptions{}.pressing_speed, py::arg("check_invariants") = false);
  plain(options, "ShotOptions", std::pair{"event_limit", &ShotOptions::event_limit},
        std::pair{"pressing_speed", &ShotOptions::pressing_speed},
        std::pair{"check_invariants", &ShotOptions::check_invariants});
}

void bind_layouts(py::module_& m) {
  m.def(
      "rack",
      [](const PoolTable& table, const PoolPhysics& physics, const std::string& kind, double jitter,
         std::uint64_t seed) {
        if (kind == "snooker") return ball_columns(simulation::snooker_setup(table, physics, jitter, seed));
        if (kind == "3cushion") return ball_columns(simulation::three_cushion_setup(table, physics, seed % 2 ? -1 : 1));
        if (kind != "9ball" && kind != "8ball")
          throw py::value_error("rack: kind is '" + kind + "', expected '9ball', '8ball', 'snooker' or '3cushion'");
        const auto rack = kind == "9ball" ? simulation::Rack::nine_ball : simulation::Rack::eight_ball;
        return ball_columns(simulation::rack(table, physics, rack, jitter, seed));
      },
      py::arg("table"), py::arg("physics"), py::arg("kind"), py::arg("jitter"), py::arg("seed"));
  m.def(
      "scatter",
      [](const PoolTable& table, const PoolPhysics& physics, std::size_t count, std::uint64_t seed) {
        return ball_columns(simulation::scatter(table, physics, count, seed));
      },
      py::arg("table"), py::arg("physics"), py::arg("count"), py::arg("seed"));
  // Placing by hand: the layout's records in, whether it was placed and the balls after out.
  m.def("place_ball", [](const PoolTable& table, const PoolPhysics& physics, const py::array& layout,
                         std::size_t ball, double x, double y, int where) {
    std::vector<PoolBall> balls = balls_from_records(layout);
    if (ball >= balls.size())
      throw py::index_error("place: ball is " + std::to_string(ball) + ", expected 0 to " +
                            std::to_string(balls.size() - 1));
    const bool placed =
        simulation::place_ball(table, physics, balls, ball, {x, y}, static_cast<simulation::Placement>(where));
    return py::make_tuple(placed, ball_columns(balls));
  });
  m.def("place_cue_ball", [](const PoolTable& table, const PoolPhysics& physics, const py::array& layout,
                             std::optional<std::pair<double, double>> wanted, int where) {
    std::vector<PoolBall> balls = balls_from_records(layout);
    std::optional<simulation::TableVector> at;
    if (wanted) at = simulation::TableVector(wanted->first, wanted->second);
    simulation::place_cue_ball(table, physics, balls, at, static_cast<simulation::Placement>(where));
    return ball_columns(balls);
  });
  m.def("respot", [](const PoolTable& table, const PoolPhysics& physics, const py::array& layout,
                     std::size_t ball, bool colour) {
    std::vector<PoolBall> balls = balls_from_records(layout);
    if (ball >= balls.size())
      throw py::index_error("respot: ball is " + std::to_string(ball) + ", expected 0 to " +
                            std::to_string(balls.size() - 1));
    if (colour)
      simulation::respot_colour(table, physics, balls, ball);
    else
      simulation::respot_on_long_string(table, physics, balls, ball);
    return ball_columns(balls);
  });
}

void bind_shot(py::module_& m) {
  py::class_<PyShot>(m, "Shot")
      .def(py::init<const PoolTable&, const PoolPhysics&, const py::array&, const ShotOptions&>())
      .def("strike", &PyShot::strike)
      .def("play", &PyShot::play)
      .def("step", &PyShot::step)
      .def("run_events", &PyShot::run_events)
      .def("run_until", &PyShot::run_until)
      .def("positions_at", &PyShot::positions_at)
      .def("time", [](const PyShot& s) { return s.shot().time(); })
      .def("energy", [](const PyShot& s) { return s.shot().energy(); })
      .def("event_count", [](const PyShot& s) { return s.shot().event_count(); })
      .def("balls", [](const PyShot& s) { return ball_columns(s.shot().balls()); })
      .def("placed", [](const PyShot& s) { return ball_columns(s.shot().placed()); })
      .def("balls_at",
           [](const PyShot& s, double t) {
             if (!(t >= 0) || !std::isfinite(t))
               throw py::value_error("balls_at: t is " + std::to_string(t) +
                                     ", expected a finite time >= 0 (s)");
             return ball_columns(s.shot().balls_at(t));
           })
      .def(
          "events",
          [](const PyShot& s, std::size_t begin) { return event_columns(s.shot().events(), begin); },
          py::arg("begin") = 0);
}

}  // namespace

void bind_engines(py::module_& m) {
  bind_settings(m);
  bind_table(m);
  bind_layouts(m);
  bind_shot(m);
  py::register_exception<simulation::EventLimitReached>(m, "EventLimitReached", PyExc_RuntimeError);
  py::register_exception<simulation::BrokenInvariant>(m, "BrokenInvariant", PyExc_RuntimeError);
}

}  // namespace billiards::python
