#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "tendril/core/rng.hpp"
#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/rl/algorithm.hpp"
#include "tendril/rl/checkpoint.hpp"
#include "tendril/rl/episode_tracker.hpp"
#include "tendril/rl/off_policy_config.hpp"
#include "tendril/rl/replay_buffer.hpp"

namespace tendril::rl {

// The machinery SAC, TD3, DDPG and DQN share (SB3's OffPolicyAlgorithm): step the envs with the
// policy's exploratory actions (uniformly random ones for the first `learning_starts` steps),
// store every transition in the replay buffer, and every `train_freq` vector steps hand the
// algorithm `gradient_steps` updates. Also prediction and checkpoints.
//
// Continuous actions live in [−1, 1] inside the algorithm (networks, buffer, noise) and are
// mapped affinely onto the env's Box bounds, which must therefore be finite: an unbounded
// action space is refused at construction. Discrete actions are indices.
//
// Randomness: every stream derives from the seed, so the same seed gives the same run.
class OffPolicyAlgorithm : public Algorithm {
 public:
  OffPolicyAlgorithm(const OffPolicyAlgorithm&) = delete;
  OffPolicyAlgorithm& operator=(const OffPolicyAlgorithm&) = delete;

  void learn(int64_t total_timesteps, const Callback& callback = {}) override;
  // One row per observation in, one row per action out (env units).
  envs::BatchMatrix predict(const envs::BatchMatrix& observations, bool deterministic) override;
  using Algorithm::predict;

  void save(const std::filesystem::path& file) const override;
  void load(const std::filesystem::path& file) override;
  void restart_environments() override { needs_reset_ = true; }

  // The replay buffer in and out of its own file (it can be large; SB3 saves it apart too).
  void save_replay_buffer(const std::filesystem::path& file) const { buffer_.save(file); }
  void load_replay_buffer(const std::filesystem::path& file) { buffer_.load(file); }
  const ReplayBuffer& replay_buffer() const { return buffer_; }

  int64_t num_timesteps() const override { return num_timesteps_; }
  const std::string& name() const override { return name_; }
  const OffPolicyConfig& off_policy_config() const { return common_; }
  int64_t gradient_updates() const { return updates_; }

 protected:
  OffPolicyAlgorithm(std::string name, envs::VecEnv& env, const OffPolicyConfig& common,
                     uint64_t seed);

  // How `act` chooses: the policy's mode; a draw from the policy (`predict` with
  // deterministic = false); or for collecting experience, with the algorithm's exploration
  // (action noise, ε-greedy) — then `observations` has one column per env.
  enum class ActMode { kDeterministic, kStochastic, kCollect };
  // The policy's actions for `observations` (observation_size × batch) into `actions`
  // (action_size × batch): in [−1, 1] for Box spaces, indices for Discrete; random draws come
  // from `rng`.
  virtual void act(const Eigen::Ref<const Eigen::MatrixXf>& observations, ActMode mode, Rng& rng,
                   Eigen::MatrixXf& actions) = 0;
  // `gradient_steps` updates from the replay buffer; `progress_remaining` runs from 1 to 0 over
  // the budget (for schedules).
  virtual TrainStats train(int64_t gradient_steps, double progress_remaining) = 0;
  // Env `env_index`'s episode ended (resets per-env exploration noise).
  virtual void episode_ended(int env_index) { (void)env_index; }
  // After every vector-env step (exploration schedules, step-counted target updates).
  virtual void after_step() {}
  // Before each collection of `train_freq` vector-env steps (gSDE redraws its noise).
  virtual void collection_started() {}
  // The algorithm's own state (weights, optimizers, noise) in and out of checkpoints.
  // `prepare_load` reads everything and returns the action that installs it, which runs only
  // once every read of the checkpoint has succeeded.
  virtual void save_state(CheckpointWriter& writer) const = 0;
  virtual std::function<void()> prepare_load(CheckpointReader& reader) = 0;

  const ReplayBuffer& buffer() const { return buffer_; }
  Rng& sample_rng() { return sample_rng_; }  // replay sampling and update-time noise
  const Space& action_space() const { return env_.action_space(); }
  int observation_size() const { return env_.observation_space().size(); }
  // Components of an action inside the algorithm (the index counts as one).
  int action_size() const { return env_.action_space().size(); }
  int num_envs() const { return env_.num_envs(); }
  uint64_t seed() const { return seed_; }
  // Counts gradient steps (for delayed and periodic target updates).
  void count_update() { ++updates_; }
  // 1 at the start of the budget of the current `learn`, 0 when it is spent (SB3's).
  double progress_remaining() const;

 private:
  void collect(Progress& progress);
  void to_env_actions(const Eigen::MatrixXf& actions, envs::BatchMatrix& env_actions) const;

  std::string name_;
  envs::VecEnv& env_;
  OffPolicyConfig common_;
  uint64_t seed_;
  ReplayBuffer buffer_;
  Rng action_rng_, sample_rng_, predict_rng_, env_seed_rng_;

  bool needs_reset_ = true;
  envs::BatchMatrix last_observations_;
  Eigen::MatrixXf actions_;  // action_size × n_envs
  envs::BatchMatrix env_actions_;

  int64_t num_timesteps_ = 0;
  int64_t total_timesteps_ = 1;  // of the current `learn`
  int64_t iterations_ = 0;
  int64_t updates_ = 0;
  EpisodeTracker episodes_;
};

}  // namespace tendril::rl
