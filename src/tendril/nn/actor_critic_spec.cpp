#include "tendril/nn/actor_critic_spec.hpp"

#include <string>

#include "tendril/core/error.hpp"

namespace tendril::nn {

namespace {

std::vector<int64_t> read_layers(const Config& policy, const char* key,
                                 const std::vector<int64_t>& fallback) {
  std::vector<int64_t> layers = policy.get_or<std::vector<int64_t>>(key, fallback);
  for (int64_t units : layers) {
    require(units > 0, "layer sizes must be positive, got " + std::to_string(units),
            policy.where(key));
  }
  return layers;
}

}  // namespace

ActorCriticSpec ActorCriticSpec::with_spaces(const Space& observation_space,
                                             const Space& action_space) const {
  require(observation_space.is_box(),
          "observations must be a Box, got " + observation_space.describe(), "nn::ActorCriticSpec");
  ActorCriticSpec spec = *this;
  spec.observation_size = observation_space.size();
  spec.discrete = action_space.is_discrete();
  spec.action_size = spec.discrete ? action_space.n() : action_space.size();
  return spec;
}

ActorCriticSpec ActorCriticSpec::from_config(const Config& policy,
                                             const ActorCriticSpec& fallback) {
  ActorCriticSpec spec = fallback;
  const std::vector<int64_t> both = read_layers(policy, "net_arch", spec.policy_layers);
  spec.policy_layers = read_layers(policy, "pi_layers", both);
  spec.value_layers =
      read_layers(policy, "vf_layers", policy.has("net_arch") ? both : spec.value_layers);
  spec.shared_trunk = policy.get_or<bool>("shared_trunk", spec.shared_trunk);
  spec.activation =
      parse_activation(policy.get_or<std::string>("activation", activation_name(spec.activation)),
                       policy.where("activation"));
  if (policy.has("pi_output_activation")) {
    const std::string name = policy.get<std::string>("pi_output_activation");
    spec.policy_output_activation.reset();
    if (name != "none") {
      spec.policy_output_activation = parse_activation(name, policy.where("pi_output_activation"));
    }
  }
  spec.orthogonal_init = policy.get_or<bool>("ortho_init", spec.orthogonal_init);
  spec.log_std_init = policy.get_or<double>("log_std_init", spec.log_std_init);
  return spec;
}

ActorCriticSpec ActorCriticSpec::from_config(const Config& policy) {
  return from_config(policy, ActorCriticSpec{});
}

}  // namespace tendril::nn
