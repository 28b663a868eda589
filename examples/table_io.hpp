// Reading a table setup file and drawing trajectories as SVG, for the billiards-table example.
//
// A setup file holds one directive per line; '#' starts a comment, blank lines are ignored:
//
//   table  <width> <height>     the playing area in metres (default 2.54 1.27)
//   radius <r>                  every ball's radius in metres (default 0.028575)
//   mass   <m>                  every ball's mass in kilograms (default 0.17)
//   ball   <x> <y> <vx> <vy>    one ball: centre and velocity (at least one ball)
//
// The cushions are the lines x = 0, x = width, y = 0, y = height.
#pragma once

#include "table.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <istream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace billiards_example {

/// Parses a setup (the format above) and validates it. Throws std::invalid_argument naming
/// `source:line`, the directive and what was expected.
inline Setup read_setup(std::istream& in, const std::string& source) {
  Setup setup;
  setup.balls.clear();
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string where = source + ":" + std::to_string(number) + ": ";
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string directive;
    if (!(words >> directive)) continue;
    const auto numbers = [&](std::size_t count, const char* expected) {
      std::vector<double> values;
      std::string word;
      while (words >> word) {
        std::size_t used = 0;
        double value = 0;
        try {
          value = std::stod(word, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used != word.size() || !std::isfinite(value)) {
          throw std::invalid_argument(where + directive + ": '" + word +
                                      "' is not a finite number, expected " + expected);
        }
        values.push_back(value);
      }
      if (values.size() != count) {
        throw std::invalid_argument(where + directive + ": " + std::to_string(values.size()) +
                                    " numbers, expected " + expected);
      }
      return values;
    };
    if (directive == "table") {
      const auto v = numbers(2, "2 numbers: width height");
      setup.width = v[0];
      setup.height = v[1];
    } else if (directive == "radius") {
      setup.radius = numbers(1, "1 number: the radius")[0];
    } else if (directive == "mass") {
      setup.mass = numbers(1, "1 number: the mass")[0];
    } else if (directive == "ball") {
      const auto v = numbers(4, "4 numbers: x y vx vy");
      setup.balls.push_back({Vector(v[0], v[1]), Vector(v[2], v[3])});
    } else {
      throw std::invalid_argument(where + "unknown directive '" + directive +
                                  "', expected table, radius, mass or ball");
    }
  }
  try {
    validate(setup);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(source + ": " + error.what());
  }
  return setup;
}

/// Each ball's path: its position at the start and at every event, and at the end.
class Trajectories {
 public:
  explicit Trajectories(const Setup& setup) : setup_(setup), paths_(setup.balls.size()) {
    for (std::size_t i = 0; i < setup.balls.size(); ++i) paths_[i].push_back(setup.balls[i].position);
  }
  /// Records the balls of `event` at their contact positions.
  void record(const Event& event, const std::vector<Ball>& balls) {
    paths_[event.first].push_back(balls[event.first].position);
    if (event.kind == Event::Kind::ball) paths_[event.second].push_back(balls[event.second].position);
  }
  /// Ends every path at the balls' current positions.
  void finish(const std::vector<Ball>& balls) {
    for (std::size_t i = 0; i < balls.size(); ++i) paths_[i].push_back(balls[i].position);
    final_ = balls;
  }

  /// The table, each ball's path (ball 0 white, the others in colour) and the balls where they
  /// started (faint) and ended. 500 pixels per metre, y upwards.
  std::string svg(const std::string& title) const {
    const double scale = 500, margin = 20;
    const double width = setup_.width * scale + 2 * margin, height = setup_.height * scale + 2 * margin;
    const auto x = [&](double value) { return margin + value * scale; };
    const auto y = [&](double value) { return margin + (setup_.height - value) * scale; };
    static const char* const colours[] = {"#f4d03f", "#2e86c1", "#e74c3c", "#8e44ad", "#e67e22",
                                          "#27ae60", "#922b21", "#17202a", "#f7dc6f", "#5dade2",
                                          "#ec7063", "#a569bd", "#f0b27a", "#52be80", "#cd6155"};
    const auto colour = [&](std::size_t i) {
      return i == 0 ? std::string("#ffffff") : colours[(i - 1) % 15];
    };
    std::ostringstream out;
    out << std::fixed << std::setprecision(2);
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" viewBox=\"0 0 " << width << " " << height << "\">\n"
        << "<title>" << title << "</title>\n"
        << "<rect x=\"0\" y=\"0\" width=\"" << width << "\" height=\"" << height << "\" fill=\"#5d4037\"/>\n"
        << "<rect x=\"" << margin << "\" y=\"" << margin << "\" width=\"" << setup_.width * scale
        << "\" height=\"" << setup_.height * scale << "\" fill=\"#1e7b45\"/>\n";
    const double r = setup_.radius * scale;
    for (std::size_t i = 0; i < paths_.size(); ++i) {
      out << "<circle cx=\"" << x(paths_[i].front().x()) << "\" cy=\"" << y(paths_[i].front().y())
          << "\" r=\"" << r << "\" fill=\"" << colour(i) << "\" fill-opacity=\"0.3\"/>\n";
    }
    for (std::size_t i = 0; i < paths_.size(); ++i) {
      out << "<polyline fill=\"none\" stroke=\"" << colour(i) << "\" stroke-width=\"1.5\" points=\"";
      for (std::size_t k = 0; k < paths_[i].size(); ++k) {
        out << (k ? " " : "") << x(paths_[i][k].x()) << "," << y(paths_[i][k].y());
      }
      out << "\"/>\n";
    }
    for (std::size_t i = 0; i < final_.size(); ++i) {
      out << "<circle cx=\"" << x(final_[i].position.x()) << "\" cy=\"" << y(final_[i].position.y())
          << "\" r=\"" << r << "\" fill=\"" << colour(i) << "\" stroke=\"#000000\" stroke-width=\"0.5\"/>\n";
    }
    out << "</svg>\n";
    return out.str();
  }

 private:
  Setup setup_;
  std::vector<std::vector<Vector>> paths_;
  std::vector<Ball> final_;
};

/// Writes `contents` to `path` through a temporary file beside it, renamed into place, so that an
/// interrupted run never leaves a half-written file. Throws std::runtime_error naming the path.
inline void write_file_atomically(const std::filesystem::path& path, const std::string& contents) {
  const std::filesystem::path temporary = path.string() + ".tmp";
  {
    errno = 0;
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out.is_open()) {
      throw std::runtime_error("cannot write " + path.string() + ": cannot create " + temporary.string() +
                               " (" + std::strerror(errno) + ")");
    }
    out << contents;
    out.flush();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw std::runtime_error("cannot write " + path.string() + ": writing " + temporary.string() +
                               " failed");
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw std::runtime_error("cannot write " + path.string() + ": " + error.message());
  }
}

}  // namespace billiards_example
