#include "tendril/rl/actor_critic_policy.hpp"

#include <cmath>
#include <vector>

#include "tendril/core/error.hpp"

namespace tendril::rl {

namespace {

std::vector<double> as_doubles(const std::vector<int64_t>& values) {
  return std::vector<double>(values.begin(), values.end());
}

// Layer sizes from a file: whole numbers of at most a million units (anything else is a damaged
// or foreign file, refused before a network of that shape is allocated).
std::vector<int64_t> as_sizes(const std::vector<double>& values, const std::string& file) {
  std::vector<int64_t> sizes;
  for (double value : values) {
    require(value >= 1.0 && value <= 1e6 && value == std::floor(value),
            "a layer size in the policy file is not a whole number of 1 to 10^6 units", file);
    sizes.push_back(static_cast<int64_t>(value));
  }
  return sizes;
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
  writer.put("policy_output_activation", spec.policy_output_activation
                                             ? nn::activation_name(*spec.policy_output_activation)
                                             : std::string("none"));
  writer.put("orthogonal_init", int64_t{spec.orthogonal_init});
  writer.put("log_std_init", spec.log_std_init);
  writer.put_floats("parameters", parameters_);
}

std::unique_ptr<Policy> ActorCriticPolicy::read(const ArchiveReader& reader,
                                                const Space& observation_space,
                                                const Space& action_space) {
  nn::ActorCriticSpec spec;
  spec.policy_layers = as_sizes(reader.get_doubles("policy_layers"), reader.name());
  spec.value_layers = as_sizes(reader.get_doubles("value_layers"), reader.name());
  spec.shared_trunk = reader.get_int("shared_trunk") != 0;
  spec.activation = nn::parse_activation(reader.get_string("activation"), reader.name());
  // Files written before the output activation existed have none.
  if (reader.contains("policy_output_activation")) {
    const std::string output = reader.get_string("policy_output_activation");
    if (output != "none")
      spec.policy_output_activation = nn::parse_activation(output, reader.name());
  }
  spec.orthogonal_init = reader.get_int("orthogonal_init") != 0;
  spec.log_std_init = reader.get_double("log_std_init");
  // The shape's parameter count must be the file's before a network of that shape is allocated.
  const Eigen::VectorXf parameters = reader.get_floats("parameters");
  require(nn::ActorCritic(spec.with_spaces(observation_space, action_space)).parameter_count() ==
              parameters.size(),
          "the policy file's parameters do not fit its network's shape", reader.name());
  auto policy = std::make_unique<ActorCriticPolicy>(observation_space, action_space, spec);
  policy->parameters_ = parameters;
  return policy;
}

}  // namespace tendril::rl
