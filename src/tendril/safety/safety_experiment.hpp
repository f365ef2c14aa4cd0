#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/rl/trainer.hpp"
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
// draws with seed + 3. The run is the task experiment's (rl/trainer), so checkpoint_freq,
// --stop-at, Ctrl-C and `tendril resume` work as for any run.
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

// The co-trained safety agent of `experiment` as the companion of its task run (rl/trainer):
// built on the run's environments, acting through the training filter when enabled, learning
// from every step, carried in every checkpoint (so the run stops politely and resumes
// exactly), and written as safety.critic (load_safety_critic) when the run finishes. Its
// scalars join progress.csv as safety/...; `experiment` must outlive the run.
rl::CompanionFactory co_trained_safety_agent(const SafetyExperiment& experiment);

// rl::train of the task experiment with the co-trained safety agent: config.yaml,
// progress.csv, the event file, eval.csv, checkpoints/, model.policy and safety.critic.
rl::TrainResult train_with_safety(const SafetyExperiment& experiment,
                                  const std::filesystem::path& run_directory,
                                  rl::TrainOptions options = {});

}  // namespace tendril::safety
