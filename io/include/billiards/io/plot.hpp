/// \file
/// A line plot as SVG, for the figures: one frame, ticks and grid on both axes, series drawn
/// as lines (solid or dashed) or as markers, a legend, all in plain SVG 1.1 that any browser shows.
/// Deterministic: the same series give the same bytes (fixed two-decimal coordinates, no dates).
#pragma once

#include <cmath>
#include <cstddef>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace billiards::io {

/// One axis: what it shows, its range and the spacing of its ticks (all finite, low < high, tick > 0).
struct Axis {
  std::string label;  ///< what it shows, with its unit
  double low = 0;     ///< the range's start
  double high = 1;    ///< the range's end
  double tick = 0.1;  ///< the spacing of the ticks and grid lines
};

/// One series of (x, y) points in axis units.
struct Series {
  /// How the points are drawn: joined by a solid or dashed line, or each a marker.
  enum class Style { line, dashed, markers };
  std::string label;   ///< its legend entry (empty: none)
  std::string colour;  ///< an SVG colour, "#rrggbb"
  Style style = Style::line;                       ///< how it is drawn
  std::vector<std::pair<double, double>> points;  ///< the (x, y) points, in axis units
};

/// `text` with the five XML special characters escaped.
inline std::string xml_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

/// Where the legend stands inside the frame.
enum class Legend { top_left, top_right };

/// The plot of `series` on axes `x` and `y` under `title`, with `notes` as lines of text below the
/// legend. Points outside the axes' ranges are clipped by the frame. Throws std::invalid_argument when an
/// axis is not as described above.
inline std::string line_plot_svg(const std::string& title, const Axis& x, const Axis& y,
                                 const std::vector<Series>& series,
                                 const std::vector<std::string>& notes = {},
                                 Legend legend = Legend::top_left) {
  for (const Axis* axis : {&x, &y}) {
    if (!(std::isfinite(axis->low) && std::isfinite(axis->high) && axis->low < axis->high &&
          std::isfinite(axis->tick) && axis->tick > 0 && (axis->high - axis->low) / axis->tick <= 100)) {
      throw std::invalid_argument("line_plot_svg: axis '" + axis->label +
                                  "' needs finite low < high and at most 100 ticks");
    }
  }
  const double width = 720, height = 450, left = 70, right = 20, top = 40, bottom = 55;
  const double plot_width = width - left - right, plot_height = height - top - bottom;
  const auto px = [&](double value) { return left + (value - x.low) / (x.high - x.low) * plot_width; };
  const auto py = [&](double value) { return top + (y.high - value) / (y.high - y.low) * plot_height; };
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << " " << height << "\" font-family=\"sans-serif\" font-size=\"13\">\n"
      << "<title>" << xml_escaped(title) << "</title>\n"
      << "<rect x=\"0\" y=\"0\" width=\"" << width << "\" height=\"" << height << "\" fill=\"#ffffff\"/>\n"
      << "<clipPath id=\"frame\"><rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << plot_width
      << "\" height=\"" << plot_height << "\"/></clipPath>\n"
      << "<text x=\"" << width / 2 << "\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">"
      << xml_escaped(title) << "</text>\n";
  // Ticks by index, so that rounding never drops the last one.
  const auto ticks = [](const Axis& axis) {
    std::vector<double> values;
    const auto count = static_cast<int>(std::floor((axis.high - axis.low) / axis.tick + 1e-9));
    for (int i = 0; i <= count; ++i) values.push_back(axis.low + i * axis.tick);
    return values;
  };
  const auto tick_label = [](double value) {
    std::ostringstream text;
    text << std::defaultfloat << std::setprecision(6) << (std::fabs(value) < 1e-12 ? 0.0 : value);
    return text.str();
  };
  for (const double value : ticks(x)) {
    out << "<line x1=\"" << px(value) << "\" y1=\"" << top << "\" x2=\"" << px(value) << "\" y2=\""
        << top + plot_height << "\" stroke=\"#e0e0e0\"/>\n"
        << "<text x=\"" << px(value) << "\" y=\"" << top + plot_height + 18 << "\" text-anchor=\"middle\">"
        << tick_label(value) << "</text>\n";
  }
  for (const double value : ticks(y)) {
    out << "<line x1=\"" << left << "\" y1=\"" << py(value) << "\" x2=\"" << left + plot_width << "\" y2=\""
        << py(value) << "\" stroke=\"#e0e0e0\"/>\n"
        << "<text x=\"" << left - 8 << "\" y=\"" << py(value) + 4 << "\" text-anchor=\"end\">"
        << tick_label(value) << "</text>\n";
  }
  out << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << plot_width << "\" height=\""
      << plot_height << "\" fill=\"none\" stroke=\"#000000\"/>\n"
      << "<text x=\"" << left + plot_width / 2 << "\" y=\"" << height - 12 << "\" text-anchor=\"middle\">"
      << xml_escaped(x.label) << "</text>\n"
      << "<text transform=\"translate(18 " << top + plot_height / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << xml_escaped(y.label) << "</text>\n";
  out << "<g clip-path=\"url(#frame)\">\n";
  for (const Series& s : series) {
    if (s.style == Series::Style::markers) {
      for (const auto& [a, b] : s.points) {
        out << "<circle cx=\"" << px(a) << "\" cy=\"" << py(b) << "\" r=\"3\" fill=\"none\" stroke=\""
            << s.colour << "\" stroke-width=\"1.5\"/>\n";
      }
      continue;
    }
    out << "<polyline fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"1.5\""
        << (s.style == Series::Style::dashed ? " stroke-dasharray=\"6 4\"" : "") << " points=\"";
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      out << (k ? " " : "") << px(s.points[k].first) << "," << py(s.points[k].second);
    }
    out << "\"/>\n";
  }
  out << "</g>\n";
  // The legend inside the frame, then the notes.
  const double x0 = legend == Legend::top_left ? left + 14 : left + plot_width - 300;
  double row = top + 20;
  for (const Series& s : series) {
    if (s.label.empty()) continue;
    if (s.style == Series::Style::markers) {
      out << "<circle cx=\"" << x0 + 12 << "\" cy=\"" << row - 4 << "\" r=\"3\" fill=\"none\" stroke=\""
          << s.colour << "\" stroke-width=\"1.5\"/>\n";
    } else {
      out << "<line x1=\"" << x0 << "\" y1=\"" << row - 4 << "\" x2=\"" << x0 + 24 << "\" y2=\"" << row - 4
          << "\" stroke=\"" << s.colour << "\" stroke-width=\"1.5\""
          << (s.style == Series::Style::dashed ? " stroke-dasharray=\"6 4\"" : "") << "/>\n";
    }
    out << "<text x=\"" << x0 + 32 << "\" y=\"" << row << "\">" << xml_escaped(s.label) << "</text>\n";
    row += 18;
  }
  for (const std::string& note : notes) {
    out << "<text x=\"" << x0 << "\" y=\"" << row << "\" fill=\"#555555\">" << xml_escaped(note)
        << "</text>\n";
    row += 18;
  }
  out << "</svg>\n";
  return out.str();
}

}  // namespace billiards::io
