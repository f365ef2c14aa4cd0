#include "tendril/core/progress_clock.hpp"

#include <algorithm>
#include <cstdio>

namespace tendril {

std::string duration_text(double seconds) {
  const auto total = static_cast<long long>(std::max(seconds, 0.0) + 0.5);
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof text, "%lldh%02lldm", total / 3600, total / 60 % 60);
  } else {
    std::snprintf(text, sizeof text, "%lldm%02llds", total / 60, total % 60);
  }
  return text;
}

double ProgressClock::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string ProgressClock::text(double done, double elapsed) {
  std::string line = "elapsed " + duration_text(elapsed);
  if (done > 0.0) line += ", ETA " + duration_text(elapsed * (1.0 - std::min(done, 1.0)) / done);
  return line;
}

}  // namespace tendril
