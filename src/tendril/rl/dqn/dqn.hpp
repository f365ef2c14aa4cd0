#pragma once

#include <Eigen/Core>

#include "tendril/nn/adam.hpp"
#include "tendril/nn/dense_mlp.hpp"
#include "tendril/rl/adam_checkpoint.hpp"
#include "tendril/rl/dqn/dqn_config.hpp"
#include "tendril/rl/dqn/dqn_loss.hpp"
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
  double exploration_rate() const { return exploration_rate_; }

 protected:
  void act(const Eigen::Ref<const Eigen::MatrixXf>& observations, ActMode mode, Rng& rng,
           Eigen::MatrixXf& actions) override;
  TrainStats train(int64_t gradient_steps, double progress_remaining) override;
  void after_step() override;
  void save_state(CheckpointWriter& writer) const override;
  std::function<void()> prepare_load(CheckpointReader& reader) override;

 private:
  DqnConfig config_;
  int64_t actions_count_ = 0;
  nn::DenseMlp q_network_;  // observation → hidden → one Q per action
  Eigen::VectorXf parameters_, target_, gradient_;
  nn::Adam optimizer_;
  int64_t env_steps_ = 0;  // vector-env steps, for the target-update period
  double exploration_rate_ = 1.0;

  ReplayBuffer::Batch batch_;
  nn::DenseMlp::Tape tape_;  // of the acting forward pass
  DqnLossWorkspace loss_workspace_;
};

}  // namespace tendril::rl
