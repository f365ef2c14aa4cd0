#pragma once

#include "tendril/nn/adam.hpp"
#include "tendril/rl/on_policy_algorithm.hpp"
#include "tendril/rl/trpo/trpo_config.hpp"

namespace tendril::rl {

// Trust Region Policy Optimization (Schulman et al. 2015, "Trust Region Policy Optimization"),
// as SB3-contrib implements it: a natural-gradient step on the surrogate, found by conjugate
// gradient on Fisher-vector products and scaled to the KL bound, then a backtracking line
// search that keeps the KL within the bound and the surrogate improving; the value function is
// fitted separately by Adam. Gradients and Fisher-vector products are written out by hand
// (nn::ActorCritic: a forward-mode pass for J v, the distribution's Fisher information, a
// backward pass for Jᵀ), so TRPO needs no autograd.
class Trpo : public OnPolicyAlgorithm {
 public:
  Trpo(envs::VecEnv& env, const TrpoConfig& config, uint64_t seed);

  const TrpoConfig& config() const { return config_; }

 protected:
  TrainStats train(double progress_remaining) override;
  void write_optimizers(ArchiveWriter& writer) const override;
  std::function<void()> read_optimizers(const ArchiveReader& reader) override;

 private:
  // Adam on the value block of the parameters for the minibatches of `n_critic_updates`
  // epochs; returns the mean value loss.
  double fit_value_function();

  TrpoConfig config_;
  int64_t value_offset_ = 0, value_count_ = 0;  // the value block of the parameters
  nn::Adam value_optimizer_;
};

}  // namespace tendril::rl
