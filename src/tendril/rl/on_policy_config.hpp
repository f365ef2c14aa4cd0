#pragma once

#include <cstdint>

#include "tendril/core/config.hpp"
#include "tendril/nn/actor_critic_spec.hpp"

namespace tendril::rl {

// What every on-policy algorithm (PPO, TRPO) shares: rollout length, GAE and the policy
// architecture. Defaults are Stable-Baselines3's.
struct OnPolicyConfig {
  int64_t n_steps = 2048;           // steps per environment per rollout
  double gamma = 0.99;              // discount γ
  double gae_lambda = 0.95;         // GAE λ
  bool normalize_advantage = true;  // standardise Â per minibatch (SB3)
  nn::ActorCriticSpec policy;       // architecture; sizes are set from the environment

  // Reads n_steps, gamma, gae_lambda, normalize_advantage and the `policy` mapping over this.
  void read(const Config& algo);
  // Raises Error naming the key of the first out-of-range value.
  void validate(const std::string& where) const;
};

}  // namespace tendril::rl
