#pragma once

#include <Eigen/Core>
#include <memory>

#include "tendril/nn/dense_mlp.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::rl {

// A Q-network's greedy policy (DQN; SB3's QNetwork): the action of the largest Q(s, ·), the
// first on ties. Not deterministic, it is ε-greedy with `exploration_rate` (SB3's predict):
// with that probability a uniformly random action. The parameters are the trained ones.
class QGreedyPolicy : public Policy {
 public:
  QGreedyPolicy(const Space& observation_space, const Space& action_space,
                const std::vector<int64_t>& hidden, nn::Activation activation);

  std::string kind() const override { return "q_greedy"; }
  const nn::DenseMlp& network() const { return network_; }
  Eigen::VectorXf& parameters() { return parameters_; }
  const Eigen::VectorXf& parameters() const { return parameters_; }
  double exploration_rate() const { return exploration_rate_; }
  void set_exploration_rate(double rate) { exploration_rate_ = rate; }

  static std::unique_ptr<Policy> read(const ArchiveReader& reader, const Space& observation_space,
                                      const Space& action_space);

 protected:
  void act_columns(const Eigen::Ref<const Eigen::MatrixXf>& observations, bool deterministic,
                   Rng& rng, Eigen::MatrixXf& actions) const override;
  void write(ArchiveWriter& writer) const override;

 private:
  QGreedyPolicy(const Space& observation_space, const Space& action_space, nn::DenseMlp network);

  nn::DenseMlp network_;
  Eigen::VectorXf parameters_;
  double exploration_rate_ = 0.0;
  mutable nn::DenseMlp::Tape tape_;
};

}  // namespace tendril::rl
