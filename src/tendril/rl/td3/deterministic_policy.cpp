#include "tendril/rl/td3/deterministic_policy.hpp"

#include "tendril/core/error.hpp"

namespace tendril::rl {

namespace {

nn::DenseMlp actor(const Space& observation_space, const Space& action_space,
                   const std::vector<int64_t>& hidden, nn::Activation activation) {
  require(action_space.is_box(),
          "a deterministic actor needs a Box action space, not " + action_space.describe(),
          "rl::DeterministicPolicy");
  std::vector<int64_t> sizes{observation_space.size()};
  sizes.insert(sizes.end(), hidden.begin(), hidden.end());
  sizes.push_back(action_space.size());
  return nn::DenseMlp(sizes, activation, /*tanh_output=*/true);
}

}  // namespace

DeterministicPolicy::DeterministicPolicy(const Space& observation_space, const Space& action_space,
                                         const std::vector<int64_t>& hidden,
                                         nn::Activation activation)
    : DeterministicPolicy(observation_space, action_space,
                          actor(observation_space, action_space, hidden, activation)) {}

DeterministicPolicy::DeterministicPolicy(const Space& observation_space, const Space& action_space,
                                         nn::DenseMlp network)
    : Policy(observation_space, action_space),
      network_(std::move(network)),
      parameters_(Eigen::VectorXf::Zero(network_.parameter_count())) {
  require(network_.input_size() == observation_space.size() &&
              network_.output_size() == action_space.size() && network_.tanh_output(),
          "the actor does not fit the spaces", "rl::DeterministicPolicy");
}

void DeterministicPolicy::act_columns(const Eigen::Ref<const Eigen::MatrixXf>& observations,
                                      bool /*deterministic*/, Rng& /*rng*/,
                                      Eigen::MatrixXf& actions) const {
  network_.forward(parameters_, observations, tape_);
  actions = tape_.output();
  scale_to_bounds(action_space(), actions);
}

void DeterministicPolicy::write(ArchiveWriter& writer) const {
  write_mlp(writer, "actor", network_);
  writer.put_floats("parameters", parameters_);
}

std::unique_ptr<Policy> DeterministicPolicy::read(const ArchiveReader& reader,
                                                  const Space& observation_space,
                                                  const Space& action_space) {
  std::unique_ptr<DeterministicPolicy> policy(
      new DeterministicPolicy(observation_space, action_space, read_mlp(reader, "actor")));
  policy->parameters_ = reader.get_floats("parameters", policy->parameters_.size());
  return policy;
}

}  // namespace tendril::rl
