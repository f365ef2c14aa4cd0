#pragma once

#include <string>

#include "tendril/core/progress_clock.hpp"

namespace tendril::dynamics {

// A progress line on standard error for the row of a model's evaluation being measured: its
// share done, elapsed time and ETA, at most once a second; a row measured in under a second
// prints none. Used as an EvaluationObserver's on_progress (fit_run.hpp).
class EvaluationProgress {
 public:
  void operator()(const std::string& metric, double horizon, double done);
  // Ends the row's progress line, if one was printed.
  void finish();

 private:
  std::string metric_;
  double horizon_ = 0.0;
  ProgressClock clock_;
  double last_print_s_ = -1.0;
};

}  // namespace tendril::dynamics
