#pragma once

#include <Eigen/Core>

#include "tendril/core/rng.hpp"
#include "tendril/nn/actor_critic_spec.hpp"
#include "tendril/nn/eigen_mlp.hpp"

namespace tendril::nn {

// The Eigen twin of an ActorCritic, used to act during rollouts and for `predict`. Its weights
// are copied from the LibTorch module by `sync_inference_policy` after every update. Batches
// are matrices with one column per sample (a row-major [n_envs, size] buffer viewed in place).
// Sampling draws from an explicit Rng, so rollouts are reproducible and the stream's state can
// be checkpointed.
class InferencePolicy {
 public:
  InferencePolicy() = default;
  explicit InferencePolicy(const ActorCriticSpec& spec);  // zero weights of spec's shape

  // Actions (action_dims × batch: Gaussian samples unclipped, or indices as floats) and their
  // log-probabilities log π(a|s). `deterministic` takes the mode instead of sampling; the log
  // probabilities are those of the returned actions either way.
  void act(const Eigen::Ref<const Eigen::MatrixXf>& observations, bool deterministic, Rng& rng,
           Eigen::MatrixXf& actions, Eigen::VectorXf& log_probs);
  // V(s) for each column.
  void value(const Eigen::Ref<const Eigen::MatrixXf>& observations, Eigen::VectorXf& values);

  int64_t action_dims() const { return spec_.discrete ? 1 : spec_.action_size; }
  const ActorCriticSpec& spec() const { return spec_; }

  EigenMlp& policy_trunk() { return policy_trunk_; }
  EigenMlp& value_trunk() { return value_trunk_; }
  DenseLayer& policy_head() { return policy_head_; }
  DenseLayer& value_head() { return value_head_; }
  Eigen::VectorXf& log_std() { return log_std_; }

 private:
  ActorCriticSpec spec_;
  EigenMlp policy_trunk_, value_trunk_;
  DenseLayer policy_head_, value_head_;
  Eigen::VectorXf log_std_;
  Eigen::MatrixXf head_output_;  // scratch: means or logits
  Eigen::MatrixXf value_output_;
};

}  // namespace tendril::nn
