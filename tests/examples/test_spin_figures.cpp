// The figures' library of examples/: the SVG line plot (plot.hpp) and the spinning-ball curves
// (spin_curves.hpp) against the closed forms written here again by hand.
#include <billiards/io/plot.hpp>
#include "spin_curves.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

using namespace billiards::io;
using namespace billiards::programs;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t found = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++found;
  return found;
}

}  // namespace

TEST_CASE("line_plot_svg draws each series, escapes text and rejects bad axes", "[examples][plot]") {
  const Axis x{"x <a & b>", 0, 10, 2}, y{"y", -1, 1, 0.5};
  const std::vector<Series> series{{"line", "#ff0000", Series::Style::line, {{0, 0}, {5, 1}, {10, -1}}},
                                   {"dots", "#0000ff", Series::Style::markers, {{1, 0.5}, {2, 0.25}}},
                                   {"", "#00ff00", Series::Style::dashed, {{0, 1}, {10, 1}}}};
  const std::string svg = line_plot_svg("a \"title\"", x, y, series, {"note"});
  SECTION("a well-formed document with the title and labels escaped") {
    CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
    CHECK(svg.substr(svg.size() - 7) == "</svg>\n");
    CHECK(svg.find("<title>a &quot;title&quot;</title>") != std::string::npos);
    CHECK(svg.find("x &lt;a &amp; b&gt;") != std::string::npos);
    CHECK(svg.find("<a & b>") == std::string::npos);
  }
  SECTION("lines as polylines, markers as circles, a legend entry per labelled series") {
    CHECK(count(svg, "<polyline") == 2);
    CHECK(count(svg, "stroke-dasharray") == 1);
    CHECK(count(svg, "<circle") == 2 + 1);  // two markers and the legend's
    CHECK(count(svg, ">line</text>") == 1);
    CHECK(count(svg, ">dots</text>") == 1);
    CHECK(count(svg, ">note</text>") == 1);
  }
  SECTION("ticks at every step, the last one included") {
    for (const char* tick :
         {">0</text>", ">2</text>", ">10</text>", ">-1</text>", ">-0.5</text>", ">1</text>"}) {
      CHECK(svg.find(tick) != std::string::npos);
    }
  }
  SECTION("the same series give the same bytes") {
    CHECK(line_plot_svg("a \"title\"", x, y, series, {"note"}) == svg);
  }
  SECTION("an axis with no range, a NaN or too many ticks is rejected, naming it") {
    const double nan = std::nan("");
    for (const Axis& bad : {Axis{"bad", 1, 1, 0.1}, Axis{"bad", 0, nan, 0.1}, Axis{"bad", 0, 1, 0},
                            Axis{"bad", 0, 1, 1e-3}, Axis{"bad", 0, 1, -1}}) {
      CHECK_THROWS_WITH(line_plot_svg("t", bad, y, series), Catch::Contains("axis 'bad'"));
      CHECK_THROWS_AS(line_plot_svg("t", x, bad, series), std::invalid_argument);
    }
  }
}

TEST_CASE("The figures' curves through the runtime are the closed forms", "[examples][spin]") {
  const double pi = std::acos(-1.0), degree = pi / 180;
  for (int degrees = 1; degrees <= 89; ++degrees) {
    const double phi = degrees * degree, s = std::sin(phi), c = std::cos(phi);
    INFO("cut " << degrees << "°");
    for (const double mu : {0.03, 0.06, 0.09}) {
      CHECK(stun_shot_throw(phi, mu) == Approx(std::atan(std::min(mu, std::tan(phi) / 7))).epsilon(1e-12));
    }
    CHECK(thirty_degree_deflection(phi) == Approx(std::atan2(s * c, s * s + 0.4)).epsilon(1e-12));
  }
  // With restitution e the throw's slope is 2 tan φ/(7(1 + e)) below the friction limit.
  CHECK(stun_shot_throw(10 * degree, 0.1, 0.5) == Approx(std::atan(2 * std::tan(10 * degree) / (7 * 1.5))));
  CHECK_THROWS_AS(stun_shot_throw(10 * degree, -0.1), billiards::invalid_argument);
}
