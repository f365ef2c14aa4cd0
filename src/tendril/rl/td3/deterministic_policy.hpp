#pragma once

#include <Eigen/Core>
#include <memory>

#include "tendril/nn/dense_mlp.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::rl {

// A deterministic actor (TD3, DDPG; SB3's TD3Policy actor): a = tanh(MLP(s)) in [−1, 1],
// mapped affinely onto the Box's bounds. Acting is the same with and without `deterministic`
// (exploration noise belongs to the algorithm's collection, as in SB3's predict). The
// parameters are the trained ones.
class DeterministicPolicy : public Policy {
 public:
  // A zero-initialised actor with `hidden` layers of `activation`.
  DeterministicPolicy(const Space& observation_space, const Space& action_space,
                      const std::vector<int64_t>& hidden, nn::Activation activation);

  std::string kind() const override { return "deterministic"; }
  const nn::DenseMlp& network() const { return network_; }
  Eigen::VectorXf& parameters() { return parameters_; }
  const Eigen::VectorXf& parameters() const { return parameters_; }

  static std::unique_ptr<Policy> read(const ArchiveReader& reader, const Space& observation_space,
                                      const Space& action_space);

 protected:
  void act_columns(const Eigen::Ref<const Eigen::MatrixXf>& observations, bool deterministic,
                   Rng& rng, Eigen::MatrixXf& actions) const override;
  void write(ArchiveWriter& writer) const override;

 private:
  DeterministicPolicy(const Space& observation_space, const Space& action_space,
                      nn::DenseMlp network);

  nn::DenseMlp network_;
  Eigen::VectorXf parameters_;
  mutable nn::DenseMlp::Tape tape_;
};

}  // namespace tendril::rl
