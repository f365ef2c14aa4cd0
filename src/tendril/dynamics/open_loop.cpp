#include "tendril/dynamics/open_loop.hpp"

#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"
#include "tendril/envs/learned/history_windows.hpp"

namespace tendril::dynamics {

RowMatrixXd open_loop_inputs(const std::string& kind, int64_t steps, double amplitude,
                             int64_t period) {
  require(steps >= 0 && period >= 4 && period % 4 == 0,
          "needs steps >= 0 and a period that is a positive multiple of 4",
          "dynamics::open_loop_inputs");
  RowMatrixXd inputs(steps, 2);
  const double p = static_cast<double>(period);
  auto ramp = [&](int64_t k) { return -1.0 + 2.0 * static_cast<double>(k % period) / p; };
  for (int64_t k = 0; k < steps; ++k) {
    const double phase = 2.0 * std::numbers::pi * static_cast<double>(k) / p;
    if (kind == "sine") {
      inputs.row(k) << std::sin(phase), std::cos(phase);
    } else if (kind == "square") {
      const int64_t quarter = (k % period) / (period / 4);
      const double signs[4][2] = {{1, 1}, {1, -1}, {-1, -1}, {-1, 1}};
      inputs.row(k) << signs[quarter][0], signs[quarter][1];
    } else if (kind == "sawtooth") {
      inputs.row(k) << ramp(k), ramp(k + period / 4);
    } else {
      throw Error("unknown open-loop input '" + kind + "' (expected sine, square or sawtooth)",
                  "dynamics::open_loop_inputs");
    }
  }
  return inputs * amplitude;
}

RowMatrixXd open_loop_rollout(Model& model, const Eigen::VectorXd& state,
                              const RowMatrixXd& inputs) {
  require(state.size() == model.state_dim() && inputs.cols() == model.input_dim(),
          "state or inputs do not match the model's sizes", "dynamics::open_loop_rollout");
  envs::HistoryWindows windows(1, model.window_length(), model.state_dim(), model.input_dim());
  windows.reset(0, state.cast<float>());
  RowMatrixXd trajectory(inputs.rows() + 1, model.state_dim());
  trajectory.row(0) = state.transpose();
  envs::BatchMatrix input(1, model.input_dim()), next;
  for (Eigen::Index k = 0; k < inputs.rows(); ++k) {
    input.row(0) = inputs.row(k).cast<float>();
    model.step(windows, input, next);
    trajectory.row(k + 1) = next.row(0).cast<double>();
  }
  return trajectory;
}

}  // namespace tendril::dynamics
