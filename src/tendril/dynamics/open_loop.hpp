#pragma once

#include "tendril/dynamics/model.hpp"
#include "tendril/dynamics/sequence_data.hpp"

namespace tendril::dynamics {

// The model driven open loop by `inputs` (steps × d_u, e.g. envs::sma_limb::open_loop_inputs)
// from rest in `state` (every history row [state, 0]): rows x_0 = state, x̂_1, …, x̂_steps.
RowMatrixXd open_loop_rollout(Model& model, const Eigen::VectorXd& state,
                              const RowMatrixXd& inputs);

}  // namespace tendril::dynamics
