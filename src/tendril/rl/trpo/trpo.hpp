#pragma once

#include <torch/torch.h>

#include <memory>

#include "tendril/rl/on_policy_algorithm.hpp"
#include "tendril/rl/trpo/trpo_config.hpp"

namespace tendril::rl {

// Trust Region Policy Optimization (Schulman et al. 2015, "Trust Region Policy Optimization"),
// as SB3-contrib implements it: a natural-gradient step on the surrogate, found by conjugate
// gradient on Fisher-vector products and scaled to the KL bound, then a backtracking line
// search that keeps the KL within the bound and the surrogate improving; the value function is
// fitted separately by Adam.
class Trpo : public OnPolicyAlgorithm {
 public:
  Trpo(envs::VecEnv& env, const TrpoConfig& config, uint64_t seed);

  const TrpoConfig& config() const { return config_; }

 protected:
  TrainStats train(double progress_remaining) override;
  void save_optimizers(CheckpointWriter& writer) const override;
  std::function<void()> prepare_load(CheckpointReader& reader, nn::ActorCritic& policy) override;

 private:
  std::shared_ptr<torch::optim::Adam> make_value_optimizer(nn::ActorCritic& policy) const;

  TrpoConfig config_;
  std::shared_ptr<torch::optim::Adam> value_optimizer_;
};

}  // namespace tendril::rl
