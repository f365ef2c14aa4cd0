#pragma once

#include <charconv>
#include <cmath>
#include <string>

namespace tendril::envs::pneumatic {

// The shortest decimal text that reads back as exactly `value` (std::to_chars).
inline std::string shortest_text(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

// `value` rounded to 1/scale (scale a power of ten, e.g. 1e3 for thousandths). Dividing the
// rounded count by the scale gives the double nearest the decimal, whose shortest text is short.
inline double rounded(double value, double scale) { return std::round(value * scale) / scale; }

}  // namespace tendril::envs::pneumatic
