#pragma once

#include <cstdio>
#include <string>

namespace tendril::adapt {

// A value as error messages show it: six significant digits, "nan" and "inf" as such.
inline std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace tendril::adapt
