#pragma once

#include <filesystem>
#include <string>

#include "tendril/core/config.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/safety/cost_critic.hpp"
#include "tendril/safety/lagrangian_penalty.hpp"

namespace tendril::safety {

// A SAC task experiment (rl::Experiment's keys) trained with a constrained baseline of seed 001
// Table 6.1 (LagrangianPenalty), in one file:
//
//   algorithm: sac
//   env: {id: Safety/DubinsCar-v0, params: {...}}
//   algo: {...}
//   n_timesteps: 100000
//   seed: 0
//   constrained:
//     method: lagrangian             # lagrangian (LR) or rspo
//     cost_limit: 0.1                # ε_risk, on Q_risk ∈ [0, 1]
//     cost_critic: {gamma: 0.9, net_arch: [64, 64], learning_rate: 3.0e-4, tau: 0.005,
//                   buffer_size: 100000, batch_size: 128, learning_starts: 1000}
//     multiplier: {initial: 1.0, learning_rate: 1.0e-3}   # rspo: {start: 100.0, end: 0.0}
//
// The cost critic is seeded with seed + 1.
struct ConstrainedExperiment {
  rl::Experiment task;
  std::string method;
  double cost_limit = 0.1;
  CostCriticSettings cost_critic;
  MultiplierSettings multiplier;

  // Reads and checks every key; the environment must report a "cost" info and have a Box
  // action space.
  static ConstrainedExperiment from_config(Config config);
};

struct ConstrainedTrainResult {
  std::filesystem::path run_directory;
  double seconds = 0.0;
  double final_multiplier = 0.0;
  double final_cost_value = 0.0;  // E[Q_risk(s, π(s))] of the last actor step
};

// Trains into `run_directory` (which must not exist or be empty): config.yaml, progress.csv and
// the event file (with lagrangian/multiplier, lagrangian/cost_value and
// lagrangian/cost_critic_loss), model.policy. A progress line unless `quiet`.
ConstrainedTrainResult train_constrained(const ConstrainedExperiment& experiment,
                                         const std::filesystem::path& run_directory,
                                         bool quiet = false);

}  // namespace tendril::safety
