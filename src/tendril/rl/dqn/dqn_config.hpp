#pragma once

#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/rl/off_policy_config.hpp"

namespace tendril::rl {

// DQN hyper-parameters. Defaults are Stable-Baselines3's DQN (stable_baselines3/dqn/dqn.py):
// buffer 1e6, 100 warm-up steps, batch 32, τ 1 (hard target copies) every 10 000 env steps,
// γ 0.99, one gradient step every 4 env steps, Adam lr 1e-4, ε from 1 to 0.05 over the first
// 10% of the budget, Huber loss, gradient norm clipped at 10, 64×64 ReLU network.
struct DqnConfig {
  OffPolicyConfig common;
  int64_t target_update_interval = 10'000;  // env steps between target updates
  double exploration_fraction = 0.1;        // of the budget over which ε anneals
  double exploration_initial_eps = 1.0;
  double exploration_final_eps = 0.05;
  std::optional<double> max_grad_norm = 10.0;
  bool double_q = false;  // van Hasselt et al. 2016: the online network picks a'
  // A bounded Q-head, Q = q_bound·tanh(z) (QGreedyPolicy); none: a linear head, as SB3's.
  std::optional<double> q_bound;

  static DqnConfig sb3();
  // `preset: sb3` and then, over it, the common off-policy keys and target_update_interval,
  // exploration_fraction, exploration_initial_eps, exploration_final_eps, max_grad_norm (a
  // number or `none`), double_q, q_bound (a number or `none`).
  static DqnConfig from_config(const Config& algo);

  void validate() const;
};

}  // namespace tendril::rl
