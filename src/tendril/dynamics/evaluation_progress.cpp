#include "tendril/dynamics/evaluation_progress.hpp"

#include <cstdio>

namespace tendril::dynamics {

void EvaluationProgress::operator()(const std::string& metric, double horizon, double done) {
  if (metric != metric_ || horizon != horizon_) {
    finish();
    metric_ = metric;
    horizon_ = horizon;
    clock_ = ProgressClock();
  }
  const double now = clock_.elapsed_s();
  if (now < 1.0 || (last_print_s_ >= 0.0 && now - last_print_s_ < 1.0 && done < 1.0)) return;
  last_print_s_ = now;
  const std::string eta = clock_.text(done);
  if (metric.find("rollout") != std::string::npos) {
    std::fprintf(stderr, "\r  measuring %s %gs: %.1f%%  %s   ", metric.c_str(), horizon,
                 100.0 * done, eta.c_str());
  } else {
    std::fprintf(stderr, "\r  measuring %s: %.1f%%  %s   ", metric.c_str(), 100.0 * done,
                 eta.c_str());
  }
  std::fflush(stderr);
}

void EvaluationProgress::finish() {
  if (last_print_s_ >= 0.0) std::fputc('\n', stderr);
  last_print_s_ = -1.0;
}

}  // namespace tendril::dynamics
