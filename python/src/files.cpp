// The io library's file formats for Python: a shot's events as JSON, its SVG and animated HTML page and
// its trajectories as CSV (as text, or written atomically), shot setup files, gas snapshots, and
// writing any text file atomically.
#include "shots.hpp"

#include <billiards/io/atomic_file.hpp>
#include <billiards/io/shot.hpp>
#include <billiards/io/snapshots.hpp>

#include <pybind11/stl.h>

#include <string>

namespace billiards::python {
namespace {

py::tuple read_shot_setup(const std::string& path, double radius) {
  const io::ShotSetup setup = io::read_shot_setup_file(path, radius);
  return py::make_tuple(setup.table ? py::cast(*setup.table) : py::none(), ball_columns(setup.balls));
}

// A snapshot's columns: (dimension, box (3,), time, species list, positions (N, 3), velocities (N, 3),
// radii (N,), masses (N,)).
py::tuple snapshot_columns(const io::Snapshot& s) {
  const auto n = static_cast<py::ssize_t>(s.particles.size());
  Array<double> position = new_rows<double>(n, 3), velocity = new_rows<double>(n, 3),
                radius = new_rows<double>(n), mass = new_rows<double>(n);
  py::list species;
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    const io::SnapshotParticle& p = s.particles[i];
    Eigen::Map<Eigen::Vector3d>(position.mutable_data() + 3 * i) = p.position;
    Eigen::Map<Eigen::Vector3d>(velocity.mutable_data() + 3 * i) = p.velocity;
    radius.mutable_data()[i] = p.radius;
    mass.mutable_data()[i] = p.mass;
    species.append(p.species);
  }
  return py::make_tuple(s.dimension, py::make_tuple(s.box.x(), s.box.y(), s.box.z()), s.time, species,
                        position, velocity, radius, mass);
}

void write_snapshot(const std::string& path, int dimension, const Array<double>& box, double time,
                    const std::vector<std::string>& species, const Array<double>& position,
                    const Array<double>& velocity, const Array<double>& radius, const Array<double>& mass) {
  const auto n = static_cast<py::ssize_t>(species.size());
  const double *pb = rows_of(box, "box", 3), *pp = rows_of(position, "position", n, 3),
               *pv = rows_of(velocity, "velocity", n, 3), *pr = rows_of(radius, "radius", n),
               *pm = rows_of(mass, "mass", n);
  io::Snapshot s;
  s.dimension = dimension;
  s.box = Eigen::Map<const Eigen::Vector3d>(pb);
  s.time = time;
  s.particles.resize(species.size());
  for (std::size_t i = 0; i < species.size(); ++i) {
    io::SnapshotParticle& p = s.particles[i];
    p.species = species[i];
    p.position = Eigen::Map<const Eigen::Vector3d>(pp + 3 * i);
    p.velocity = Eigen::Map<const Eigen::Vector3d>(pv + 3 * i);
    p.radius = pr[i];
    p.mass = pm[i];
  }
  io::write_snapshot_file(path, s);
}

}  // namespace

void bind_files(py::module_& m) {
  m.def("shot_json",
        [](const PyShot& s, const std::string& table) { return io::shot_json(s.shot(), table); });
  m.def("shot_svg", [](const PyShot& s, const std::string& title) { return io::shot_svg(s.shot(), title); });
  m.def("shot_html", [](const PyShot& s, const std::string& title, double rate) {
    return io::shot_html(s.shot(), title, rate);
  });
  m.def("trajectories_csv",
        [](const PyShot& s, double rate) { return io::trajectories_csv(s.shot(), rate); });
  m.def("write_file_atomically", [](const std::string& path, const std::string& text) {
    py::gil_scoped_release released;
    io::write_file_atomically(path, text);
  });
  m.def("read_shot_setup", &read_shot_setup);
  m.def("read_snapshot",
        [](const std::string& path) { return snapshot_columns(io::read_snapshot_file(path)); });
  m.def("write_snapshot", &write_snapshot);
}

}  // namespace billiards::python
