#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "tendril/core/archive.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/rl/observer.hpp"
#include "tendril/rl/off_policy_algorithm.hpp"
#include "tendril/rl/replay_buffer.hpp"
#include "tendril/safety/constraint.hpp"
#include "tendril/safety/filtered_vec_env.hpp"
#include "tendril/safety/safety_reward.hpp"

namespace tendril::safety {

struct CoTrainingSettings {
  int64_t buffer_size = 100000;
  int64_t learning_starts = 1000;  // safety transitions before the first update
  int64_t train_freq = 1;          // vector-env steps between updates
  int64_t gradient_steps = 1;
  // Sampled unsafe states per stored transition for the supervised loss (eq. 6.6).
  int64_t unsafe_samples_per_step = 1;
};

// The safety agent of seed 001 §6.3.1, trained beside a task agent from the task agent's own
// rollouts: an observer of every step that writes the transitions, with r_safe (eq. 6.3) in
// place of the task reward, into a gated replay buffer of its own and updates the safety agent
// (an off-policy algorithm on the same spaces, never stepping the environments itself) from
// it. The gate of each environment closes at the first transition into X_unsafe — stored, as
// a termination — and opens again when its episode ends; the task agent's buffer is untouched.
// An episode's last transition at the time limit is a termination too (the thesis' finite
// horizon T, §6.2.1).
//
// Eq. (6.6), V_s(x) = −1/(1 − γ) on X_unsafe, is learnt as in the thesis' code (an MSE to
// that target): each stored transition comes with `unsafe_samples_per_step` transitions from
// uniformly drawn unsafe states with reward −1/(1 − γ) that terminate at once, whose TD target
// is exactly that value (for every action, as V* is action-independent there).
class SafetyCoTrainer : public rl::Observer {
 public:
  SafetyCoTrainer(rl::OffPolicyAlgorithm& safety_agent, const envs::SafetyConstraint& constraint,
                  const SafetyReward& reward, const CoTrainingSettings& settings,
                  int64_t total_timesteps, uint64_t seed);

  void on_step(const rl::StepEvent& event) override;
  // When the task agent acts through a FilteredVecEnv, the safety agent learns from what the
  // environments executed rather than from the task agent's proposals. Borrows `env`.
  void learn_executed_actions_of(const FilteredVecEnv& env) { filtered_env_ = &env; }

  const rl::ReplayBuffer& buffer() const { return buffer_; }
  int64_t stored_transitions() const { return stored_; }
  int64_t gated_transitions() const { return gated_; }  // seen while the gate was closed
  int64_t unsafe_entries() const { return unsafe_entries_; }
  const rl::TrainStats& last_stats() const { return last_stats_; }

  // Its state — the gated buffer, its draws, the gates, the counts and the last update's
  // scalars — in and out of a checkpoint under `prefix`. `prepare_load` reads and checks
  // everything and returns the action that installs it.
  void save(ArchiveWriter& writer, const std::string& prefix) const;
  std::function<void()> prepare_load(const ArchiveReader& reader, const std::string& prefix);

 private:
  void store(const Eigen::Ref<const Eigen::VectorXf>& observation, const Action& action,
             double reward, const Eigen::Ref<const Eigen::VectorXf>& next_observation,
             bool terminated);
  Action agent_action(const Eigen::Ref<const Eigen::VectorXf>& action) const;

  rl::OffPolicyAlgorithm& agent_;
  const FilteredVecEnv* filtered_env_ = nullptr;
  const envs::SafetyConstraint& constraint_;
  SafetyReward reward_;
  CoTrainingSettings settings_;
  int64_t total_timesteps_;
  Space action_space_;
  rl::ReplayBuffer buffer_;
  Rng rng_;
  std::vector<uint8_t> gate_open_;
  int64_t steps_ = 0, stored_ = 0, gated_ = 0, unsafe_entries_ = 0;
  rl::TrainStats last_stats_;
};

}  // namespace tendril::safety
