#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include "tendril/core/config.hpp"
#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/rl/algorithm.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {

// One experiment file (DESIGN.md, "Experiments and runs"), in the spirit of the RL Baselines3
// Zoo's hyper-parameter files:
//
//   algorithm: ppo                 # ppo | trpo | sac | td3 | ddpg | dqn
//   env:
//     id: Pendulum-v1
//     params: {g: 10.0}            # the environment's own parameters
//     wrappers:                    # around each copy, innermost first (wrapper_registry.hpp)
//       - history_stack: {length: 4}
//     n_envs: 4
//     num_threads: 1               # threads stepping the environments
//     normalize_observation: false
//     normalize_reward: true
//   algo: {...}                    # the algorithm's keys (preset + overrides)
//   n_timesteps: 500000
//   seed: 0
//   eval: {freq: 50000, episodes: 10, deterministic: true, save_best: false, record: 0,
//          n_envs: 1,                          # envs the episodes are spread over
//          env: {dynamic_tolerance: false}}   # env.params changed for evaluation (scalars)
//   checkpoint_freq: 100000        # environment steps between checkpoints; 0: none
//   save_replay_buffer: false      # off-policy: keep the replay buffer with the checkpoint
//   output: runs/ppo_pendulum      # where new runs go (a timestamp is appended)
//   warm_start: runs/beam/case2    # start from another run's learned state (its newest
//                                  # checkpoint, or a checkpoint file; Algorithm::warm_start)
//
// Every key is checked: unknown keys and wrong types raise Error naming the key path.
struct Experiment {
  Config config;  // the whole document, with overrides applied
  std::string algorithm;
  VecEnvOptions env;
  Config algo;
  int64_t n_timesteps = 0;
  uint64_t seed = 0;
  int64_t eval_freq = 0;
  int eval_episodes = 10;
  bool eval_deterministic = true;
  // Keep the model of the best evaluation so far as best_model.policy (SB3's EvalCallback with a
  // best-model path): value-based learners such as DQN can lose a solved task late in a run.
  bool eval_save_best = false;
  // The first `eval_record` episodes of every evaluation (and of the final one) are recorded
  // into the run's episodes/ as eval_<steps>_<NNNN>.tep (docs/episode_format.md) for
  // `tendril serve` and `tendril plot episode`.
  int eval_record = 0;
  // Evaluations over this many envs of one vector env (batched policy and, where the env has it,
  // batched model calls; rl::evaluate_policy on a VecEnv); 1: one env, episode after episode.
  // More than 1 needs raw observations (no normalize_observation) and no recording.
  int eval_n_envs = 1;
  // Scalar env.params set otherwise for evaluation (key, YAML text): e.g. seed 001's success
  // rate at the final goal tolerance while training shrinks it.
  std::vector<std::pair<std::string, std::string>> eval_env_overrides;
  int64_t checkpoint_freq = 0;
  bool save_replay_buffer = false;
  std::string output;
  // The checkpoint a new run starts from (a run directory given in the file is resolved to its
  // newest intact checkpoint, and config records that file); empty: from scratch.
  std::string warm_start;

  // Reads and validates every key, including the algorithm's and the environment's (by
  // building them once), so a bad file fails before anything is written.
  static Experiment from_config(Config config);
};

// What an allocation failure (std::bad_alloc) while building or training the experiment is
// about, named as the config names the sizes that decide it.
std::string out_of_memory_message(const Experiment& experiment);

// The environment options of evaluations: the experiment's, with eval.env's parameters set on a
// copy of env.params.
VecEnvOptions evaluation_env_options(const Experiment& experiment);

// The algorithm named in the experiment, on `env`.
std::unique_ptr<Algorithm> make_algorithm(const Experiment& experiment, envs::VecEnv& env);

}  // namespace tendril::rl
