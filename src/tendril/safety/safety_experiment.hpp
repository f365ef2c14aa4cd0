#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/safety/co_trainer.hpp"
#include "tendril/safety/constraint.hpp"
#include "tendril/safety/safety_filter.hpp"

namespace tendril::safety {

// A task experiment (rl::Experiment's keys) with a safety agent co-trained beside it from the
// same rollouts (seed 001 §6.3.1), in one file:
//
//   algorithm: sac                 # the task agent, any rl algorithm
//   env: {id: Safety/DoubleIntegrator-v0, params: {...}}   # raw observations (no normalization)
//   algo: {...}
//   n_timesteps: 20000
//   seed: 0
//   safety:
//     algorithm: sac               # sac (Box actions) or dqn (Discrete)
//     algo: {...}                  # its keys; its gamma is the γ of r_safe (eq. 6.3)
//     buffer_size: 100000          # the gated buffer (SafetyCoTrainer)
//     learning_starts: 1000
//     train_freq: 1
//     gradient_steps: 1
//     unsafe_samples_per_step: 1   # eq. 6.6
//     training_filter: {enabled: false, epsilon: 0.0}   # who acts while co-training
//     eval: {episodes: 100, epsilon: 0.0, deterministic: true}   # ε₂ of eq. 6.5
//
// With `training_filter.enabled`, the task agent acts through the safety filter at that ε₂
// (FilteredVecEnv), with draws of the safety agent's exploring policy where the filter
// intervenes; otherwise the task agent alone acts, and the safety agent only watches. The thesis
// does not say which (§6.3.1); see configs/safety/ for the choice per environment.
//
// The safety agent is seeded with seed + 1, the co-trainer's draws with seed + 2, the filter's
// draws with seed + 3.
struct SafetyExperiment {
  rl::Experiment task;
  std::string safety_algorithm;
  Config safety_algo;
  double safety_gamma = 0.99;
  CoTrainingSettings co_training;
  bool training_filter = false;
  double training_filter_epsilon = 0.0;
  int eval_episodes = 100;
  double eval_epsilon = 0.0;
  bool eval_deterministic = true;

  // Reads and checks every key (the safety agent is built once on a probe environment), so a
  // bad file fails before anything is written.
  static SafetyExperiment from_config(Config config);
};

struct SafetyTrainResult {
  std::filesystem::path run_directory;
  double seconds = 0.0;
  int64_t stored_transitions = 0;  // in the gated safety buffer
  int64_t gated_transitions = 0;
  int64_t unsafe_entries = 0;
  double training_intervention_rate = 0.0;  // of the training filter's decisions (0 without)
};

// Trains the task agent with the co-trained safety agent into `run_directory` (which must not
// exist or be empty): config.yaml, progress.csv and the TensorBoard event file (the task
// agent's scalars, Stable-Baselines3's names, and the safety agent's as safety/...),
// model.policy (the task policy, rl::load_policy) and safety.critic (load_safety_critic).
// A live progress line goes to standard error unless `quiet`. No checkpoints: a run is not
// resumed.
SafetyTrainResult train_with_safety(const SafetyExperiment& experiment,
                                    const std::filesystem::path& run_directory, bool quiet = false);

}  // namespace tendril::safety
