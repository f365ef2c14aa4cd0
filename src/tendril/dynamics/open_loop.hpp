#pragma once

#include <string>

#include "tendril/dynamics/model.hpp"
#include "tendril/dynamics/sequence_data.hpp"

namespace tendril::dynamics {

// Seed 001's open-loop test inputs (thesis Fig. 4.4; [CODE] hardware_exp trajectories: 800 steps
// each, published at 20 Hz ⇒ 40 s), as two throttles (x, y), scaled by `amplitude` (10: full
// throttle), for step k = 0 … steps − 1 with period P = 800:
//   sine      (sin 2πk/P, cos 2πk/P)              one circle per period
//   square    (+1, +1), (+1, −1), (−1, −1), (−1, +1) for P/4 steps each
//   sawtooth  x ramps from −1 by 2/P per step and wraps; y a quarter period ahead
RowMatrixXd open_loop_inputs(const std::string& kind, int64_t steps, double amplitude = 10.0,
                             int64_t period = 800);

// The model driven open loop by `inputs` (steps × d_u) from rest in `state` (every history row
// [state, 0]): rows x_0 = state, x̂_1, …, x̂_steps.
RowMatrixXd open_loop_rollout(Model& model, const Eigen::VectorXd& state,
                              const RowMatrixXd& inputs);

}  // namespace tendril::dynamics
