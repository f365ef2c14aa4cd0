#pragma once

#include <Eigen/Core>
#include <memory>

#include "tendril/nn/actor_critic.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::rl {

// The policy of an on-policy actor-critic (PPO, TRPO; SB3's ActorCriticPolicy): a diagonal
// Gaussian with state-independent log σ over a Box, or a categorical over a Discrete space,
// plus the value network the algorithm trains beside it. Acting clips Gaussian samples to the
// Box's bounds (SB3 clips before stepping); the rollout stores them unclipped. The parameters
// are the trained ones (the algorithm's optimizer updates `parameters()` in place).
class ActorCriticPolicy : public Policy {
 public:
  // Zero parameters of the shape `spec` takes for these spaces (spec's sizes are set from them).
  ActorCriticPolicy(const Space& observation_space, const Space& action_space,
                    const nn::ActorCriticSpec& spec);

  std::string kind() const override { return "actor_critic"; }
  const nn::ActorCritic& network() const { return network_; }
  Eigen::VectorXf& parameters() { return parameters_; }
  const Eigen::VectorXf& parameters() const { return parameters_; }

  // For rollouts, on observations as the algorithm sees them (one column each): actions as
  // sampled (unclipped), their log π, and V(s).
  void sample(const Eigen::Ref<const Eigen::MatrixXf>& observations, Rng& rng,
              Eigen::MatrixXf& actions, Eigen::VectorXf& log_probs) const;
  void values(const Eigen::Ref<const Eigen::MatrixXf>& observations, Eigen::VectorXf& values) const;

  // The policy of a model file (Policy::save), for load_policy.
  static std::unique_ptr<Policy> read(const ArchiveReader& reader, const Space& observation_space,
                                      const Space& action_space);

 protected:
  void act_columns(const Eigen::Ref<const Eigen::MatrixXf>& observations, bool deterministic,
                   Rng& rng, Eigen::MatrixXf& actions) const override;
  void write(ArchiveWriter& writer) const override;

 private:
  nn::ActorCritic network_;
  Eigen::VectorXf parameters_;
  mutable nn::ActorCritic::Tape tape_;
  mutable Eigen::VectorXf log_probs_;
};

}  // namespace tendril::rl
