/// \file
/// Numbers as billiards::io writes them: every digit, in text files and in JSON.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace billiards::io {

/// A number with 17 significant digits (%.17g): read back, the same double, bit for bit.
inline std::string digits17(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

/// A number as JSON: digits17, null where it is not finite.
inline std::string json_number(double x) { return std::isfinite(x) ? digits17(x) : "null"; }

}  // namespace billiards::io
