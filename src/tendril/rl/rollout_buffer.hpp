#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "tendril/rl/gae.hpp"

namespace tendril::rl {

// The on-policy rollout of PPO and TRPO: `n_steps` lock-step steps of `n_envs` environments,
// stored time-major (row t·n_envs + e is step t of env e) in contiguous row-major arrays that a
// tensor can view without a copy. Filled step by step, then `finish` computes GAE(λ)
// advantages and value targets. Allocates only at construction.
class RolloutBuffer {
 public:
  using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  RolloutBuffer(int64_t n_steps, int64_t n_envs, int64_t observation_size, int64_t action_dims);

  void clear() { steps_ = 0; }
  bool full() const { return steps_ == n_steps_; }
  int64_t n_steps() const { return n_steps_; }
  int64_t n_envs() const { return n_envs_; }
  int64_t size() const { return n_steps_ * n_envs_; }

  // Appends one step of every environment: observations s_t (n_envs × observation_size),
  // actions a_t (action_dims × n_envs, one column per env), then per env r_t, V(s_t),
  // log π(a_t|s_t), the episode-end flags, and V(final observation) where truncated.
  void add(const Eigen::Ref<const RowMatrix>& observations,
           const Eigen::Ref<const Eigen::MatrixXf>& actions, const Eigen::VectorXf& rewards,
           const Eigen::VectorXf& values, const Eigen::VectorXf& log_probs,
           const std::vector<uint8_t>& terminated, const std::vector<uint8_t>& truncated,
           const Eigen::VectorXf& truncation_values);

  // GAE(λ) over the full buffer (see compute_gae); `last_values` is V(s_T) per environment.
  void finish(const Eigen::VectorXf& last_values, double gamma, double lambda);

  const RowMatrix& observations() const { return observations_; }
  const RowMatrix& actions() const { return actions_; }
  const Eigen::VectorXf& log_probs() const { return log_probs_; }
  const Eigen::VectorXf& values() const { return gae_input_.values; }
  const Eigen::VectorXf& rewards() const { return gae_input_.rewards; }
  const Eigen::VectorXf& advantages() const { return gae_output_.advantages; }
  const Eigen::VectorXf& returns() const { return gae_output_.returns; }

 private:
  int64_t n_steps_, n_envs_;
  int64_t steps_ = 0;
  RowMatrix observations_;
  RowMatrix actions_;
  Eigen::VectorXf log_probs_;
  GaeInput gae_input_;
  GaeOutput gae_output_;
};

// 1 − Var[returns − values] / Var[returns] over a finished buffer: how much of the variation of
// the value targets the value function predicted (1 perfect, 0 no better than a constant).
double explained_variance(const RolloutBuffer& buffer);

}  // namespace tendril::rl
