#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "tendril/core/rng.hpp"
#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/nn/actor_critic.hpp"
#include "tendril/nn/inference_policy.hpp"
#include "tendril/rl/checkpoint.hpp"
#include "tendril/rl/on_policy_config.hpp"
#include "tendril/rl/rollout_buffer.hpp"

namespace tendril::rl {

// Named scalars of one update, with Stable-Baselines3's logger names ("train/approx_kl", …).
using TrainStats = std::vector<std::pair<std::string, double>>;

// What `learn` reports after each iteration (rollout + update).
struct Progress {
  int64_t timesteps = 0;             // environment steps so far, over all envs
  int64_t iterations = 0;            // rollouts so far
  double episode_return_mean = 0.0;  // over the last 100 finished episodes (0 if none)
  double episode_length_mean = 0.0;
  int64_t episodes = 0;  // finished episodes so far
  TrainStats train;
  // Wall time of this iteration: stepping the environments, policy inference, the update.
  double env_seconds = 0.0, inference_seconds = 0.0, update_seconds = 0.0;
};

// The machinery PPO and TRPO share (SB3's OnPolicyAlgorithm): collect `n_steps` steps from each
// environment with the current policy (Eigen inference copy, batched over envs), compute GAE,
// hand the rollout to the algorithm's update, repeat. Also prediction and checkpoints.
//
// Randomness: every stream derives from the seed — network initialisation, action sampling,
// minibatch shuffling, environment seeds, `predict` — so the same seed gives the same run.
// The VecEnv is borrowed and must outlive the algorithm.
class OnPolicyAlgorithm {
 public:
  // Returning false from the callback stops `learn` after the current iteration.
  using Callback = std::function<bool(const Progress&)>;

  virtual ~OnPolicyAlgorithm() = default;
  OnPolicyAlgorithm(const OnPolicyAlgorithm&) = delete;
  OnPolicyAlgorithm& operator=(const OnPolicyAlgorithm&) = delete;

  // Trains until `total_timesteps` environment steps have been taken in all (calls to `learn`
  // continue the count; linear schedules anneal over `total_timesteps`).
  void learn(int64_t total_timesteps, const Callback& callback = {});

  // The policy's action for one observation: the mode when `deterministic`, else a sample
  // from a dedicated stream. Box actions are clipped to the action space's finite bounds.
  Action predict(const Observation& observation, bool deterministic);
  // The same for a batch (one row per observation, one row per action).
  envs::BatchMatrix predict(const envs::BatchMatrix& observations, bool deterministic);

  // Writes everything needed to resume — weights, optimizer state, RNG states, counters,
  // observation/reward normalizer statistics of the wrapped envs — atomically.
  void save(const std::filesystem::path& file) const;
  // Restores a checkpoint of the same algorithm and architecture. A missing, corrupt or
  // mismatching file raises Error and leaves this object unchanged. The environments restart
  // from a reset at the next `learn`.
  void load(const std::filesystem::path& file);

  // Makes the next rollout start from a seeded reset of every environment, as it does after
  // `load`. The trainer calls it at each checkpoint so that a run resumed from that checkpoint
  // and the uninterrupted run are the same computation.
  void restart_environments() { needs_reset_ = true; }

  int64_t num_timesteps() const { return num_timesteps_; }
  int64_t iterations() const { return iterations_; }
  const std::string& name() const { return name_; }
  const nn::ActorCritic& policy() const { return policy_; }
  const OnPolicyConfig& on_policy_config() const { return common_; }
  // Returns of the last (up to) 100 finished episodes, oldest first.
  const std::deque<double>& recent_returns() const { return recent_returns_; }

 protected:
  OnPolicyAlgorithm(std::string name, envs::VecEnv& env, const OnPolicyConfig& common,
                    uint64_t seed);

  // The algorithm's update from the full rollout in `buffer()`; `progress_remaining` runs from
  // 1 to 0 over the budget (for schedules). Must leave the inference copy in sync.
  virtual TrainStats train(double progress_remaining) = 0;
  // Optimizer state in and out of checkpoints. `prepare_load` builds and fills new optimizers
  // for `policy` (a freshly loaded module) without touching the current ones, and returns the
  // action that installs them; it runs only once every read has succeeded.
  virtual void save_optimizers(CheckpointWriter& writer) const = 0;
  virtual std::function<void()> prepare_load(CheckpointReader& reader, nn::ActorCritic& policy) = 0;

  nn::ActorCritic& mutable_policy() { return policy_; }
  const RolloutBuffer& buffer() const { return buffer_; }
  Rng& shuffle_rng() { return shuffle_rng_; }
  // Copies the module's weights into the Eigen inference policy.
  void sync_inference();

 private:
  void collect_rollout(Progress& progress);
  void record_episodes(const envs::VecStep& step);

  std::string name_;
  envs::VecEnv& env_;
  OnPolicyConfig common_;
  uint64_t seed_;
  nn::ActorCritic policy_{nullptr};
  nn::InferencePolicy inference_;
  RolloutBuffer buffer_;
  Rng action_rng_, shuffle_rng_, predict_rng_, env_seed_rng_;

  // Collection state between iterations.
  bool needs_reset_ = true;
  envs::BatchMatrix last_observations_;
  Eigen::MatrixXf actions_;        // action_dims × n_envs
  envs::BatchMatrix env_actions_;  // n_envs × action_dims, clipped
  Eigen::VectorXf values_, log_probs_, truncation_values_, last_values_;

  int64_t num_timesteps_ = 0;
  int64_t iterations_ = 0;
  int64_t episodes_ = 0;
  std::deque<double> recent_returns_, recent_lengths_;
};

}  // namespace tendril::rl
