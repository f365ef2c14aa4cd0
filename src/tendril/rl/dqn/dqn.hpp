#pragma once

#include <Eigen/Core>

#include "tendril/nn/adam.hpp"
#include "tendril/nn/dense_mlp.hpp"
#include "tendril/rl/adam_checkpoint.hpp"
#include "tendril/rl/dqn/dqn_config.hpp"
#include "tendril/rl/dqn/dqn_loss.hpp"
#include "tendril/rl/dqn/q_greedy_policy.hpp"
#include "tendril/rl/off_policy_algorithm.hpp"

namespace tendril::rl {

// Deep Q-Network (Mnih et al. 2015, "Human-level control through deep reinforcement learning",
// Algorithm 1) as Stable-Baselines3 implements it: ε-greedy exploration with a linearly
// annealed ε, a target network updated every `target_update_interval` env steps, Huber loss,
// gradient-norm clipping; optionally double DQN's targets. Discrete action spaces only.
class Dqn : public OffPolicyAlgorithm {
 public:
  Dqn(envs::VecEnv& env, const DqnConfig& config, uint64_t seed);

  const DqnConfig& config() const { return config_; }
  const Policy& policy() const override { return policy_; }
  const QGreedyPolicy& q_policy() const { return policy_; }  // its Q-network
  double exploration_rate() const { return policy_.exploration_rate(); }

 protected:
  void explore(const Eigen::Ref<const Eigen::MatrixXf>& observations, Rng& rng,
               Eigen::MatrixXf& actions) override;
  TrainStats train(int64_t gradient_steps, double progress_remaining) override;
  void after_step() override;
  void write_own_state(ArchiveWriter& writer) const override;
  std::function<void()> read_own_state(const ArchiveReader& reader) override;

 private:
  DqnConfig config_;
  QGreedyPolicy policy_;  // the Q-network: its parameters are trained in place
  Eigen::VectorXf target_, gradient_;
  nn::Adam optimizer_;
  int64_t env_steps_ = 0;  // vector-env steps, for the target-update period

  ReplayBuffer::Batch batch_;
  DqnLossWorkspace loss_workspace_;
};

}  // namespace tendril::rl
