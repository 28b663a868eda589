// billiards-spin-figures: the figures of the spinning-ball model, computed through billiards::runtime
// (spin_curves.hpp) and drawn beside the closed forms they are known by:
//   throw.svg               the stun-shot throw against the cut angle for three friction coefficients
//                           (collide_with_friction against TP A-14's atan(min(μ, tan φ/7)))
//   thirty_degree_rule.svg  the rolling cue ball's deflection against the cut angle
//                           (collide_with_friction with μ = 0 and evolve against the 30° rule)
//
//   billiards-spin-figures [--out FOLDER]      (default: the current folder)
//
// It prints, per curve, the largest difference between the runtime and the closed form, and the
// 30° curve's maximum. Exit status: 0 on success; 1 when the runtime differs from a closed form by more
// than 1e-9 degrees; 2 on a bad command line; 3 when a figure cannot be written.
#include <billiards/io/plot.hpp>
#include "spin_curves.hpp"

#include <billiards/io/atomic_file.hpp>
#include <billiards_support/cli_checks.hpp>
#include <billiards_support/standard_output.hpp>

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace billiards::io;
using namespace billiards::programs;

constexpr double degree = 3.14159265358979323846 / 180;
constexpr double allowed_degrees = 1e-9;  // the runtime against the closed forms

// Parses the command line into `out`; an exit status where the program ends here.
std::optional<int> parse(int argc, char** argv, std::string& out) {
  CLI::App app{"Draws the throw and 30-degree-rule figures of the spinning-ball model as SVG.",
               "billiards-spin-figures"};
  app.add_option("--out", out, "Folder the two SVG files are written to (default: the current folder)");
  if (const std::optional<int> code = billiards_support::parse_command_line(app, argc, argv)) return code;
  std::error_code folder_error;
  if (!std::filesystem::is_directory(out, folder_error)) {
    std::cerr << "billiards-spin-figures: --out: '" << out
              << "' is not a folder, expected an existing folder\n";
    return 2;
  }

  return std::nullopt;
}

// The throw: the closed form every quarter degree, the runtime every 2°, for three μ around the 0.06
// Alciatore measured for pool balls; `agrees` false where they differ by more than allowed_degrees.
std::vector<Series> throw_series(bool& agrees) {
  const struct {
    double friction;
    const char* colour;
  } frictions[] = {{0.03, "#2e86c1"}, {0.06, "#c0392b"}, {0.09, "#27ae60"}};
  // One line per μ; the legend names the two kinds once (entries without points).
  std::vector<Series> throw_series{
      {"lines: TP A-14, atan(min(μ, tan φ/7))", "#555555", Series::Style::line, {}},
      {"circles: billiards::collide_with_friction", "#555555", Series::Style::markers, {}}};
  for (const auto& [friction, colour] : frictions) {
    std::ostringstream label;
    label << "μ = " << friction;
    Series formula{label.str(), colour, Series::Style::line, {}};
    Series runtime{"", colour, Series::Style::markers, {}};
    for (int quarter = 1; quarter < 360; ++quarter) {
      const double phi = quarter * degree / 4;
      formula.points.emplace_back(quarter / 4.0, stun_shot_throw_formula(phi, friction) / degree);
    }
    double largest = 0;
    for (int degrees = 2; degrees <= 88; degrees += 2) {
      const double phi = degrees * degree;
      const double thrown = stun_shot_throw(phi, friction) / degree;
      runtime.points.emplace_back(degrees, thrown);
      largest = std::max(largest, std::fabs(thrown - stun_shot_throw_formula(phi, friction) / degree));
    }
    std::printf("throw, mu = %g: largest difference from atan(min(mu, tan(phi)/7)) %.2e degrees\n", friction,
                largest);
    agrees = agrees && largest <= allowed_degrees;
    throw_series.push_back(std::move(formula));
    throw_series.push_back(std::move(runtime));
  }

  return throw_series;
}

// The 30° rule: the closed form every tenth of a degree (its maximum found on that grid), the runtime
// every 2°, the 30° line, and a note of the maximum.
std::vector<Series> thirty_degree_series(bool& agrees, std::string& note) {
  Series formula{"atan(sin φ cos φ/(sin² φ + 2/5))", "#c0392b", Series::Style::line, {}};
  Series runtime{"collide_with_friction (μ = 0) and evolve", "#17202a", Series::Style::markers, {}};
  double peak = 0, peak_at = 0;
  for (int tenth = 1; tenth < 900; ++tenth) {
    const double theta = thirty_degree_formula(tenth * degree / 10) / degree;
    formula.points.emplace_back(tenth / 10.0, theta);
    if (theta > peak) peak = theta, peak_at = tenth / 10.0;
  }
  double largest = 0;
  for (int degrees = 2; degrees <= 88; degrees += 2) {
    const double theta = thirty_degree_deflection(degrees * degree) / degree;
    runtime.points.emplace_back(degrees, theta);
    largest = std::max(largest, std::fabs(theta - thirty_degree_formula(degrees * degree) / degree));
  }
  std::printf(
      "30-degree rule: largest difference from the closed form %.2e degrees; maximum %.2f degrees at "
      "a cut of %.1f degrees\n",
      largest, peak, peak_at);
  agrees = agrees && largest <= allowed_degrees;
  std::ostringstream peak_note;
  peak_note << std::fixed << std::setprecision(2) << "maximum " << peak << "° at a cut of "
            << std::setprecision(1) << peak_at << "°";
  const Series thirty{"30°", "#7f8c8d", Series::Style::dashed, {{0, 30}, {90, 30}}};

  note = peak_note.str();
  return {formula, runtime, thirty};
}

// Writes both figures into `out`; an exit status where one cannot be written.
std::optional<int> write(const std::string& out, const std::vector<Series>& throw_series,
                         const std::vector<Series>& thirty_series, const std::string& note) {
  const Axis cut{"cut angle φ (degrees)", 0, 90, 10};
  const std::filesystem::path folder(out);
  try {
    const auto throw_path = folder / "throw.svg", thirty_path = folder / "thirty_degree_rule.svg";
    billiards::io::write_file_atomically(
        throw_path, line_plot_svg("Throw of a stun shot (e = 1): object ball off the line of centres", cut,
                                  Axis{"throw angle (degrees)", 0, 8, 1}, throw_series));
    std::printf("wrote %s\n", throw_path.c_str());
    billiards::io::write_file_atomically(
        thirty_path,
        line_plot_svg("The 30° rule: a rolling cue ball's deflection once it rolls again", cut,
                      Axis{"deflection θ (degrees)", 0, 45, 5}, thirty_series, {note}, Legend::top_right));
    std::printf("wrote %s\n", thirty_path.c_str());
  } catch (const std::runtime_error& error) {
    std::cerr << "billiards-spin-figures: " << error.what() << "\n";
    return 3;
  }
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".";
  if (const std::optional<int> code = parse(argc, argv, out)) return *code;
  bool agrees = true;
  const std::vector<Series> throws = throw_series(agrees);
  std::string note;
  const std::vector<Series> thirty = thirty_degree_series(agrees, note);
  if (const std::optional<int> code = write(out, throws, thirty, note)) return *code;
  if (billiards_support::standard_output_failed("billiards-spin-figures")) return 3;
  if (!agrees) {
    std::cerr << "billiards-spin-figures: the runtime differs from a closed form by more than "
              << allowed_degrees << " degrees\n";
    return 1;
  }
  return 0;
}
