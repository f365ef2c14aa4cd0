#pragma once

#include <cstdint>

#include "tendril/adapt/adaptation_log.hpp"
#include "tendril/adapt/gprca.hpp"
#include "tendril/adapt/reaching_robot.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::adapt {

// What the compensator's GP reads (seed 002 §IV-C: "the action proposed by π_θ"):
//   command  the command the policy's action leads to (the pressures the robot receives) —
//            the default, a choice: with delta actions (§IV-A) the error depends on where the
//            arm is driven, which the held command says and the step does not
//   delta    the policy's action itself
enum class CompensatorInput { command, delta };

struct GprcaTrialsOptions {
  int max_trials = 15;
  int steps_per_trial = 100;  // L_E: 100 in S0–S1, 150 in S2–S4 (seed 002 §V-C2, V-D2)
  // Trials run after the goal flag is raised (the compensator keeps learning, §VI).
  int trials_after_goal = 0;
  // Search the hyper-parameters after every trial, while the robot is reset.
  bool search_between_trials = true;
  CompensatorInput input = CompensatorInput::command;
  CompensationOptions compensator;  // its steps_per_episode is set from steps_per_trial
};

// GPRCA on a robot (seed 002 Alg. 2): trials of the trained policy π_θ acting on the
// compensated observation s_t = x_t + c_t, the compensator G retrained every n_B steps on
// e_{t+1} = x̂_{t+1} − x_{t+1} (x̂ from `model` fed the robot's real history), until a trial
// ends at the goal (G_f) — then `trials_after_goal` more — or `max_trials` ran. A trial ends
// at the goal, at a collision, or after steps_per_trial steps. The first trial starts from a
// reset seeded with `seed`, later ones continue the robot's random streams (the resting drift
// walks on between trials). Goal and collision are judged on the measured state.
AdaptationResult run_gprca(ReachingRobot& robot, RobotHistoryModel& model, const rl::Policy& policy,
                           const GprcaTrialsOptions& options, uint64_t seed);

}  // namespace tendril::adapt
