#include "tendril/rl/td3/td3_config.hpp"

#include "tendril/core/error.hpp"

namespace tendril::rl {

namespace {

void make_ddpg(Td3Config& config) {
  config.n_critics = 1;
  config.policy_delay = 1;
  config.target_policy_noise = 0.0;
}

}  // namespace

Td3Config Td3Config::sb3(Td3Variant variant) {
  const bool ddpg = variant == Td3Variant::kDdpg;
  Td3Config config;
  config.common.learning_rate = {1e-3, false};
  config.common.net_arch = {400, 300};
  if (ddpg) make_ddpg(config);
  return config;
}

Td3Config Td3Config::sb2(Td3Variant variant) {
  const bool ddpg = variant == Td3Variant::kDdpg;
  Td3Config config;
  config.common.buffer_size = 50'000;
  config.common.batch_size = 128;
  config.common.net_arch = {64, 64};
  config.common.train_freq = 100;
  if (ddpg) {
    make_ddpg(config);
    config.common.gradient_steps = 50;
    config.common.learning_rate = {1e-4, false};
    config.critic_learning_rate = 1e-3;
    config.common.tau = 0.001;
  } else {
    config.common.gradient_steps = 100;
    config.common.learning_rate = {3e-4, false};
  }
  return config;
}

Td3Config Td3Config::from_config(const Config& algo, Td3Variant variant) {
  const bool ddpg = variant == Td3Variant::kDdpg;
  const std::string name = ddpg ? "DDPG" : "TD3";
  Td3Config config = read_preset(algo, {"sb3", "sb2"}, name) == "sb2" ? sb2(variant) : sb3(variant);
  config.common.read(algo);
  if (!ddpg) {
    config.n_critics = algo.get_or<int>("n_critics", config.n_critics);
    config.policy_delay = algo.get_or<int64_t>("policy_delay", config.policy_delay);
    config.target_policy_noise =
        algo.get_or<double>("target_policy_noise", config.target_policy_noise);
    config.target_noise_clip = algo.get_or<double>("target_noise_clip", config.target_noise_clip);
  }
  config.critic_learning_rate =
      algo.get_optional("critic_learning_rate", config.critic_learning_rate, "learning_rate");
  config.action_noise.read(algo);
  algo.reject_unknown();
  config.validate(name + " config");
  return config;
}

void Td3Config::validate(const std::string& where) const {
  common.validate(where);
  require(n_critics >= 1, "n_critics must be at least 1", where);
  require(policy_delay >= 1, "policy_delay must be at least 1", where);
  require(target_policy_noise >= 0.0 && target_noise_clip >= 0.0,
          "target_policy_noise and target_noise_clip must be non-negative", where);
  require(!critic_learning_rate || *critic_learning_rate > 0.0,
          "critic_learning_rate must be positive", where);
  action_noise.validate(where);
}

}  // namespace tendril::rl
