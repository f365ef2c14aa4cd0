#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace tendril::rl {

// One rollout of `n_steps` steps from each of `n_envs` environments, stored time-major: entry
// t·n_envs + e is step t of environment e.
struct GaeInput {
  int64_t n_steps = 0;
  int64_t n_envs = 0;
  Eigen::VectorXf rewards;          // r_t
  Eigen::VectorXf values;           // V(s_t)
  std::vector<uint8_t> terminated;  // the task ended after step t: nothing to bootstrap
  std::vector<uint8_t> truncated;   // a time limit cut the episode after step t
  // V of the final observation where step t was truncated (read only there).
  Eigen::VectorXf truncation_values;
  // V(s_T) of the observation after the rollout's last step, per environment.
  Eigen::VectorXf last_values;
};

struct GaeOutput {
  Eigen::VectorXf advantages;  // Â_t
  Eigen::VectorXf returns;     // Â_t + V(s_t), the value-function target
};

// Generalized advantage estimation (Schulman et al. 2016, "High-dimensional continuous control
// using generalized advantage estimation", eq. 16), per environment, backwards in time:
//
//   δ_t = r_t + γ V_next,t − V(s_t)
//   Â_t = δ_t + γλ (1 − done_t) Â_{t+1}
//
// where V_next,t is V(s_{t+1}) while the episode continues, V(final observation) when a time
// limit truncated it (the state was not terminal, only the episode was cut: bootstrap), and 0
// when it terminated. done_t = terminated_t or truncated_t stops the recursion at episode
// boundaries, so advantages never leak from the next episode into this one.
GaeOutput compute_gae(const GaeInput& input, double gamma, double lambda);

}  // namespace tendril::rl
