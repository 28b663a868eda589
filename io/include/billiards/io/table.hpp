/// \file
/// Reading a table setup file and drawing trajectories as SVG (billiards-table's, and any program's).
///
/// A setup file holds one directive per line; '#' starts a comment, blank lines are ignored:
///
/// \verbatim
///   table  <width> <height>     the playing area in metres (default 2.54 1.27)
///   radius <r>                  every ball's radius in metres (default 0.028575)
///   mass   <m>                  every ball's mass in kilograms (default 0.17)
///   ball   <x> <y> <vx> <vy>    one ball: centre and velocity (at least one ball)
/// \endverbatim
///
/// The cushions are the lines x = 0, x = width, y = 0, y = height.
#pragma once

#include <billiards/simulation/table.hpp>

#include <billiards/io/atomic_file.hpp>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <algorithm>
#include <fstream>
#include <iomanip>
#include <istream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace billiards::io {

using billiards::simulation::Ball;
using billiards::simulation::TableEvent;
using billiards::simulation::TableSetup;
using billiards::simulation::TableVector;

/// Limits on what a setup file may hold, so that a hostile file (/dev/zero, a endless stream) is
/// rejected promptly instead of growing memory: a line of at most 4096 characters, at most 256 MiB in
/// all (a million balls take about 40 MB).
inline constexpr std::size_t longest_setup_line = 4096;                ///< characters a line
inline constexpr std::size_t largest_setup_file = std::size_t(256) << 20;  ///< bytes a file

/// `text` for a message: at most 40 characters, the rest elided.
inline std::string excerpt(const std::string& text) {
  constexpr std::size_t shown = 40;
  return text.size() <= shown ? text
                              : text.substr(0, shown) + "… (" + std::to_string(text.size()) + " characters)";
}

/// A number in a setup file: a finite double, the whole word (strtod, so subnormal values such as
/// 1e-310 are read as what they are). Throws std::invalid_argument with `where` and an excerpt.
inline double parse_number(const std::string& word, const std::string& where, const char* expected) {
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(word.c_str(), &end);
  const bool whole = end != nullptr && *end == '\0' && !word.empty();
  if (!whole || !std::isfinite(value)) {
    throw std::invalid_argument(where + "'" + excerpt(word) + "' is not a finite number, expected " +
                                expected);
  }
  if (errno == ERANGE && value == 0) {
    throw std::invalid_argument(where + "'" + excerpt(word) +
                                "' is below the smallest subnormal number (it would read as 0), expected " +
                                expected);
  }
  return value;
}

/// One line of `in` into `line` (without its '\n'), at most longest_setup_line characters: never more is
/// held in memory (a longer line throws std::invalid_argument with `where` and `expected`, as does a
/// file that cannot be read). Returns whether the line ended with '\n'.
inline bool read_bounded_line(std::istream& in, std::string& line, const std::string& where, const char* expected) {
  line.clear();
  bool ended = false;
  for (int c; (c = in.get()) != std::char_traits<char>::eof();) {
    if (c == '\n') {
      ended = true;
      break;
    }
    if (line.size() == longest_setup_line) {
      throw std::invalid_argument(where + "the line is longer than " + std::to_string(longest_setup_line) +
                                  " characters ('" + excerpt(line) + "'), expected " + expected);
    }
    line.push_back(static_cast<char>(c));
  }
  if (in.bad()) throw std::invalid_argument(where + "cannot read the file: " + std::strerror(errno));
  return ended;
}

/// Reads a setup's lines: for each directive, `handle(where, directive, words)` with `where` the
/// "source:line: " prefix for messages and `words` the rest of the line ('#' starts a comment; blank
/// lines are skipped). A line beyond longest_setup_line characters or a file beyond largest_setup_file
/// bytes throws std::invalid_argument at once, as does a file that cannot be read.
template <typename Handle>
void read_directives(std::istream& in, const std::string& source, Handle handle) {
  std::string line;
  std::size_t total = 0;
  for (int number = 1;; ++number) {
    const std::string where = source + ":" + std::to_string(number) + ": ";
    const bool ended = read_bounded_line(in, line, where, "one directive per line");
    total += line.size() + 1;
    if (total > largest_setup_file) {
      throw std::invalid_argument(where + "the file is larger than " +
                                  std::to_string(largest_setup_file >> 20) +
                                  " MiB, expected a setup (one line per ball)");
    }
    if (!ended && line.empty()) break;  // the end of the file
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string directive;
    if (!(words >> directive)) {
      if (!ended) break;
      continue;
    }
    handle(where, directive, words);
    if (!ended) break;
  }
}

/// The numbers left on a directive's line: exactly `count` of them (or, with `at_most` above `count`,
/// any count from `count` to `at_most`), each a finite number (parse_number). Throws
/// std::invalid_argument naming `where`, the directive and `expected`.
inline std::vector<double> directive_numbers(std::istringstream& words, const std::string& where,
                                             const std::string& directive, std::size_t count,
                                             const char* expected, std::size_t at_most = 0) {
  std::vector<double> values;
  std::string word;
  while (words >> word) values.push_back(parse_number(word, where + directive + ": ", expected));
  if (values.size() < count || values.size() > std::max(count, at_most)) {
    throw std::invalid_argument(where + directive + ": " + std::to_string(values.size()) + " numbers, expected " +
                                expected);
  }
  return values;
}

/// Parses a setup (the format above) and validates it. Throws std::invalid_argument naming
/// `source:line`, the directive and what was expected; a file that cannot be read says why.
inline TableSetup read_setup(std::istream& in, const std::string& source) {
  TableSetup setup;
  setup.balls.clear();
  setup.origin.file = source + ": ";
  read_directives(in, source, [&](const std::string& where, const std::string& directive, std::istringstream& words) {
    const auto numbers = [&](std::size_t count, const char* expected) {
      return directive_numbers(words, where, directive, count, expected);
    };
    if (directive == "table") {
      const auto v = numbers(2, "2 numbers: width height");
      setup.width = v[0];
      setup.height = v[1];
      setup.origin.table = where;
    } else if (directive == "radius") {
      setup.radius = numbers(1, "1 number: the radius")[0];
      setup.origin.radius = where;
    } else if (directive == "mass") {
      setup.mass = numbers(1, "1 number: the mass")[0];
      setup.origin.mass = where;
    } else if (directive == "ball") {
      const auto v = numbers(4, "4 numbers: x y vx vy");
      setup.balls.push_back({TableVector(v[0], v[1]), TableVector(v[2], v[3])});
      setup.origin.balls.push_back(where);
    } else {
      throw std::invalid_argument(where + "unknown directive '" + excerpt(directive) +
                                  "', expected table, radius, mass or ball");
    }
  });
  validate(setup);
  return setup;
}

/// Opens `path` for reading as a setup file; throws std::invalid_argument saying why it cannot be.
inline std::ifstream open_setup_file(const std::string& path) {
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open()) {
    throw std::invalid_argument(
        path + ": cannot open the setup file: " + (errno != 0 ? std::strerror(errno) : "unknown reason"));
  }
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw std::invalid_argument(path + ": is a folder, expected a setup file");
  }
  return in;
}

/// Opens and reads a setup file: read_setup, with an error that says why a file cannot be opened.
inline TableSetup read_setup_file(const std::string& path) {
  std::ifstream in = open_setup_file(path);
  return read_setup(in, path);
}

/// Each ball's path: its position at the start and at every event, and at the end.
class Trajectories {
 public:
  /// Starts every ball's path at its position in `setup`.
  explicit Trajectories(const TableSetup& setup) : setup_(setup), paths_(setup.balls.size()) {
    for (std::size_t i = 0; i < setup.balls.size(); ++i) paths_[i].push_back(setup.balls[i].position);
  }
  /// Records the balls of `event` at their contact positions.
  void record(const TableEvent& event, const std::vector<Ball<2>>& balls) {
    paths_[event.first].push_back(balls[event.first].position);
    if (event.kind == TableEvent::Kind::ball) paths_[event.second].push_back(balls[event.second].position);
  }
  /// Ends every path at the balls' current positions.
  void finish(const std::vector<Ball<2>>& balls) {
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
  TableSetup setup_;
  std::vector<std::vector<TableVector>> paths_;
  std::vector<Ball<2>> final_;
};

}  // namespace billiards::io
