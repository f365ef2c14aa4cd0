#include "tendril/rl/dqn/q_greedy_policy.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::rl {

namespace {

nn::DenseMlp q_network(const Space& observation_space, const Space& action_space,
                       const std::vector<int64_t>& hidden, nn::Activation activation,
                       bool bounded) {
  require(action_space.is_discrete(),
          "a Q-network policy needs a Discrete action space, not " + action_space.describe(),
          "rl::QGreedyPolicy");
  std::vector<int64_t> sizes{observation_space.size()};
  sizes.insert(sizes.end(), hidden.begin(), hidden.end());
  sizes.push_back(action_space.n());
  return nn::DenseMlp(sizes, activation, /*tanh_output=*/bounded);
}

}  // namespace

QGreedyPolicy::QGreedyPolicy(const Space& observation_space, const Space& action_space,
                             const std::vector<int64_t>& hidden, nn::Activation activation,
                             double q_bound)
    : QGreedyPolicy(observation_space, action_space,
                    q_network(observation_space, action_space, hidden, activation, q_bound > 0.0),
                    q_bound) {}

QGreedyPolicy::QGreedyPolicy(const Space& observation_space, const Space& action_space,
                             nn::DenseMlp network, double q_bound)
    : Policy(observation_space, action_space),
      network_(std::move(network)),
      q_bound_(q_bound),
      parameters_(Eigen::VectorXf::Zero(network_.parameter_count())) {
  require(action_space.is_discrete() && network_.input_size() == observation_space.size() &&
              network_.output_size() == action_space.n(),
          "the Q-network does not fit the spaces", "rl::QGreedyPolicy");
  require(q_bound >= 0.0 && std::isfinite(q_bound) && network_.tanh_output() == (q_bound > 0.0),
          "a bounded Q-head needs a positive bound and a tanh output layer, an unbounded one "
          "neither",
          "rl::QGreedyPolicy");
}

const Eigen::MatrixXf& QGreedyPolicy::q_values(
    const Eigen::Ref<const Eigen::MatrixXf>& observations) const {
  network_.forward(parameters_, observations, tape_);
  if (q_bound_ == 0.0) return tape_.output();
  values_ = static_cast<float>(q_bound_) * tape_.output();
  return values_;
}

void QGreedyPolicy::act_columns(const Eigen::Ref<const Eigen::MatrixXf>& observations,
                                bool deterministic, Rng& rng, Eigen::MatrixXf& actions) const {
  // The argmax of B·tanh(z) is that of z: the bound does not change the choice.
  network_.forward(parameters_, observations, tape_);
  actions.resize(1, observations.cols());
  for (Eigen::Index i = 0; i < observations.cols(); ++i) {
    Eigen::Index best;
    tape_.output().col(i).maxCoeff(&best);
    actions(0, i) = static_cast<float>(best);
    if (!deterministic && rng.uniform() < exploration_rate_) {
      actions(0, i) = static_cast<float>(rng.below(static_cast<uint64_t>(action_space().n())));
    }
  }
}

void QGreedyPolicy::write(ArchiveWriter& writer) const {
  write_mlp(writer, "q_network", network_);
  writer.put_floats("parameters", parameters_);
  writer.put("q_bound", q_bound_);
  writer.put("exploration_rate", exploration_rate_);
}

std::unique_ptr<Policy> QGreedyPolicy::read(const ArchiveReader& reader,
                                            const Space& observation_space,
                                            const Space& action_space) {
  // Policies written before bounded heads existed have no "q_bound": unbounded.
  const double q_bound = reader.contains("q_bound") ? reader.get_double("q_bound") : 0.0;
  std::unique_ptr<QGreedyPolicy> policy(new QGreedyPolicy(
      observation_space, action_space, read_mlp(reader, "q_network"), q_bound));
  policy->parameters_ = reader.get_floats("parameters", policy->parameters_.size());
  policy->exploration_rate_ = reader.get_double("exploration_rate");
  return policy;
}

}  // namespace tendril::rl
