#include "tendril/rl/on_policy_config.hpp"

#include "tendril/core/error.hpp"

namespace tendril::rl {

void OnPolicyConfig::read(const Config& algo) {
  n_steps = algo.get_or<int64_t>("n_steps", n_steps);
  gamma = algo.get_or<double>("gamma", gamma);
  gae_lambda = algo.get_or<double>("gae_lambda", gae_lambda);
  normalize_advantage = algo.get_or<bool>("normalize_advantage", normalize_advantage);
  policy = nn::ActorCriticSpec::from_config(algo.child("policy"), policy);
}

void OnPolicyConfig::validate(const std::string& where) const {
  require(n_steps >= 1, "n_steps must be at least 1, got " + std::to_string(n_steps), where);
  require(gamma >= 0.0 && gamma <= 1.0, "gamma must lie in [0, 1]", where);
  require(gae_lambda >= 0.0 && gae_lambda <= 1.0, "gae_lambda must lie in [0, 1]", where);
}

}  // namespace tendril::rl
