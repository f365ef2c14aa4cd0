#pragma once

#include <torch/torch.h>

#include <memory>

#include "tendril/nn/flat_adam.hpp"
#include "tendril/rl/on_policy_algorithm.hpp"
#include "tendril/rl/ppo/ppo_config.hpp"

namespace tendril::rl {

// Proximal Policy Optimization with the clipped surrogate objective (Schulman et al. 2017,
// "Proximal Policy Optimization Algorithms"), as Stable-Baselines3 implements it: one Adam
// optimizer over policy and value parameters, `n_epochs` passes of shuffled minibatches over
// each rollout. The parameters live in one flat buffer (nn::FlatAdam), so gradient clipping and
// the Adam step cost a few whole-buffer operations per minibatch; the minibatch's forward and
// backward passes are written out by hand over that buffer (nn::DenseActorCritic, ppo_loss),
// which makes an update a handful of small matrix products instead of LibTorch dispatches.
class Ppo : public OnPolicyAlgorithm {
 public:
  Ppo(envs::VecEnv& env, const PpoConfig& config, uint64_t seed);

  const PpoConfig& config() const { return config_; }

 protected:
  TrainStats train(double progress_remaining) override;
  void save_optimizers(CheckpointWriter& writer) const override;
  std::function<void()> prepare_load(CheckpointReader& reader, nn::ActorCritic& policy) override;

 private:
  std::shared_ptr<nn::FlatAdam> make_optimizer(nn::ActorCritic& policy) const;

  PpoConfig config_;
  std::shared_ptr<nn::FlatAdam> optimizer_;
};

}  // namespace tendril::rl
