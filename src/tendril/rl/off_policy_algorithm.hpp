#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "tendril/core/archive.hpp"
#include "tendril/rl/algorithm.hpp"
#include "tendril/rl/off_policy_config.hpp"
#include "tendril/rl/replay_buffer.hpp"

namespace tendril::rl {

// The machinery SAC, TD3, DDPG and DQN share (SB3's OffPolicyAlgorithm): step the envs with the
// policy's exploratory actions (uniformly random ones for the first `learning_starts` steps),
// store every transition in the replay buffer, and every `train_freq` vector steps hand the
// algorithm `gradient_steps` updates.
//
// Continuous actions live in [−1, 1] inside the algorithm (networks, buffer, noise) and are
// mapped affinely onto the env's Box bounds, which must therefore be finite: an unbounded
// action space is refused at construction. Discrete actions are indices.
class OffPolicyAlgorithm : public Algorithm {
 public:
  bool has_replay_buffer() const override { return true; }
  // The replay buffer in and out of its own file (it can be large; SB3 saves it apart too).
  uint32_t save_replay_buffer(const std::filesystem::path& file) const override {
    return buffer_.save(file);
  }
  void load_replay_buffer(const std::filesystem::path& file) override { buffer_.load(file); }
  const ReplayBuffer& replay_buffer() const { return buffer_; }

  const OffPolicyConfig& off_policy_config() const { return common_; }
  int64_t gradient_updates() const { return updates_; }

  // `gradient_steps` updates from `buffer` instead of the algorithm's own: a critic trained
  // beside another agent, on that agent's rollouts with rewards of its own (seed 001 §6.3.1's
  // safety agent). The buffer must have this algorithm's observation and action sizes.
  TrainStats train_on(const ReplayBuffer& buffer, int64_t gradient_steps,
                      double progress_remaining);
  // Counts one vector-env step collected elsewhere, `timesteps` environment steps into a budget
  // of `total_timesteps` (DQN's target-update period and exploration schedule follow them).
  void count_external_step(int64_t timesteps, int64_t total_timesteps) {
    set_step_counters(timesteps, total_timesteps);
    after_step();
  }

 protected:
  // `stored_observation_size`: the size of what store_observations makes of an observation
  // (−1: the observation's own size).
  OffPolicyAlgorithm(std::string name, envs::VecEnv& env, const OffPolicyConfig& common,
                     uint64_t seed, int64_t stored_observation_size = -1);

  // The exploratory actions for collecting experience, with the algorithm's exploration
  // (sampling, action noise, ε-greedy): `observations` has one column per env, `actions` gets
  // one column per env, in [−1, 1] for Box spaces, indices for Discrete; draws from `rng`.
  virtual void explore(const Eigen::Ref<const Eigen::MatrixXf>& observations, Rng& rng,
                       Eigen::MatrixXf& actions) = 0;
  // `gradient_steps` updates from the replay buffer; `progress_remaining` runs from 1 to 0 over
  // the budget (for schedules).
  virtual TrainStats train(int64_t gradient_steps, double progress_remaining) = 0;
  // What the replay buffer keeps of observations (one per column): the observations
  // themselves, or what a frozen policy head makes of them, computed once instead of at every
  // update (SAC with a frozen head).
  virtual void store_observations(const Eigen::Ref<const Eigen::MatrixXf>& observations,
                                  Eigen::MatrixXf& stored) {
    stored = observations;
  }
  // Env `env_index`'s episode ended (resets per-env exploration noise).
  virtual void episode_ended(int env_index) { (void)env_index; }
  // After every vector-env step (exploration schedules, step-counted target updates).
  virtual void after_step() {}
  // Before each collection of `train_freq` vector-env steps (gSDE redraws its noise).
  virtual void collection_started() {}
  // The algorithm's own state (weights, targets, optimizers, noise) in and out of checkpoints;
  // `read_own_state` reads everything and returns the action that installs it.
  virtual void write_own_state(ArchiveWriter& writer) const = 0;
  virtual std::function<void()> read_own_state(const ArchiveReader& reader) = 0;

  // The buffer updates sample from: the own one, or the one `train_on` was given.
  const ReplayBuffer& buffer() const { return training_buffer_ ? *training_buffer_ : buffer_; }
  Rng& sample_rng() { return stream(Stream::kUpdates); }  // replay sampling, update-time noise
  const Space& action_space() const { return env().action_space(); }
  int observation_size() const { return env().observation_space().size(); }
  // Components of an action inside the algorithm (the index counts as one).
  int action_size() const { return env().action_space().size(); }
  int num_envs() const { return env().num_envs(); }
  // Counts gradient steps (for delayed and periodic target updates).
  void count_update() { ++updates_; }

 private:
  void run(int64_t total_timesteps, const Observers& observers) override;
  void write_state(ArchiveWriter& writer) const override;
  std::function<void()> read_state(const ArchiveReader& reader) override;
  void collect(Progress& progress, const Observers& observers);

  OffPolicyConfig common_;
  ReplayBuffer buffer_;
  const ReplayBuffer* training_buffer_ = nullptr;  // set during train_on
  Eigen::MatrixXf actions_, env_action_columns_;   // action_size × n_envs
  Eigen::MatrixXf stored_, stored_next_;           // what the buffer keeps, × n_envs
  envs::BatchMatrix env_actions_;
  int64_t updates_ = 0;
};

}  // namespace tendril::rl
