#pragma once

#include <filesystem>
#include <string>

#include "tendril/core/config.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/rl/trainer.hpp"
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

// The cost critic and multiplier of `experiment` as the companion of its SAC run (rl/trainer):
// the penalty installed in SAC's actor loss, both learning from every step, carried in every
// checkpoint (the run stops politely and resumes exactly), their scalars in progress.csv as
// lagrangian/multiplier, lagrangian/cost_value and lagrangian/cost_critic_loss. The cost critic
// is seeded with seed + 1; `experiment` must outlive the run.
rl::CompanionFactory constrained_baseline(const ConstrainedExperiment& experiment);

// rl::train of the task experiment with that companion: config.yaml, progress.csv, the event
// file, eval.csv, checkpoints/ and model.policy.
rl::TrainResult train_constrained(const ConstrainedExperiment& experiment,
                                  const std::filesystem::path& run_directory,
                                  rl::TrainOptions options = {});

}  // namespace tendril::safety
