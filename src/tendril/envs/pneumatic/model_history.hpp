#pragma once

#include <memory>

#include "tendril/envs/pneumatic/model_dynamics.hpp"
#include "tendril/envs/robot_history_model.hpp"

namespace tendril::envs::pneumatic {

// GPRCA's model F_φ (seed 002 §IV-C) over the learned model of PneumaticArm/LearnedReach-v0:
// ModelDynamics fed the arm's measured tips (mm), commands in the task's normalised units
// (a ∈ [−1, 1]⁹, p = 0.75 (a + 1) bar). Holds `model` by reference: its owner outlives it.
std::unique_ptr<RobotHistoryModel> model_history(ModelDynamics& model);

}  // namespace tendril::envs::pneumatic
