#include "tendril/dynamics/open_loop.hpp"

#include "tendril/core/error.hpp"
#include "tendril/envs/learned/history_windows.hpp"

namespace tendril::dynamics {

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
