/// \file
/// Snapshots of spheres or disks in a periodic box, read and written in two formats.
///
/// .sph, the format of Smallenburg's event-driven code and of the Colloid Visualization Tool, one line a
/// particle: its type (one character), centre and radius. It holds no velocities and no masses: read,
/// every velocity is 0 and every mass 1. Always 3-D (a 2-D snapshot goes in extended XYZ).
/// \verbatim
///     N
///     Lx Ly Lz
///     a x y z r
/// \endverbatim
///
/// Extended XYZ, which OVITO reads (one frame; a file of several frames is read up to its first).
/// Properties names the columns (name:type:count); species and pos are required, velo, radius and mass
/// optional (0, 0.5 and 1 where absent), and any other column is skipped. `pbc="T T F"` makes the
/// snapshot 2-D (every z then 0; the lattice's third side is the cell's thickness, not a period). The
/// box must be orthogonal (a diagonal Lattice).
/// \code{.unparsed}
///     N
///     Lattice="Lx 0 0 0 Ly 0 0 0 Lz" Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1:mass:R:1 Time=t pbc="T T T"
///     a x y z vx vy vz r m
/// \endcode
///
/// A bad file gets one line naming the file, the line and what was expected (std::invalid_argument).
/// gas_setup and snapshot_of convert to and from the gas of billiards/simulation/gas.hpp, which runs
/// equal spheres (or disks) in a square or cubic box.
/// Written numbers keep every digit (%.17g): a snapshot read back is the snapshot written.
#pragma once

#include <billiards/io/json.hpp>
#include <billiards/io/table.hpp>

#include <billiards/simulation/gas.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <istream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace billiards::io {

/// One particle of a snapshot.
struct SnapshotParticle {
  std::string species = "a";                                ///< its type: no spaces; one character in .sph
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< its centre (z = 0 in 2-D)
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< its velocity (z = 0 in 2-D)
  double radius = 0.5;                                      ///< positive
  double mass = 1;                                          ///< positive
};

/// A configuration in an orthogonal periodic box.
struct Snapshot {
  int dimension = 3;                                  ///< 2 (disks: x and y periodic) or 3
  Eigen::Vector3d box = Eigen::Vector3d::Ones();  ///< the box's sides (in 2-D the third is a thickness)
  double time = 0;                                    ///< the time the state is at
  std::vector<SnapshotParticle> particles;            ///< the particles, in the file's order
};

/// The most particles a snapshot file may declare: the gas's own limit.
inline constexpr std::size_t largest_snapshot = std::size_t(1) << 31;

namespace snapshot_detail {

/// One line of a snapshot file, at most longest_setup_line characters; false at the end of the file.
inline bool read_line(std::istream& in, std::string& line, const std::string& where) {
  const bool ended = read_bounded_line(in, line, where, "one particle a line");
  return ended || !line.empty();
}

inline std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string word; in >> word;) out.push_back(word);
  return out;
}

inline std::string where(const std::string& source, std::size_t line) {
  return source + ":" + std::to_string(line) + ": ";
}

/// The particle count of a snapshot's first line: a whole number from 1 to largest_snapshot.
inline std::size_t count(const std::string& line, const std::string& at) {
  const std::vector<std::string> w = words(line);
  std::size_t used = 0;
  unsigned long long n = 0;
  bool whole = w.size() == 1 && !w[0].empty() && std::isdigit(static_cast<unsigned char>(w[0][0]));
  if (whole) {
    try {
      n = std::stoull(w[0], &used);
    } catch (const std::exception&) {
      whole = false;
    }
  }
  if (!whole || used != w[0].size() || n < 1 || n > largest_snapshot) {
    throw std::invalid_argument(at + "'" + excerpt(line) + "' is not a particle count, expected a whole number from 1 to " +
                                std::to_string(largest_snapshot));
  }
  return static_cast<std::size_t>(n);
}

/// The particle count on a snapshot's first line (count), read from `in`.
inline std::size_t first_line(std::istream& in, std::string& line, const std::string& source) {
  if (!read_line(in, line, where(source, 1)))
    throw std::invalid_argument(where(source, 1) + "the file is empty, expected the particle count");
  return count(line, where(source, 1));
}

inline double positive(const std::string& word, const std::string& at, const char* what) {
  const double value = parse_number(word, at, what);
  if (!(value > 0)) throw std::invalid_argument(at + what + " is " + word + ", expected a positive number");
  return value;
}

/// The particles' lines: `count` of them from line `first` on, each handed to `particle(where, line, words)`.
template <typename Particle>
void read_particles(std::istream& in, const std::string& source, std::size_t first, std::size_t count,
                    Particle particle) {
  std::string line;
  for (std::size_t i = 0; i < count; ++i) {
    const std::string at = where(source, first + i);
    if (!read_line(in, line, at)) {
      throw std::invalid_argument(at + "the file ends after " + std::to_string(i) + " particles, expected " +
                                  std::to_string(count));
    }
    particle(at, line, words(line));
  }
}

/// Throws std::invalid_argument where particle i's species cannot be written: empty, with a space, or
/// (in .sph) longer than one character.
inline void check_species(const std::string& species, std::size_t i, bool one_character) {
  const bool spaces = std::any_of(species.begin(), species.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; });
  if (species.empty() || spaces || (one_character && species.size() != 1)) {
    throw std::invalid_argument("particle " + std::to_string(i) + "'s species is '" + excerpt(species) + "', expected " +
                                (one_character ? "one character that is not a space (.sph)" : "a name without spaces"));
  }
}

/// A quoted or plain value of an extended XYZ comment line's key=value pairs, lower-case keys.
inline std::vector<std::pair<std::string, std::string>> key_values(const std::string& line, const std::string& at) {
  std::vector<std::pair<std::string, std::string>> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i == line.size()) break;
    const std::size_t key_start = i;
    while (i < line.size() && line[i] != '=' && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    std::string key = line.substr(key_start, i - key_start);
    for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    std::string value;
    if (i < line.size() && line[i] == '=') {
      ++i;
      if (i < line.size() && line[i] == '"') {
        const std::size_t close = line.find('"', i + 1);
        if (close == std::string::npos)
          throw std::invalid_argument(at + key + "'s value has no closing quote, expected key=\"value\"");
        value = line.substr(i + 1, close - i - 1);
        i = close + 1;
      } else {
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        value = line.substr(start, i - start);
      }
    }
    out.emplace_back(key, value);
  }
  return out;
}

}  // namespace snapshot_detail

/// Reads a .sph snapshot (the format above) from `in`; `source` names it in messages.
inline Snapshot read_sph(std::istream& in, const std::string& source) {
  using namespace snapshot_detail;
  Snapshot s;
  std::string line;
  const std::size_t n = first_line(in, line, source);
  if (!read_line(in, line, where(source, 2)))
    throw std::invalid_argument(where(source, 2) + "the file ends, expected the box's sides 'Lx Ly Lz'");
  const std::vector<std::string> box = words(line);
  if (box.size() != 3)
    throw std::invalid_argument(where(source, 2) + std::to_string(box.size()) +
                                " numbers, expected the box's three sides 'Lx Ly Lz'");
  for (int k = 0; k < 3; ++k) s.box[k] = positive(box[static_cast<std::size_t>(k)], where(source, 2), "the box's side");
  s.particles.reserve(std::min<std::size_t>(n, std::size_t(1) << 20));
  read_particles(in, source, 3, n, [&](const std::string& at, const std::string& text, const std::vector<std::string>& w) {
    if (w.size() != 5 || w[0].size() != 1)
      throw std::invalid_argument(at + "'" + excerpt(text) + "', expected 'type x y z radius', the type one character");
    SnapshotParticle p;
    p.species = w[0];
    for (int k = 0; k < 3; ++k)
      p.position[k] = parse_number(w[static_cast<std::size_t>(k) + 1], at, "a coordinate");
    p.radius = positive(w[4], at, "the radius");
    s.particles.push_back(p);
  });
  std::size_t extra = 3 + n;
  while (read_line(in, line, where(source, extra))) {
    if (!words(line).empty())
      throw std::invalid_argument(where(source, extra) + "a line after the " + std::to_string(n) +
                                  " particles the first line declares, expected the end of the file");
    ++extra;
  }
  return s;
}

/// Reads the first frame of an extended XYZ file (the format above) from `in`.
inline Snapshot read_extended_xyz(std::istream& in, const std::string& source) {
  using namespace snapshot_detail;
  Snapshot s;
  std::string line;
  const std::size_t n = first_line(in, line, source);
  const std::string at = where(source, 2);
  if (!read_line(in, line, at)) throw std::invalid_argument(at + "the file ends, expected the comment line with Lattice=\"…\"");
  bool lattice = false;
  std::string properties = "species:S:1:pos:R:3";
  for (const auto& [key, value] : key_values(line, at)) {
    if (key == "lattice") {
      const std::vector<std::string> v = words(value);
      if (v.size() != 9) throw std::invalid_argument(at + "Lattice has " + std::to_string(v.size()) + " numbers, expected 9");
      for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column) {
          const double x = parse_number(v[static_cast<std::size_t>(3 * row + column)], at + "Lattice: ", "a number");
          if (row == column) {
            if (!(x > 0)) throw std::invalid_argument(at + "Lattice's side " + std::to_string(row + 1) + " is " + v[static_cast<std::size_t>(3 * row + column)] + ", expected a positive length");
            s.box[row] = x;
          } else if (x != 0) {
            throw std::invalid_argument(at + "Lattice=\"" + excerpt(value) + "\" is not diagonal, expected an orthogonal box");
          }
        }
      }
      lattice = true;
    } else if (key == "properties") {
      properties = value;
    } else if (key == "time") {
      s.time = parse_number(value, at + "Time: ", "a time");
    } else if (key == "pbc") {
      const std::vector<std::string> v = words(value);
      if (v == std::vector<std::string>{"T", "T", "T"}) {
        s.dimension = 3;
      } else if (v == std::vector<std::string>{"T", "T", "F"}) {
        s.dimension = 2;
      } else {
        throw std::invalid_argument(at + "pbc=\"" + excerpt(value) + "\", expected \"T T T\" (3-D) or \"T T F\" (2-D)");
      }
    }
  }
  if (!lattice) throw std::invalid_argument(at + "no Lattice=\"…\", expected the box as Lattice=\"Lx 0 0 0 Ly 0 0 0 Lz\"");
  // The columns: where each property starts, and how many words a line has.
  struct Column {
    std::string name;
    std::size_t start = 0, count = 0;
  };
  std::vector<Column> columns;
  std::size_t width = 0;
  {
    std::vector<std::string> fields;
    std::string field;
    std::istringstream parts(properties);
    while (std::getline(parts, field, ':')) fields.push_back(field);
    if (fields.size() % 3 != 0 || fields.empty())
      throw std::invalid_argument(at + "Properties=" + excerpt(properties) + ", expected name:type:count triples");
    for (std::size_t k = 0; k < fields.size(); k += 3) {
      std::size_t used = 0;
      unsigned long c = 0;
      try {
        c = std::stoul(fields[k + 2], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != fields[k + 2].size() || c < 1 || c > 9)
        throw std::invalid_argument(at + "Properties: " + fields[k] + "'s count is '" + excerpt(fields[k + 2]) + "', expected 1 to 9");
      columns.push_back({fields[k], width, c});
      width += c;
    }
  }
  const auto find = [&](const std::string& name, std::size_t count, bool required) -> const Column* {
    for (const Column& c : columns) {
      if (c.name != name) continue;
      if (c.count != count)
        throw std::invalid_argument(at + "Properties: " + name + " has " + std::to_string(c.count) + " columns, expected " + std::to_string(count));
      return &c;
    }
    if (required) throw std::invalid_argument(at + "Properties has no " + name + ", expected species and pos at least");
    return nullptr;
  };
  const Column* species = find("species", 1, true);
  const Column* pos = find("pos", 3, true);
  const Column* velo = find("velo", 3, false);
  const Column* radius = find("radius", 1, false);
  const Column* mass = find("mass", 1, false);
  s.particles.reserve(std::min<std::size_t>(n, std::size_t(1) << 20));
  read_particles(in, source, 3, n, [&](const std::string& where_, const std::string&, const std::vector<std::string>& w) {
    if (w.size() != width)
      throw std::invalid_argument(where_ + std::to_string(w.size()) + " fields, expected " + std::to_string(width) + " (Properties=" + excerpt(properties) + ")");
    SnapshotParticle p;
    p.species = w[species->start];
    for (int k = 0; k < 3; ++k) p.position[k] = parse_number(w[pos->start + static_cast<std::size_t>(k)], where_, "a coordinate");
    if (velo)
      for (int k = 0; k < 3; ++k) p.velocity[k] = parse_number(w[velo->start + static_cast<std::size_t>(k)], where_, "a velocity component");
    if (radius) p.radius = positive(w[radius->start], where_, "the radius");
    if (mass) p.mass = positive(w[mass->start], where_, "the mass");
    if (s.dimension == 2 && (p.position.z() != 0 || p.velocity.z() != 0))
      throw std::invalid_argument(where_ + "z or v_z is not 0, expected a 2-D snapshot (pbc=\"T T F\") to lie in the plane z = 0");
    s.particles.push_back(p);
  });
  return s;
}

/// The .sph text of a snapshot (velocities and masses are not part of the format).
inline std::string sph_text(const Snapshot& s) {
  const auto number = digits17;
  if (s.dimension != 3)
    throw std::invalid_argument("a " + std::to_string(s.dimension) + "-D snapshot, expected a 3-D one for .sph (disks go in extended XYZ)");
  for (std::size_t i = 0; i < s.particles.size(); ++i) snapshot_detail::check_species(s.particles[i].species, i, true);
  std::string out = std::to_string(s.particles.size()) + "\n" + number(s.box.x()) + " " + number(s.box.y()) + " " +
                    number(s.box.z()) + "\n";
  for (const SnapshotParticle& p : s.particles) {
    out += p.species + " " + number(p.position.x()) + " " + number(p.position.y()) + " " +
           number(p.position.z()) + " " + number(p.radius) + "\n";
  }
  return out;
}

/// The extended XYZ text of a snapshot, one frame: every property of each particle.
inline std::string extended_xyz_text(const Snapshot& s) {
  const auto number = digits17;
  for (std::size_t i = 0; i < s.particles.size(); ++i) snapshot_detail::check_species(s.particles[i].species, i, false);
  std::string out = std::to_string(s.particles.size()) + "\nLattice=\"" + number(s.box.x()) + " 0 0 0 " +
                    number(s.box.y()) + " 0 0 0 " + number(s.box.z()) +
                    "\" Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1:mass:R:1 Time=" + number(s.time) +
                    (s.dimension == 2 ? " pbc=\"T T F\"\n" : " pbc=\"T T T\"\n");
  for (const SnapshotParticle& p : s.particles) {
    out += p.species;
    for (int k = 0; k < 3; ++k) out += " " + number(p.position[k]);
    for (int k = 0; k < 3; ++k) out += " " + number(p.velocity[k]);
    out += " " + number(p.radius) + " " + number(p.mass) + "\n";
  }
  return out;
}

/// The gas of a snapshot of dimension D: its box a square (2-D) or a cube (3-D), each particle's radius
/// and mass (GasSetup's `radii` and `masses` where they are not all equal), and its velocities, or,
/// where every one is 0 (a .sph file holds none), Gaussian ones at kT = 1 drawn with `seed`
/// (gas::thermal_velocities). Throws std::invalid_argument naming `source` and what was expected;
/// validate's checks (overlaps, the box's size) follow when the gas is built.
template <int D>
billiards::simulation::GasSetup<D> gas_setup(const Snapshot& s, const std::string& source, std::uint64_t seed) {
  const auto number = digits17;
  const std::string at = source + ": ";
  if (s.dimension != D)
    throw std::invalid_argument(at + "a " + std::to_string(s.dimension) + "-D snapshot, expected " + std::to_string(D) + "-D");
  const bool square = s.box.x() == s.box.y() && (D == 2 || s.box.x() == s.box.z());
  if (!square) {
    throw std::invalid_argument(at + "the box is " + number(s.box.x()) + " x " + number(s.box.y()) +
                                (D == 3 ? " x " + number(s.box.z()) : std::string()) + ", expected a " +
                                (D == 2 ? "square" : "cube") + " (the gas's periodic box has one side)");
  }
  if (s.particles.empty()) throw std::invalid_argument(at + "no particles, expected at least 2");
  billiards::simulation::GasSetup<D> setup;
  setup.side = s.box.x();
  setup.radius = s.particles[0].radius;
  setup.mass = s.particles[0].mass;
  bool moving = false, equal = true;
  for (const SnapshotParticle& p : s.particles) {
    billiards::simulation::Ball<D> ball;
    ball.position = p.position.template head<D>();
    ball.velocity = p.velocity.template head<D>();
    moving = moving || p.velocity != Eigen::Vector3d::Zero();
    equal = equal && p.radius == setup.radius && p.mass == setup.mass;
    setup.balls.push_back(ball);
    setup.radii.push_back(p.radius);
    setup.masses.push_back(p.mass);
  }
  if (equal) setup.radii.clear(), setup.masses.clear();
  if (!moving && setup.balls.size() >= 2) billiards::simulation::gas::thermal_velocities(setup, seed);
  return setup;
}

/// The snapshot of a gas's state at `time`: the box's sides (in 2-D a thickness of 1), each particle's
/// radius and mass, and its species from `species` (one a ball, in the setup's order: a snapshot read
/// keeps its own), or "a" for every one where `species` is empty.
template <int D>
Snapshot snapshot_of(const billiards::simulation::GasSetup<D>& setup, double time,
                     const std::vector<std::string>& species = {}) {
  Snapshot s;
  s.dimension = D;
  s.box = Eigen::Vector3d(setup.side, setup.side, D == 3 ? setup.side : 1.0);
  s.time = time;
  s.particles.reserve(setup.balls.size());
  for (std::size_t i = 0; i < setup.balls.size(); ++i) {
    SnapshotParticle p;
    p.position.template head<D>() = setup.balls[i].position;
    p.velocity.template head<D>() = setup.balls[i].velocity;
    p.radius = setup.radius_of(i);
    p.mass = setup.mass_of(i);
    if (!species.empty()) p.species = species[i];
    s.particles.push_back(p);
  }
  return s;
}

/// Whether `path` names an extended XYZ file (.xyz or .extxyz) rather than a .sph one; anything else
/// is rejected, naming the path.
inline bool is_extended_xyz(const std::string& path) {
  const auto ends = [&](const std::string& tail) {
    return path.size() >= tail.size() && path.compare(path.size() - tail.size(), tail.size(), tail) == 0;
  };
  if (ends(".xyz") || ends(".extxyz")) return true;
  if (ends(".sph")) return false;
  throw std::invalid_argument(path + ": not a snapshot file name, expected one ending in .sph, .xyz or .extxyz");
}

/// Reads a snapshot file, its format by its name (.sph, or .xyz/.extxyz for extended XYZ).
inline Snapshot read_snapshot_file(const std::string& path) {
  const bool xyz = is_extended_xyz(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(path + ": cannot open it: " + std::strerror(errno));
  return xyz ? read_extended_xyz(in, path) : read_sph(in, path);
}

/// Writes a snapshot file atomically, its format by its name.
inline void write_snapshot_file(const std::string& path, const Snapshot& s) {
  write_file_atomically(path, is_extended_xyz(path) ? extended_xyz_text(s) : sph_text(s));
}

}  // namespace billiards::io
