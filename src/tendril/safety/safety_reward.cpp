#include "tendril/safety/safety_reward.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::safety {

SafetyReward::SafetyReward(double gamma) : gamma_(gamma) {
  require(gamma > 0.0 && gamma < 1.0, "gamma must lie in (0, 1)", "SafetyReward");
}

double SafetyReward::level(double margin, double max_margin) {
  require(max_margin > 0.0, "the largest safety margin must be positive", "SafetyReward::level");
  return std::min(margin / max_margin, 1.0);
}

double SafetyReward::reward(double level_x, int64_t time_step, bool unsafe,
                            bool next_unsafe) const {
  if (unsafe) return -1.0;
  if (next_unsafe) {
    return -1.0 / (std::pow(gamma_, static_cast<double>(time_step)) * (1.0 - gamma_));
  }
  return level_x;
}

double SafetyReward::safe_value_bound(int64_t horizon) const {
  return (1.0 - std::pow(gamma_, static_cast<double>(horizon + 1))) / (1.0 - gamma_);
}

double SafetyReward::irrecoverable_value_bound() const { return -(1.0 + gamma_) / (1.0 - gamma_); }

double SafetyReward::unsafe_value(int64_t horizon) const { return -safe_value_bound(horizon); }

}  // namespace tendril::safety
