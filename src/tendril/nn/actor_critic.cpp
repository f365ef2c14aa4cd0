#include "tendril/nn/actor_critic.hpp"

#include "tendril/core/error.hpp"
#include "tendril/nn/categorical.hpp"
#include "tendril/nn/diag_gaussian.hpp"
#include "tendril/nn/orthogonal_init.hpp"

namespace tendril::nn {

torch::Tensor PolicyDistribution::log_prob(const torch::Tensor& actions) const {
  return discrete ? categorical::log_prob(logits, actions)
                  : diag_gaussian::log_prob(mean, log_std, actions);
}

torch::Tensor PolicyDistribution::entropy() const {
  return discrete ? categorical::entropy(logits) : diag_gaussian::entropy(mean, log_std);
}

torch::Tensor PolicyDistribution::kl(const PolicyDistribution& other) const {
  return discrete ? categorical::kl(logits, other.logits)
                  : diag_gaussian::kl(mean, log_std, other.mean, other.log_std);
}

PolicyDistribution PolicyDistribution::detached() const {
  PolicyDistribution copy;
  copy.discrete = discrete;
  if (discrete) {
    copy.logits = logits.detach();
  } else {
    copy.mean = mean.detach();
    copy.log_std = log_std.detach();
  }
  return copy;
}

torch::Tensor PolicyDistribution::mode() const {
  return discrete ? logits.argmax(-1, /*keepdim=*/true).to(torch::kFloat) : mean;
}

ActorCriticImpl::ActorCriticImpl(const ActorCriticSpec& spec, Rng& init_rng) : spec_(spec) {
  require(spec.observation_size > 0, "observation size must be positive", "nn::ActorCritic");
  require(spec.action_size > 0, "action size must be positive", "nn::ActorCritic");
  const bool ortho = spec.orthogonal_init;
  policy_trunk_ = register_module("policy_trunk", Mlp(spec.observation_size, spec.policy_layers,
                                                      spec.activation, ortho, init_rng));
  if (!spec.shared_trunk) {
    value_trunk_ = register_module("value_trunk", Mlp(spec.observation_size, spec.value_layers,
                                                      spec.activation, ortho, init_rng));
  }
  const int64_t value_latent =
      spec.shared_trunk ? policy_trunk_->output_size() : value_trunk_->output_size();
  policy_head_ =
      register_module("policy_head", make_linear(policy_trunk_->output_size(), spec.action_size,
                                                 ortho, kPolicyHeadGain, init_rng));
  value_head_ =
      register_module("value_head", make_linear(value_latent, 1, ortho, kValueHeadGain, init_rng));
  if (!spec.discrete) {
    log_std_ = register_parameter(
        "log_std", torch::full({spec.action_size}, spec.log_std_init, torch::kFloat));
  }
}

PolicyDistribution ActorCriticImpl::distribution_from_latent(const torch::Tensor& latent) {
  PolicyDistribution result;
  result.discrete = spec_.discrete;
  if (spec_.discrete) {
    result.logits = policy_head_->forward(latent);
  } else {
    result.mean = policy_head_->forward(latent);
    result.log_std = log_std_;
  }
  return result;
}

ActorCriticImpl::Evaluation ActorCriticImpl::evaluate(const torch::Tensor& observations,
                                                      const torch::Tensor& actions) {
  const torch::Tensor policy_latent = policy_trunk_->forward(observations);
  const torch::Tensor value_latent =
      spec_.shared_trunk ? policy_latent : value_trunk_->forward(observations);
  const PolicyDistribution pi = distribution_from_latent(policy_latent);
  return {pi.log_prob(actions), pi.entropy(), value_head_->forward(value_latent).squeeze(-1)};
}

PolicyDistribution ActorCriticImpl::distribution(const torch::Tensor& observations) {
  return distribution_from_latent(policy_trunk_->forward(observations));
}

torch::Tensor ActorCriticImpl::value(const torch::Tensor& observations) {
  const torch::Tensor latent = spec_.shared_trunk ? policy_trunk_->forward(observations)
                                                  : value_trunk_->forward(observations);
  return value_head_->forward(latent).squeeze(-1);
}

std::vector<torch::Tensor> ActorCriticImpl::policy_parameters() const {
  std::vector<torch::Tensor> result = policy_trunk_->parameters();
  for (const auto& p : policy_head_->parameters()) result.push_back(p);
  if (log_std_.defined()) result.push_back(log_std_);
  return result;
}

std::vector<torch::Tensor> ActorCriticImpl::value_parameters() const {
  std::vector<torch::Tensor> result;
  if (!spec_.shared_trunk) result = value_trunk_->parameters();
  for (const auto& p : value_head_->parameters()) result.push_back(p);
  return result;
}

}  // namespace tendril::nn
