#include "tendril/rl/actor_critic_policy.hpp"

#include <vector>

namespace tendril::rl {

namespace {

std::vector<double> as_doubles(const std::vector<int64_t>& values) {
  return std::vector<double>(values.begin(), values.end());
}

std::vector<int64_t> as_sizes(const std::vector<double>& values) {
  return std::vector<int64_t>(values.begin(), values.end());
}

}  // namespace

ActorCriticPolicy::ActorCriticPolicy(const Space& observation_space, const Space& action_space,
                                     const nn::ActorCriticSpec& spec)
    : Policy(observation_space, action_space),
      network_(spec.with_spaces(observation_space, action_space)),
      parameters_(Eigen::VectorXf::Zero(network_.parameter_count())) {}

void ActorCriticPolicy::sample(const Eigen::Ref<const Eigen::MatrixXf>& observations, Rng& rng,
                               Eigen::MatrixXf& actions, Eigen::VectorXf& log_probs) const {
  network_.act(parameters_, observations, /*deterministic=*/false, rng, actions, log_probs, tape_);
}

void ActorCriticPolicy::values(const Eigen::Ref<const Eigen::MatrixXf>& observations,
                               Eigen::VectorXf& values) const {
  network_.value(parameters_, observations, values, tape_);
}

void ActorCriticPolicy::act_columns(const Eigen::Ref<const Eigen::MatrixXf>& observations,
                                    bool deterministic, Rng& rng, Eigen::MatrixXf& actions) const {
  network_.act(parameters_, observations, deterministic, rng, actions, log_probs_, tape_);
  clip_to_bounds(action_space(), actions);
}

void ActorCriticPolicy::write(ArchiveWriter& writer) const {
  const nn::ActorCriticSpec& spec = network_.spec();
  writer.put_doubles("policy_layers", as_doubles(spec.policy_layers));
  writer.put_doubles("value_layers", as_doubles(spec.value_layers));
  writer.put("shared_trunk", int64_t{spec.shared_trunk});
  writer.put("activation", nn::activation_name(spec.activation));
  writer.put("orthogonal_init", int64_t{spec.orthogonal_init});
  writer.put("log_std_init", spec.log_std_init);
  writer.put_floats("parameters", parameters_);
}

std::unique_ptr<Policy> ActorCriticPolicy::read(const ArchiveReader& reader,
                                                const Space& observation_space,
                                                const Space& action_space) {
  nn::ActorCriticSpec spec;
  spec.policy_layers = as_sizes(reader.get_doubles("policy_layers"));
  spec.value_layers = as_sizes(reader.get_doubles("value_layers"));
  spec.shared_trunk = reader.get_int("shared_trunk") != 0;
  spec.activation = nn::parse_activation(reader.get_string("activation"), reader.name());
  spec.orthogonal_init = reader.get_int("orthogonal_init") != 0;
  spec.log_std_init = reader.get_double("log_std_init");
  auto policy = std::make_unique<ActorCriticPolicy>(observation_space, action_space, spec);
  policy->parameters_ = reader.get_floats("parameters", policy->parameters_.size());
  return policy;
}

}  // namespace tendril::rl
