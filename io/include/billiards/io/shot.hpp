/// \file
/// A shot's setup files and outputs (billiards-shot's, and any program's): placements read from a
/// file, the events as JSON (docs/events.schema.json), the trajectories sampled at a rate (CSV), the
/// shot drawn as SVG, and one self-contained HTML page that animates it (a slider over time).
///
/// A shot setup file holds one directive per line; '#' starts a comment, blank lines are ignored:
///
/// \verbatim
///   table  7ft | 8ft | 9ft | snooker | carom
///                                           the table (default: the command line's --table)
///   ball   <x> <y> [<vx> <vy> [<wx> <wy> <wz>]]
///                                           one ball: centre (m), velocity (m/s) and spin (rad/s), at
///                                           rest and without spin where left out; ball i is the i-th
/// \endverbatim
#pragma once

#include <billiards/io/json.hpp>
#include <billiards/io/table.hpp>

#include <billiards/simulation/shot.hpp>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace billiards::io {

using billiards::simulation::PoolBall;
using billiards::simulation::PoolPhysics;
using billiards::simulation::PoolTable;
using billiards::simulation::Shot;
using billiards::simulation::ShotEvent;

/// What a shot setup file holds: the table's preset, if named, and the balls.
struct ShotSetup {
  std::optional<std::string> table;  ///< "7ft", "8ft", "9ft", "snooker" or "carom"
  std::vector<PoolBall> balls;       ///< in the file's order
  std::vector<std::string> origins;  ///< each ball's "file:line: "
};

/// The most balls a shot setup may hold.
inline constexpr std::size_t most_shot_balls = 64;

/// Parses a shot setup (the format above). Throws std::invalid_argument naming `source:line`, the
/// directive and what was expected. The balls are checked against the table by Shot itself; the caller
/// names the line of a ball Shot rejects (ShotSetup::origins).
inline ShotSetup read_shot_setup(std::istream& in, const std::string& source, double radius) {
  ShotSetup setup;
  read_directives(in, source, [&](const std::string& where, const std::string& directive, std::istringstream& words) {
    if (directive == "table") {
      std::string name, extra;
      if (!(words >> name) || (words >> extra) ||
          (name != "7ft" && name != "8ft" && name != "9ft" && name != "snooker" && name != "carom")) {
        throw std::invalid_argument(where + "table: '" + excerpt(name) +
                                    "', expected one of 7ft, 8ft, 9ft, snooker, carom");
      }
      setup.table = name;
    } else if (directive == "ball") {
      if (setup.balls.size() == most_shot_balls) {
        throw std::invalid_argument(where + "ball: more than " + std::to_string(most_shot_balls) +
                                    " balls, expected at most " + std::to_string(most_shot_balls));
      }
      const std::vector<double> v = directive_numbers(
          words, where, directive, 2, "2, 4 or 7 numbers: x y [vx vy [wx wy wz]]", 7);
      if (v.size() != 2 && v.size() != 4 && v.size() != 7) {
        throw std::invalid_argument(where + "ball: " + std::to_string(v.size()) +
                                    " numbers, expected 2, 4 or 7 numbers: x y [vx vy [wx wy wz]]");
      }
      PoolBall ball;
      ball.position = {v[0], v[1], radius};
      if (v.size() >= 4) ball.velocity = {v[2], v[3], 0};
      if (v.size() == 7) ball.angular_velocity = {v[4], v[5], v[6]};
      setup.balls.push_back(ball);
      setup.origins.push_back(where);
    } else {
      throw std::invalid_argument(where + "unknown directive '" + excerpt(directive) + "', expected table or ball");
    }
  });
  if (setup.balls.empty()) throw std::invalid_argument(source + ": no ball, expected at least one 'ball x y' line");
  return setup;
}

/// Opens and reads a shot setup file (read_shot_setup).
inline ShotSetup read_shot_setup_file(const std::string& path, double radius) {
  std::ifstream in = open_setup_file(path);
  return read_shot_setup(in, path, radius);
}

namespace shot_detail {


inline std::string vector_json(const Eigen::Vector3d& v, int size) {
  std::string out = "[" + json_number(v.x()) + ", " + json_number(v.y());
  if (size == 3) out += ", " + json_number(v.z());
  return out + "]";
}

inline std::string state_json(std::size_t index, const PoolBall& b) {
  return "{\"ball\": " + std::to_string(index) + ", \"position\": " + vector_json(b.position, 2) +
         ", \"velocity\": " + vector_json(b.velocity, 2) + ", \"angular_velocity\": " +
         vector_json(b.angular_velocity, 3) + ", \"pocketed\": " + (b.pocketed ? "true" : "false") + "}";
}

/// The balls' colours: the cue ball white, then the pool balls' (1 yellow … 8 black, 9–15 their stripes);
/// on a table without pockets the carom balls (1 yellow, 2 red); in a layout of 22 balls the snooker
/// balls (snooker_ball::: 1–15 red, then yellow, green, brown, blue, pink, black).
inline std::string colour(const Shot& shot, std::size_t i) {
  static const char* const pool[] = {"#f4d03f", "#1f4fa3", "#d62828", "#6a2c91", "#f77f00",
                                     "#1e8449", "#7b241c", "#111111"};
  static const char* const snooker[] = {"#f4d03f", "#1e8449", "#7b4a1e", "#1f4fa3", "#f48fb1", "#111111"};
  if (i == 0) return "#ffffff";
  if (!shot.table().has_pockets) return i == 1 ? "#f4d03f" : "#d62828";
  if (shot.placed().size() == billiards::simulation::snooker_ball::ball_count)
    return billiards::simulation::snooker_ball::is_red(i) ? "#d62828" : snooker[(i - billiards::simulation::snooker_ball::yellow) % 6];
  return pool[(i - 1) % 8];
}

}  // namespace shot_detail

/// The shot as JSON: the table, the physics, the balls at the start (as placed, the strikes at t = 0
/// applied, before any contact), every event (time, kind, the balls,
/// the cushion, jaw or pocket, the phases, and the balls' states after it), the balls at rest and the
/// pocketed balls.
inline std::string shot_json(const Shot& shot, const std::string& table_name) {
  using shot_detail::state_json;
  std::ostringstream out;
  const PoolTable& t = shot.table();
  const PoolPhysics& p = shot.physics();
  out << "{\n  \"table\": {\"size\": \"" << table_name << "\", \"length\": " << json_number(t.length)
      << ", \"width\": " << json_number(t.width) << ", \"nose_height\": " << json_number(t.nose_height) << "},\n"
      << "  \"physics\": {\"radius\": " << json_number(p.radius) << ", \"mass\": " << json_number(p.mass)
      << ", \"sliding_friction\": " << json_number(p.cloth.sliding_friction)
      << ", \"rolling_friction\": " << json_number(p.cloth.rolling_friction)
      << ", \"spinning_friction\": " << json_number(p.cloth.spinning_friction) << ", \"gravity\": " << json_number(p.cloth.gravity)
      << ", \"ball_restitution\": " << json_number(p.ball_restitution) << ", \"ball_friction\": " << json_number(p.ball_friction)
      << ", \"cushion_restitution\": " << json_number(p.cushion_restitution)
      << ", \"cushion_friction\": " << json_number(p.cushion_friction) << "},\n";
  const auto balls_json = [&](const std::vector<PoolBall>& balls) {
    std::string text = "[";
    for (std::size_t i = 0; i < balls.size(); ++i) text += (i ? ",\n    " : "\n    ") + state_json(i, balls[i]);
    return text + "\n  ]";
  };
  // The balls as placed, with the strikes at t = 0 applied: before any contact at t = 0.
  std::vector<PoolBall> start = shot.placed();
  for (const ShotEvent& e : shot.events()) {
    if (e.kind != ShotEvent::Kind::strike || e.time != 0) break;
    start[e.first] = e.first_after;
  }
  out << "  \"start\": " << balls_json(start) << ",\n  \"events\": [";
  const auto& events = shot.events();
  for (std::size_t k = 0; k < events.size(); ++k) {
    const ShotEvent& e = events[k];
    out << (k ? ",\n    " : "\n    ") << "{\"time\": " << json_number(e.time) << ", \"kind\": \""
        << billiards::simulation::kind_name(e.kind) << "\", \"balls\": [" << e.first;
    if (e.kind == ShotEvent::Kind::ball) out << ", " << e.second;
    out << "]";
    if (e.kind == ShotEvent::Kind::cushion || e.kind == ShotEvent::Kind::jaw || e.kind == ShotEvent::Kind::pocket)
      out << ", \"" << billiards::simulation::kind_name(e.kind) << "\": " << e.second;
    out << ", \"from\": \"" << billiards::simulation::motion_name(e.from) << "\", \"to\": \""
        << billiards::simulation::motion_name(e.to) << "\", \"states\": [" << state_json(e.first, e.first_after);
    if (e.kind == ShotEvent::Kind::ball) out << ", " << state_json(e.second, e.second_after);
    out << "]}";
  }
  const std::vector<PoolBall> rest = shot.balls();
  out << "\n  ],\n  \"time\": " << json_number(shot.time()) << ",\n  \"final\": " << balls_json(rest)
      << ",\n  \"pocketed\": [";
  bool first = true;
  for (std::size_t i = 0; i < rest.size(); ++i) {
    if (!rest[i].pocketed) continue;
    out << (first ? "" : ", ") << i;
    first = false;
  }
  out << "]\n}\n";
  return out.str();
}

/// The sample times of a shot at `rate` per second: 0, 1/rate, … up to the last event, and the last
/// event's time itself.
inline std::vector<double> sample_times(const Shot& shot, double rate) {
  std::vector<double> times;
  const double end = shot.time();
  const auto count = static_cast<std::size_t>(std::floor(end * rate));
  for (std::size_t k = 0; k <= count; ++k) times.push_back(static_cast<double>(k) / rate);
  if (times.back() < end) times.push_back(end);
  return times;
}

/// The trajectories as CSV, one row per ball per sample: time,ball,x,y,vx,vy,pocketed.
inline std::string trajectories_csv(const Shot& shot, double rate) {
  std::string out = "time,ball,x,y,vx,vy,pocketed\n";
  for (const double t : sample_times(shot, rate)) {
    const std::vector<PoolBall> balls = shot.balls_at(t);
    for (std::size_t i = 0; i < balls.size(); ++i) {
      out += json_number(t) + "," + std::to_string(i) + "," + json_number(balls[i].position.x()) + "," +
             json_number(balls[i].position.y()) + "," + json_number(balls[i].velocity.x()) + "," +
             json_number(balls[i].velocity.y()) + "," + (balls[i].pocketed ? "1" : "0") + "\n";
    }
  }
  return out;
}

/// The table drawn in SVG units of millimetres (y up as on the table): the cloth, cushions, jaws and the
/// shot's pockets (Shot::pockets); `margin` around the noses.
inline std::string table_svg(const Shot& shot, double margin) {
  const PoolTable& table = shot.table();
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);
  const auto X = [&](double x) { return 1000 * (x + margin); };
  const auto Y = [&](double y) { return 1000 * (table.width + margin - y); };
  out << "<rect x=\"0\" y=\"0\" width=\"" << 1000 * (table.length + 2 * margin) << "\" height=\""
      << 1000 * (table.width + 2 * margin) << "\" fill=\"#5d4037\"/>\n"
      << "<rect x=\"" << X(0) << "\" y=\"" << Y(table.width) << "\" width=\"" << 1000 * table.length << "\" height=\""
      << 1000 * table.width << "\" fill=\"#1e7b45\"/>\n";
  for (const auto& pocket : shot.pockets()) {
    out << "<circle cx=\"" << X(pocket.centre.x()) << "\" cy=\"" << Y(pocket.centre.y()) << "\" r=\""
        << 1000 * pocket.radius << "\" fill=\"#111111\"/>\n";
  }
  for (const auto& c : table.cushions()) {
    out << "<line x1=\"" << X(c.start.x()) << "\" y1=\"" << Y(c.start.y()) << "\" x2=\"" << X(c.end.x())
        << "\" y2=\"" << Y(c.end.y()) << "\" stroke=\"#0b5e2e\" stroke-width=\"6\"/>\n";
  }
  for (const auto& jaw : table.jaws()) {
    out << "<circle cx=\"" << X(jaw.centre.x()) << "\" cy=\"" << Y(jaw.centre.y()) << "\" r=\"" << 1000 * jaw.radius
        << "\" fill=\"#0b5e2e\"/>\n";
  }
  return out.str();
}

/// The shot as SVG: the table, each ball's path sampled at 200 per second and at every event of its
/// own, where it started (faint) and where it stopped (numbered); a pocketed ball's path ends in its pocket.
inline std::string shot_svg(const Shot& shot, const std::string& title) {
  const PoolTable& table = shot.table();
  const double margin = 0.12, R = shot.physics().radius;
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);
  const auto X = [&](double x) { return 1000 * (x + margin); };
  const auto Y = [&](double y) { return 1000 * (table.width + margin - y); };
  const double width = 1000 * (table.length + 2 * margin), height = 1000 * (table.width + 2 * margin);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width / 2.5 << "\" height=\"" << height / 2.5
      << "\" viewBox=\"0 0 " << width << " " << height << "\">\n<title>";
  for (const char c : title) {
    if (c == '<') out << "&lt;";
    else if (c == '&') out << "&amp;";
    else out << c;
  }
  out << "</title>\n" << table_svg(shot, margin);
  // The sample times and every event's time, in order.
  std::vector<double> times = sample_times(shot, 200);
  for (const ShotEvent& e : shot.events()) times.push_back(e.time);
  std::sort(times.begin(), times.end());
  std::vector<std::vector<PoolBall>> samples;
  for (const double t : times) samples.push_back(shot.balls_at(t));
  const std::size_t n = samples.front().size();
  for (std::size_t i = 0; i < n; ++i) {
    const PoolBall& start = samples.front()[i];
    if (start.pocketed) continue;
    out << "<circle cx=\"" << X(start.position.x()) << "\" cy=\"" << Y(start.position.y()) << "\" r=\"" << 1000 * R
        << "\" fill=\"" << shot_detail::colour(shot, i) << "\" fill-opacity=\"0.3\"/>\n";
  }
  for (std::size_t i = 0; i < n; ++i) {
    out << "<polyline fill=\"none\" stroke=\"" << shot_detail::colour(shot, i) << "\" stroke-width=\"3\" points=\"";
    const Eigen::Vector3d* last = nullptr;
    bool first = true;
    for (const auto& balls : samples) {
      const Eigen::Vector3d& r = balls[i].position;
      if (last && *last == r) continue;
      out << (first ? "" : " ") << X(r.x()) << "," << Y(r.y());
      first = false;
      last = &r;
      if (balls[i].pocketed) break;
    }
    out << "\"/>\n";
  }
  const std::vector<PoolBall> rest = shot.balls();
  for (std::size_t i = 0; i < n; ++i) {
    if (rest[i].pocketed) continue;
    out << "<circle cx=\"" << X(rest[i].position.x()) << "\" cy=\"" << Y(rest[i].position.y()) << "\" r=\"" << 1000 * R
        << "\" fill=\"" << shot_detail::colour(shot, i) << "\" stroke=\"#000000\" stroke-width=\"1.5\"/>\n";
    if (i > 0) {
      out << "<text x=\"" << X(rest[i].position.x()) << "\" y=\"" << Y(rest[i].position.y()) + 9
          << "\" font-family=\"sans-serif\" font-size=\"26\" text-anchor=\"middle\" fill=\""
          << (i == 8 ? "#ffffff" : "#000000") << "\">" << i << "</text>\n";
    }
  }
  out << "</svg>\n";
  return out.str();
}

/// One self-contained HTML page that animates the shot: the table in SVG, the balls moved by a slider
/// over time (and a play button), from the trajectories sampled at `rate` per second and embedded in
/// the page. No script, style or font is loaded from elsewhere. The page's state is readable: each ball
/// is a circle with id "ball-i" whose data-x and data-y hold its centre (m) at the slider's time, and
/// the address's fragment "#t=SECONDS" sets the slider when the page opens.
inline std::string shot_html(const Shot& shot, const std::string& title, double rate) {
  const PoolTable& table = shot.table();
  const double margin = 0.12, R = shot.physics().radius;
  const std::vector<double> times = sample_times(shot, rate);
  std::ostringstream data;
  data << "{\"length\": " << json_number(table.length) << ", \"width\": " << json_number(table.width)
       << ", \"margin\": " << json_number(margin) << ", \"times\": [";
  for (std::size_t k = 0; k < times.size(); ++k) data << (k ? "," : "") << json_number(times[k]);
  data << "], \"balls\": [";
  std::vector<std::vector<PoolBall>> samples;
  for (const double t : times) samples.push_back(shot.balls_at(t));
  const std::size_t n = samples.front().size();
  for (std::size_t i = 0; i < n; ++i) {
    data << (i ? "," : "") << "{\"x\": [";
    for (std::size_t k = 0; k < samples.size(); ++k) data << (k ? "," : "") << json_number(samples[k][i].position.x());
    data << "], \"y\": [";
    for (std::size_t k = 0; k < samples.size(); ++k) data << (k ? "," : "") << json_number(samples[k][i].position.y());
    data << "], \"pocketed\": [";
    for (std::size_t k = 0; k < samples.size(); ++k) data << (k ? "," : "") << (samples[k][i].pocketed ? 1 : 0);
    data << "]}";
  }
  data << "]}";
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);
  const double width = 1000 * (table.length + 2 * margin), height = 1000 * (table.width + 2 * margin);
  std::string escaped;
  for (const char c : title) escaped += c == '<' ? std::string("&lt;") : c == '&' ? std::string("&amp;") : std::string(1, c);
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << escaped
      << "</title>\n<style>body{font-family:sans-serif;margin:1em;background:#fafafa}svg{max-width:100%;height:auto}"
         "#controls{margin:0.5em 0}#time{width:60%}</style>\n</head>\n<body>\n<h1>"
      << escaped << "</h1>\n<div id=\"controls\"><button id=\"play\" type=\"button\">Play</button> "
      << "<input id=\"time\" type=\"range\" min=\"0\" max=\"" << times.size() - 1 << "\" step=\"1\" value=\"0\"> "
      << "<span id=\"clock\">0.000 s</span></div>\n"
      << "<svg id=\"table\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width / 2.5 << "\" height=\""
      << height / 2.5 << "\" viewBox=\"0 0 " << width << " " << height << "\">\n"
      << table_svg(shot, margin);
  for (std::size_t i = 0; i < n; ++i) {
    out << "<circle id=\"ball-" << i << "\" r=\"" << 1000 * R << "\" fill=\"" << shot_detail::colour(shot, i)
        << "\" stroke=\"#000000\" stroke-width=\"1.5\"/>\n";
  }
  out << "</svg>\n<script id=\"shot-data\" type=\"application/json\">" << data.str() << "</script>\n"
      << R"js(<script>
"use strict";
const shot = JSON.parse(document.getElementById("shot-data").textContent);
const slider = document.getElementById("time");
const clock = document.getElementById("clock");
function show(k) {
  k = Math.max(0, Math.min(shot.times.length - 1, k));
  slider.value = k;
  clock.textContent = shot.times[k].toFixed(3) + " s";
  shot.balls.forEach((ball, i) => {
    const circle = document.getElementById("ball-" + i);
    const x = ball.x[k], y = ball.y[k];
    circle.setAttribute("cx", (1000 * (x + shot.margin)).toFixed(2));
    circle.setAttribute("cy", (1000 * (shot.width + shot.margin - y)).toFixed(2));
    circle.setAttribute("data-x", String(x));
    circle.setAttribute("data-y", String(y));
    circle.setAttribute("visibility", ball.pocketed[k] ? "hidden" : "visible");
  });
  document.body.setAttribute("data-time", String(shot.times[k]));
}
function at(seconds) {
  let k = 0;
  while (k + 1 < shot.times.length && shot.times[k + 1] <= seconds) ++k;
  return k;
}
slider.addEventListener("input", () => show(Number(slider.value)));
let timer = null;
document.getElementById("play").addEventListener("click", () => {
  if (timer !== null) { clearInterval(timer); timer = null; return; }
  if (Number(slider.value) >= shot.times.length - 1) show(0);
  const start = performance.now() - 1000 * shot.times[Number(slider.value)];
  timer = setInterval(() => {
    const k = at((performance.now() - start) / 1000);
    show(k);
    if (k >= shot.times.length - 1) { clearInterval(timer); timer = null; }
  }, 1000 / 60);
});
const hash = /^#t=([0-9.eE+-]+)$/.exec(window.location.hash);
show(hash ? at(Number(hash[1])) : 0);
</script>
</body>
</html>
)js";
  return out.str();
}

}  // namespace billiards::io
