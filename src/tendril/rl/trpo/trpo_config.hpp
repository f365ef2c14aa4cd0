#pragma once

#include <cstdint>

#include "tendril/core/config.hpp"
#include "tendril/rl/on_policy_config.hpp"

namespace tendril::rl {

// TRPO hyper-parameters. Defaults are SB3-contrib's TRPO (sb3_contrib/trpo/trpo.py): n_steps
// 2048, γ 0.99, λ 0.95, KL bound 0.01, 15 conjugate-gradient steps with damping 0.1, line search
// shrinking by 0.8 at most 10 times, value function fitted by 10 epochs of Adam (lr 1e-3,
// minibatches of 128), 64×64 tanh trunks. Separate trunks are required: the value fit must not
// move the policy.
struct TrpoConfig {
  OnPolicyConfig common;
  double target_kl = 0.01;  // δ, the bound on the mean KL(π_old ‖ π_new) per update
  int64_t cg_max_steps = 15;
  double cg_damping = 0.1;  // F + damping·I, for a well-conditioned solve
  double line_search_shrinking_factor = 0.8;
  int64_t line_search_max_iter = 10;
  int64_t n_critic_updates = 10;  // Adam epochs over the rollout for the value function
  int64_t batch_size = 128;       // value-function minibatch
  double learning_rate = 1e-3;    // value-function Adam
  double adam_epsilon = 1e-5;

  static TrpoConfig sb3();
  // stable-baselines v2's TRPO defaults: timesteps_per_batch 1024, max_kl 0.01, cg_iters 10,
  // cg_damping 0.01, λ 0.98, γ 0.99, vf_iters 3, vf_stepsize 3e-4 (value minibatches of 128).
  static TrpoConfig trpo_v2();
  // `preset: sb3 | trpo_v2` (default sb3) and any of: n_steps, gamma, gae_lambda,
  // normalize_advantage, target_kl, cg_max_steps, cg_damping, line_search_shrinking_factor,
  // line_search_max_iter, n_critic_updates, batch_size, learning_rate, adam_epsilon, policy{…}.
  // Unknown keys and out-of-range values raise Error naming the key.
  static TrpoConfig from_config(const Config& algo);

  void validate() const;
};

}  // namespace tendril::rl
