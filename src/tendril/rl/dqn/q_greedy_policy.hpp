#pragma once

#include <Eigen/Core>
#include <memory>

#include "tendril/nn/dense_mlp.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::rl {

// A Q-network's greedy policy (DQN; SB3's QNetwork): the action of the largest Q(s, ·), the
// first on ties. Not deterministic, it is ε-greedy with `exploration_rate` (SB3's predict):
// with that probability a uniformly random action. The parameters are the trained ones.
//
// With a positive `q_bound` B the Q-head is bounded, Q = B·tanh(z) (the network's output layer
// is tanh): seed 001's limb safety DQN bounds its values to ±1/(1 − γ) this way.
class QGreedyPolicy : public Policy {
 public:
  QGreedyPolicy(const Space& observation_space, const Space& action_space,
                const std::vector<int64_t>& hidden, nn::Activation activation,
                double q_bound = 0.0);

  std::string kind() const override { return "q_greedy"; }
  const nn::DenseMlp& network() const { return network_; }
  double q_bound() const { return q_bound_; }  // 0: unbounded
  // Q(s, ·) of the trained parameters: action_count × batch, one column per observation column.
  const Eigen::MatrixXf& q_values(const Eigen::Ref<const Eigen::MatrixXf>& observations) const;
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
  QGreedyPolicy(const Space& observation_space, const Space& action_space, nn::DenseMlp network,
                double q_bound);

  nn::DenseMlp network_;
  double q_bound_ = 0.0;
  Eigen::VectorXf parameters_;
  double exploration_rate_ = 0.0;
  mutable nn::DenseMlp::Tape tape_;
  mutable Eigen::MatrixXf values_;
};

}  // namespace tendril::rl
