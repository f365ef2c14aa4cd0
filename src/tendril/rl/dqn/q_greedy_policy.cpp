#include "tendril/rl/dqn/q_greedy_policy.hpp"

#include "tendril/core/error.hpp"

namespace tendril::rl {

namespace {

nn::DenseMlp q_network(const Space& observation_space, const Space& action_space,
                       const std::vector<int64_t>& hidden, nn::Activation activation) {
  require(action_space.is_discrete(),
          "a Q-network policy needs a Discrete action space, not " + action_space.describe(),
          "rl::QGreedyPolicy");
  std::vector<int64_t> sizes{observation_space.size()};
  sizes.insert(sizes.end(), hidden.begin(), hidden.end());
  sizes.push_back(action_space.n());
  return nn::DenseMlp(sizes, activation);
}

}  // namespace

QGreedyPolicy::QGreedyPolicy(const Space& observation_space, const Space& action_space,
                             const std::vector<int64_t>& hidden, nn::Activation activation)
    : QGreedyPolicy(observation_space, action_space,
                    q_network(observation_space, action_space, hidden, activation)) {}

QGreedyPolicy::QGreedyPolicy(const Space& observation_space, const Space& action_space,
                             nn::DenseMlp network)
    : Policy(observation_space, action_space),
      network_(std::move(network)),
      parameters_(Eigen::VectorXf::Zero(network_.parameter_count())) {
  require(action_space.is_discrete() && network_.input_size() == observation_space.size() &&
              network_.output_size() == action_space.n() && !network_.tanh_output(),
          "the Q-network does not fit the spaces", "rl::QGreedyPolicy");
}

void QGreedyPolicy::act_columns(const Eigen::Ref<const Eigen::MatrixXf>& observations,
                                bool deterministic, Rng& rng, Eigen::MatrixXf& actions) const {
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
  writer.put("exploration_rate", exploration_rate_);
}

std::unique_ptr<Policy> QGreedyPolicy::read(const ArchiveReader& reader,
                                            const Space& observation_space,
                                            const Space& action_space) {
  std::unique_ptr<QGreedyPolicy> policy(
      new QGreedyPolicy(observation_space, action_space, read_mlp(reader, "q_network")));
  policy->parameters_ = reader.get_floats("parameters", policy->parameters_.size());
  policy->exploration_rate_ = reader.get_double("exploration_rate");
  return policy;
}

}  // namespace tendril::rl
