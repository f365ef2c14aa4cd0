#include "tendril/rl/gae.hpp"

#include "tendril/core/error.hpp"

namespace tendril::rl {

GaeOutput compute_gae(const GaeInput& input, double gamma, double lambda) {
  const int64_t size = input.n_steps * input.n_envs;
  require(input.rewards.size() == size && input.values.size() == size &&
              static_cast<int64_t>(input.terminated.size()) == size &&
              static_cast<int64_t>(input.truncated.size()) == size &&
              input.truncation_values.size() == size && input.last_values.size() == input.n_envs,
          "GAE input arrays do not match n_steps × n_envs", "rl::compute_gae");
  GaeOutput output{Eigen::VectorXf(size), Eigen::VectorXf(size)};
  for (int64_t env = 0; env < input.n_envs; ++env) {
    double next_advantage = 0.0;  // Â_{t+1}
    for (int64_t t = input.n_steps - 1; t >= 0; --t) {
      const int64_t i = t * input.n_envs + env;
      double next_value;
      if (input.terminated[i]) {
        next_value = 0.0;
      } else if (input.truncated[i]) {
        next_value = input.truncation_values[i];
      } else if (t + 1 < input.n_steps) {
        next_value = input.values[i + input.n_envs];
      } else {
        next_value = input.last_values[env];
      }
      const bool done = input.terminated[i] || input.truncated[i];
      const double delta = input.rewards[i] + gamma * next_value - input.values[i];
      const double advantage = delta + (done ? 0.0 : gamma * lambda * next_advantage);
      output.advantages[i] = static_cast<float>(advantage);
      output.returns[i] = static_cast<float>(advantage + input.values[i]);
      next_advantage = advantage;
    }
  }
  return output;
}

}  // namespace tendril::rl
