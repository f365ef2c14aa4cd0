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
#include "tendril/rl/algorithm.hpp"
#include "tendril/rl/checkpoint.hpp"
#include "tendril/rl/episode_tracker.hpp"
#include "tendril/rl/on_policy_config.hpp"
#include "tendril/rl/rollout_buffer.hpp"

namespace tendril::rl {

// The machinery PPO and TRPO share (SB3's OnPolicyAlgorithm): collect `n_steps` steps from each
// environment with the current policy (Eigen inference copy, batched over envs), compute GAE,
// hand the rollout to the algorithm's update, repeat. Also prediction and checkpoints.
//
// Randomness: every stream derives from the seed — network initialisation, action sampling,
// minibatch shuffling, environment seeds, `predict` — so the same seed gives the same run.
// The VecEnv is borrowed and must outlive the algorithm.
class OnPolicyAlgorithm : public Algorithm {
 public:
  OnPolicyAlgorithm(const OnPolicyAlgorithm&) = delete;
  OnPolicyAlgorithm& operator=(const OnPolicyAlgorithm&) = delete;

  void learn(int64_t total_timesteps, const Callback& callback = {}) override;

  // The same for a batch (one row per observation, one row per action).
  envs::BatchMatrix predict(const envs::BatchMatrix& observations, bool deterministic) override;
  using Algorithm::predict;

  void save(const std::filesystem::path& file) const override;
  void load(const std::filesystem::path& file) override;
  void restart_environments() override { needs_reset_ = true; }

  int64_t num_timesteps() const override { return num_timesteps_; }
  int64_t iterations() const { return iterations_; }
  const std::string& name() const override { return name_; }
  const nn::ActorCritic& policy() const { return policy_; }
  const OnPolicyConfig& on_policy_config() const { return common_; }
  // Returns of the last (up to) 100 finished episodes, oldest first.
  const std::deque<double>& recent_returns() const { return episodes_.recent_returns(); }

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
  EpisodeTracker episodes_;
};

}  // namespace tendril::rl
