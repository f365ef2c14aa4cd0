#pragma once

#include "tendril/nn/adam.hpp"
#include "tendril/rl/on_policy_algorithm.hpp"
#include "tendril/rl/ppo/ppo_config.hpp"

namespace tendril::rl {

// Proximal Policy Optimization with the clipped surrogate objective (Schulman et al. 2017,
// "Proximal Policy Optimization Algorithms"), as Stable-Baselines3 implements it: one Adam
// optimizer over policy and value parameters (or one each, when the value network has a
// learning rate of its own), `n_epochs` passes of shuffled minibatches over
// each rollout. The minibatch's forward and backward passes are written out by hand over the
// policy's flat parameter vector (nn::ActorCritic, ppo_loss), so an update is a handful of
// small matrix products, and gradient clipping and the Adam step are whole-vector operations.
class Ppo : public OnPolicyAlgorithm {
 public:
  Ppo(envs::VecEnv& env, const PpoConfig& config, uint64_t seed);

  const PpoConfig& config() const { return config_; }

 protected:
  TrainStats train(double progress_remaining) override;
  void write_optimizers(ArchiveWriter& writer) const override;
  std::function<void()> read_optimizers(const ArchiveReader& reader) override;

 private:
  // The Adam step(s) on `parameters` from gradient_.
  void adam_step(Eigen::VectorXf& parameters);

  PpoConfig config_;
  // Over every parameter, or over the policy block [0, policy_parameter_count) when the value
  // block has value_optimizer_.
  nn::Adam optimizer_;
  nn::Adam value_optimizer_;
  Eigen::VectorXf gradient_;
};

}  // namespace tendril::rl
