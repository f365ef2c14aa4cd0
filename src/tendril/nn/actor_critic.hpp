#pragma once

#include <torch/torch.h>

#include <vector>

#include "tendril/core/rng.hpp"
#include "tendril/nn/actor_critic_spec.hpp"
#include "tendril/nn/mlp.hpp"

namespace tendril::nn {

// The action distribution a policy outputs for a batch of observations.
// Gaussian: `mean` [batch, dims] and state-independent `log_std` [dims]; categorical: `logits`
// [batch, n]. Actions are float tensors [batch, dims] (categorical: [batch, 1] indices).
struct PolicyDistribution {
  bool discrete = false;
  torch::Tensor mean, log_std, logits;

  torch::Tensor log_prob(const torch::Tensor& actions) const;  // [batch]
  torch::Tensor entropy() const;                               // [batch]
  // KL(this ‖ other), per sample [batch].
  torch::Tensor kl(const PolicyDistribution& other) const;
  // The same distribution cut from the autograd graph (TRPO's fixed "old" policy).
  PolicyDistribution detached() const;
  // Mode: the mean, or the most likely index.
  torch::Tensor mode() const;
};

// Policy and value networks of an on-policy actor-critic (SB3's ActorCriticPolicy):
//   policy trunk → policy head (mean or logits) [+ log σ parameter]
//   value trunk  → value head (scalar)
// With `spec.shared_trunk` one trunk feeds both heads. Parameters are initialised from
// `init_rng`, so the same seed gives the same network without LibTorch's global generator.
class ActorCriticImpl : public torch::nn::Module {
 public:
  ActorCriticImpl(const ActorCriticSpec& spec, Rng& init_rng);

  struct Evaluation {
    torch::Tensor log_prob;  // log π(a|s) [batch]
    torch::Tensor entropy;   // H[π(·|s)] [batch]
    torch::Tensor value;     // V(s) [batch]
  };
  // Everything a policy-gradient loss needs for stored (observation, action) pairs, sharing
  // the trunk pass when the trunk is shared.
  Evaluation evaluate(const torch::Tensor& observations, const torch::Tensor& actions);

  PolicyDistribution distribution(const torch::Tensor& observations);
  torch::Tensor value(const torch::Tensor& observations);  // [batch]

  // Parameters that shape the policy (trunk, head, log σ) and the value (trunk, head). With a
  // shared trunk its parameters belong to the policy list only.
  std::vector<torch::Tensor> policy_parameters() const;
  std::vector<torch::Tensor> value_parameters() const;

  const ActorCriticSpec& spec() const { return spec_; }
  const Mlp& policy_trunk() const { return policy_trunk_; }
  const Mlp& value_trunk() const { return value_trunk_; }  // empty when shared
  const torch::nn::Linear& policy_head() const { return policy_head_; }
  const torch::nn::Linear& value_head() const { return value_head_; }
  const torch::Tensor& log_std() const { return log_std_; }  // undefined when categorical

 private:
  PolicyDistribution distribution_from_latent(const torch::Tensor& latent);

  ActorCriticSpec spec_;
  Mlp policy_trunk_{nullptr};
  Mlp value_trunk_{nullptr};
  torch::nn::Linear policy_head_{nullptr};
  torch::nn::Linear value_head_{nullptr};
  torch::Tensor log_std_;
};
TORCH_MODULE(ActorCritic);

}  // namespace tendril::nn
