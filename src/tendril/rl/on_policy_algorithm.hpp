#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>

#include "tendril/core/archive.hpp"
#include "tendril/rl/actor_critic_policy.hpp"
#include "tendril/rl/algorithm.hpp"
#include "tendril/rl/on_policy_config.hpp"
#include "tendril/rl/rollout_buffer.hpp"

namespace tendril::rl {

// The machinery PPO and TRPO share (SB3's OnPolicyAlgorithm): collect `n_steps` steps from each
// environment with the current policy (batched over envs), compute GAE, hand the rollout to the
// algorithm's update, repeat. The policy is an ActorCriticPolicy whose parameters the update
// changes in place.
class OnPolicyAlgorithm : public Algorithm {
 public:
  const Policy& policy() const override { return policy_; }
  const ActorCriticPolicy& actor_critic() const { return policy_; }
  const OnPolicyConfig& on_policy_config() const { return common_; }

 protected:
  OnPolicyAlgorithm(std::string name, envs::VecEnv& env, const OnPolicyConfig& common,
                    uint64_t seed);

  // The algorithm's update from the full rollout in `buffer()`; `progress_remaining` runs from
  // 1 to 0 over the budget (for schedules).
  virtual TrainStats train(double progress_remaining) = 0;
  // The optimizers' state in and out of checkpoints; `read_optimizers` returns the action that
  // installs what it read.
  virtual void write_optimizers(ArchiveWriter& writer) const = 0;
  virtual std::function<void()> read_optimizers(const ArchiveReader& reader) = 0;

  ActorCriticPolicy& mutable_policy() { return policy_; }
  const nn::ActorCritic& network() const { return policy_.network(); }
  Eigen::VectorXf& parameters() { return policy_.parameters(); }
  const RolloutBuffer& buffer() const { return buffer_; }
  Rng& shuffle_rng() { return stream(Stream::kUpdates); }

 private:
  void run(int64_t total_timesteps, const Observers& observers) override;
  void write_state(ArchiveWriter& writer) const override;
  std::function<void()> read_state(const ArchiveReader& reader) override;
  void collect_rollout(Progress& progress, const Observers& observers);

  OnPolicyConfig common_;
  ActorCriticPolicy policy_;
  RolloutBuffer buffer_;

  // Scratch of collection, reused across steps.
  Eigen::MatrixXf actions_, clipped_actions_;  // action_dims × n_envs
  envs::BatchMatrix env_actions_;              // n_envs × action_dims, clipped
  Eigen::VectorXf values_, log_probs_, truncation_values_, last_values_;
};

}  // namespace tendril::rl
