#include "tendril/rl/rollout_buffer.hpp"

#include <algorithm>

#include "tendril/core/error.hpp"

namespace tendril::rl {

RolloutBuffer::RolloutBuffer(int64_t n_steps, int64_t n_envs, int64_t observation_size,
                             int64_t action_dims)
    : n_steps_(n_steps), n_envs_(n_envs) {
  require(n_steps > 0 && n_envs > 0, "n_steps and n_envs must be positive", "rl::RolloutBuffer");
  const int64_t total = n_steps * n_envs;
  observations_.resize(total, observation_size);
  actions_.resize(total, action_dims);
  log_probs_.resize(total);
  gae_input_.n_steps = n_steps;
  gae_input_.n_envs = n_envs;
  gae_input_.rewards.resize(total);
  gae_input_.values.resize(total);
  gae_input_.terminated.resize(total);
  gae_input_.truncated.resize(total);
  gae_input_.truncation_values.resize(total);
  gae_output_.advantages.resize(total);
  gae_output_.returns.resize(total);
}

void RolloutBuffer::add(const Eigen::Ref<const RowMatrix>& observations,
                        const Eigen::Ref<const Eigen::MatrixXf>& actions,
                        const Eigen::VectorXf& rewards, const Eigen::VectorXf& values,
                        const Eigen::VectorXf& log_probs, const std::vector<uint8_t>& terminated,
                        const std::vector<uint8_t>& truncated,
                        const Eigen::VectorXf& truncation_values) {
  require(!full(), "the rollout buffer is full", "rl::RolloutBuffer::add");
  const int64_t first = steps_ * n_envs_;
  observations_.middleRows(first, n_envs_) = observations;
  actions_.middleRows(first, n_envs_) = actions.transpose();
  gae_input_.rewards.segment(first, n_envs_) = rewards;
  gae_input_.values.segment(first, n_envs_) = values;
  log_probs_.segment(first, n_envs_) = log_probs;
  std::copy(terminated.begin(), terminated.end(), gae_input_.terminated.begin() + first);
  std::copy(truncated.begin(), truncated.end(), gae_input_.truncated.begin() + first);
  gae_input_.truncation_values.segment(first, n_envs_) = truncation_values;
  ++steps_;
}

void RolloutBuffer::finish(const Eigen::VectorXf& last_values, double gamma, double lambda) {
  require(full(), "GAE needs a full rollout", "rl::RolloutBuffer::finish");
  gae_input_.last_values = last_values;
  gae_output_ = compute_gae(gae_input_, gamma, lambda);
}

double explained_variance(const RolloutBuffer& buffer) {
  const Eigen::ArrayXd returns = buffer.returns().cast<double>().array();
  const Eigen::ArrayXd residual = returns - buffer.values().cast<double>().array();
  const auto variance = [](const Eigen::ArrayXd& x) { return (x - x.mean()).square().mean(); };
  const double returns_variance = variance(returns);
  if (returns_variance == 0.0) return 0.0;
  return 1.0 - variance(residual) / returns_variance;
}

}  // namespace tendril::rl
