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
//     eval: {episodes: 100, epsilon: 0.0, deterministic: true}   # ε₂ of eq. 6.5
//
// The safety agent is seeded with seed + 1, the co-trainer's draws with seed + 2.
struct SafetyExperiment {
  rl::Experiment task;
  std::string safety_algorithm;
  Config safety_algo;
  double safety_gamma = 0.99;
  CoTrainingSettings co_training;
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
};

// Trains the task agent with the co-trained safety agent into `run_directory` (which must not
// exist or be empty): config.yaml, model.policy (the task policy, rl::load_policy) and
// safety.critic (load_safety_critic).
SafetyTrainResult train_with_safety(const SafetyExperiment& experiment,
                                    const std::filesystem::path& run_directory);

// Returns and safety of `episodes` episodes (reset seeds seed, seed + 1, ...). An episode is
// safe when none of its observations, the first included, lies in X_unsafe.
struct SafetyEvaluation {
  int episodes = 0;
  double mean_return = 0.0;
  double std_return = 0.0;
  double safety_rate = 0.0;        // fraction of safe episodes
  double intervention_rate = 0.0;  // of the filter's decisions (0 without a filter)
};
SafetyEvaluation evaluate_safety(Env& env, const Constraint& constraint, const TaskActor& actor,
                                 int episodes, uint64_t seed);

// A run of train_with_safety evaluated on the same episodes without and with the filter at ε₂;
// a run of `tendril train` (no safety.critic, e.g. the reward-penalty baseline) without it.
// Returns are the task reward's: an environment's `unsafe_penalty` is set to 0 for this.
struct RunSafetyEvaluation {
  double epsilon = 0.0;
  SafetyEvaluation unfiltered;
  std::optional<SafetyEvaluation> filtered;
};
RunSafetyEvaluation evaluate_safety_run(const std::filesystem::path& run_directory, double epsilon,
                                        int episodes, uint64_t seed);

}  // namespace tendril::safety
