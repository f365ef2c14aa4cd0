#include "tendril/envs/pneumatic/linear_arm_model.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs::pneumatic {

LinearArmModel::LinearArmModel(int window) : window_(window) {
  require(window >= 1, "window must be >= 1, got " + std::to_string(window),
          "pneumatic::LinearArmModel");
}

TipVector LinearArmModel::rest() {
  TipVector tips;
  tips << 0.0, 0.0, -199.3, 0.0, 0.0, -398.6, 0.0, 0.0, -597.9;
  return tips;
}

TipVector LinearArmModel::steady_state(const ChamberVector& pressures_bar) {
  TipVector tips = rest();
  for (int module = 0; module < 3; ++module) {
    for (int chamber = 0; chamber < 3; ++chamber) {
      const double p = pressures_bar[3 * module + chamber];
      const double angle = chamber * 2.0 * std::numbers::pi / 3.0;
      for (int below = module; below < 3; ++below) {
        const double span = below - module + 1;
        tips[3 * below] -= kBend * span * p * std::cos(angle);
        tips[3 * below + 1] -= kBend * span * p * std::sin(angle);
        tips[3 * below + 2] -= kExtension * p;
      }
    }
  }
  return tips;
}

void LinearArmModel::predict(const BatchMatrix& windows, BatchMatrix& next_states) {
  constexpr int kRow = 18;
  require(windows.cols() == static_cast<Eigen::Index>(window_) * kRow,
          "windows of " + std::to_string(windows.cols()) + " values, not " +
              std::to_string(window_ * kRow),
          "pneumatic::LinearArmModel");
  next_states.resize(windows.rows(), 9);
  const Eigen::Index newest = static_cast<Eigen::Index>(window_ - 1) * kRow;
  const double beta = 1.0 - std::exp(-kPeriod / kLag);
  for (Eigen::Index i = 0; i < windows.rows(); ++i) {
    const TipVector tips = windows.row(i).segment(newest, 9).transpose().cast<double>();
    const ChamberVector pressures =
        windows.row(i).segment(newest + 9, 9).transpose().cast<double>();
    const TipVector next = tips + beta * (steady_state(pressures) - tips);
    next_states.row(i) = next.transpose().cast<float>();
  }
}

}  // namespace tendril::envs::pneumatic
