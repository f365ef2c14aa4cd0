#include "tendril/envs/sma_limb/linear_limb_model.hpp"

#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs::sma_limb {

LinearLimbModel::LinearLimbModel(int window) : window_(window) {
  require(window >= 1, "window must be >= 1, got " + std::to_string(window),
          "sma_limb::LinearLimbModel");
}

void LinearLimbModel::predict(const BatchMatrix& windows, BatchMatrix& next_states) {
  constexpr int kRow = 6;
  require(windows.cols() == static_cast<Eigen::Index>(window_) * kRow,
          "windows of " + std::to_string(windows.cols()) + " values, not " +
              std::to_string(window_ * kRow),
          "sma_limb::LinearLimbModel");
  next_states.resize(windows.rows(), 4);
  const Eigen::Index newest = static_cast<Eigen::Index>(window_ - 1) * kRow;
  const double w = kNaturalFrequency;
  for (Eigen::Index i = 0; i < windows.rows(); ++i) {
    for (int axis = 0; axis < 2; ++axis) {
      const double angle = windows(i, newest + axis);
      const double velocity = windows(i, newest + 2 + axis);
      const double throttle = windows(i, newest + 4 + axis);
      const double next_velocity =
          velocity + kPeriod * (w * w * (kGain * throttle - angle) - 2.0 * w * velocity);
      next_states(i, 2 + axis) = static_cast<float>(next_velocity);
      next_states(i, axis) = static_cast<float>(angle + kPeriod * next_velocity);
    }
  }
}

}  // namespace tendril::envs::sma_limb
