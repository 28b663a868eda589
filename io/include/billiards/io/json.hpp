/// \file
/// Numbers as billiards::io's JSON and CSV write them.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace billiards::io {

/// A number as JSON: 17 significant digits (read back bit for bit), null where it is not finite.
inline std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

}  // namespace billiards::io
