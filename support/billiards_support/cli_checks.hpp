// The command-line checks of the programs (the examples, billiards-accuracy), one definition for every
// program: counts and numbers are checked as text before conversion ("-1" must not wrap to 2^64 − 1;
// NaN and infinities are rejected by name), and each error names the value and what was expected.
#pragma once

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <limits>
#include <string>

namespace billiards_support {

/// A whole number of at least `smallest` and at most `largest` (2^64 − 1 unless given).
inline CLI::Validator count_at_least(std::uint64_t smallest,
                                     std::uint64_t largest = std::numeric_limits<std::uint64_t>::max()) {
  return CLI::Validator(
      [smallest, largest](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        const std::string quoted = "'" + text.substr(0, 40) + (text.size() > 40 ? "…'" : "'");
        if (text.empty() || end != text.data() + text.size() || error == std::errc::invalid_argument) {
          return quoted + " is not a whole number, expected one of at least " + std::to_string(smallest);
        }
        if (error == std::errc::result_out_of_range) return quoted + " is larger than 2^64 - 1";
        if (value < smallest) return quoted + " is less than " + std::to_string(smallest);
        if (value > largest) return quoted + " is more than " + std::to_string(largest);
        return {};
      },
      "COUNT");
}

/// A finite number, positive (`positive`) or at least zero.
inline CLI::Validator finite_number(bool positive) {
  return CLI::Validator(
      [positive](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        const bool in_range = positive ? value > 0 : value >= 0;
        if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) || !in_range) {
          return "'" + text.substr(0, 40) + (text.size() > 40 ? "…'" : "'") + " is not a " +
                 (positive ? "positive" : "non-negative") + " finite number";
        }
        return {};
      },
      positive ? "NUMBER > 0" : "NUMBER >= 0");
}

/// A path given as a value: not empty. An empty value would otherwise read as the option not given
/// (no SVG written, the random table run) or fail later with a message that names no option.
/// `expected` says what the path names: "a file's path", "a folder's path".
inline CLI::Validator path_given(const std::string& expected) {
  return CLI::Validator(
      [expected](std::string& text) -> std::string {
        return text.empty() ? "the path is empty, expected " + expected : std::string();
      },
      "");
}

/// Parses the command line with `app`; the exit status where the program ends here: 0 after --help
/// (the usage printed), 2 after a usage error (one line on stderr: "NAME: what (run with --help for
/// usage)", NAME the app's name).
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::cerr << app.get_name() << ": " << error.what() << " (run with --help for usage)\n";
    return 2;
  }
  return std::nullopt;
}

}  // namespace billiards_support
