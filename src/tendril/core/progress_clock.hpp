#pragma once

#include <chrono>
#include <string>

namespace tendril {

// "1m05s", "2h03m": a duration for progress lines.
std::string duration_text(double seconds);

// The wall clock of a long task since it started, and the time left extrapolated from the share
// done so far (the progress lines of training, model fits, data collection and calibration).
class ProgressClock {
 public:
  ProgressClock() : start_(std::chrono::steady_clock::now()) {}
  double elapsed_s() const;
  // "elapsed 0m12s, ETA 0m48s" after `done` of the work (0 to 1); no ETA before any is done.
  std::string text(double done) const { return text(done, elapsed_s()); }
  static std::string text(double done, double elapsed_s);

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace tendril
