#include "tendril/envs/sma_limb/reach_observation.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::envs::sma_limb {

void write_reach_observation(const HistoryWindows& windows, int env,
                             const Eigen::Vector2d& throttles, const Eigen::Vector4d& goal,
                             const PowerProxy* power, int history,
                             Eigen::Ref<Eigen::VectorXf> out) {
  const int base = power != nullptr ? 14 : 10;
  require(out.size() == base + 6 * history && history <= windows.length(),
          "observation buffer of the wrong size", "envs::sma_limb::write_reach_observation");
  out.head<4>() = windows.state(env);
  out.segment<2>(4) = throttles.cast<float>();
  out.segment<4>(6) = goal.cast<float>();
  if (power != nullptr) out.segment<4>(10) = power->power().cast<float>();
  const int length = windows.length(), row = windows.row_size();
  const auto window = windows.windows().row(env);
  for (int h = 0; h < history; ++h) {
    const int k = length - history + h;
    auto slot = out.segment(base + 6 * h, 6);
    slot.head<4>() = window.segment(k * row, 4).transpose();
    if (k > 0) {
      slot.tail<2>() = window.segment((k - 1) * row + 4, 2).transpose();
    } else {
      slot.tail<2>().setZero();
    }
  }
  if (!out.allFinite()) out = out.unaryExpr([](float v) { return std::isfinite(v) ? v : 0.0f; });
}

ReachObserver::ReachObserver(const LearnedReachOptions& options)
    : options_(options),
      windows_(1, std::max(options.history, 1), 4, 2),
      power_(options.power),
      next_(BatchMatrix::Zero(1, 4)) {
  options_.validate("envs::sma_limb::ReachObserver");
}

void ReachObserver::reset(const Eigen::Vector4d& state) {
  windows_.reset(0, state.cast<float>());
  power_.reset();
  throttles_.setZero();
}

void ReachObserver::apply(const Eigen::Vector2d& throttles) {
  throttles_ = throttles;
  windows_.set_input(0, throttles.cast<float>());
  power_.update(throttles.x(), throttles.y());
}

void ReachObserver::reached(const Eigen::Vector4d& state) {
  next_.row(0) = state.cast<float>().transpose();
  windows_.advance(next_);
}

void ReachObserver::observe(const Eigen::Vector4d& goal, Eigen::Ref<Eigen::VectorXf> out) const {
  write_reach_observation(windows_, 0, throttles_, goal, options_.power_proxy ? &power_ : nullptr,
                          options_.history, out);
}

}  // namespace tendril::envs::sma_limb
