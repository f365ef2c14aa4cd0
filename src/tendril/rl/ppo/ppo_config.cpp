#include "tendril/rl/ppo/ppo_config.hpp"

#include "tendril/core/error.hpp"

namespace tendril::rl {

PpoConfig PpoConfig::sb3() { return PpoConfig{}; }

PpoConfig PpoConfig::ppo1() {
  PpoConfig config;
  config.common.n_steps = 256;
  config.common.gamma = 0.99;
  config.common.gae_lambda = 0.95;
  config.batch_size = 64;
  config.n_epochs = 4;
  config.learning_rate = {1e-3, true};
  config.clip_range = {0.2, true};
  config.ent_coef = 0.01;
  config.vf_coef = 1.0;
  config.max_grad_norm.reset();
  config.adam_epsilon = 1e-5;
  return config;
}

PpoConfig PpoConfig::from_config(const Config& algo) {
  const std::string preset = algo.get_or<std::string>("preset", "sb3");
  PpoConfig config;
  if (preset == "ppo1") {
    config = ppo1();
  } else if (preset != "sb3") {
    throw Error("unknown PPO preset '" + preset + "', expected sb3 or ppo1", algo.where("preset"));
  }
  config.common.read(algo);
  config.batch_size = algo.get_or<int64_t>("batch_size", config.batch_size);
  config.n_epochs = algo.get_or<int64_t>("n_epochs", config.n_epochs);
  config.learning_rate = read_schedule(algo, "learning_rate", config.learning_rate);
  if (algo.has("vf_learning_rate")) {
    config.vf_learning_rate = read_schedule(algo, "vf_learning_rate", Schedule{});
  }
  config.clip_range = read_schedule(algo, "clip_range", config.clip_range);
  config.clip_range_vf = algo.get_optional("clip_range_vf", config.clip_range_vf);
  config.ent_coef = algo.get_or<double>("ent_coef", config.ent_coef);
  config.vf_coef = algo.get_or<double>("vf_coef", config.vf_coef);
  config.max_grad_norm = algo.get_optional("max_grad_norm", config.max_grad_norm);
  config.target_kl = algo.get_optional("target_kl", config.target_kl);
  config.adam_epsilon = algo.get_or<double>("adam_epsilon", config.adam_epsilon);
  algo.reject_unknown();
  config.validate();
  return config;
}

void PpoConfig::validate() const {
  const std::string where = "PPO config";
  common.validate(where);
  require(batch_size >= 1, "batch_size must be at least 1", where);
  require(n_epochs >= 1, "n_epochs must be at least 1", where);
  require(learning_rate.initial > 0.0, "learning_rate must be positive", where);
  require(!vf_learning_rate || vf_learning_rate->initial > 0.0, "vf_learning_rate must be positive",
          where);
  require(clip_range.initial > 0.0, "clip_range must be positive", where);
  require(!clip_range_vf || *clip_range_vf > 0.0, "clip_range_vf must be positive", where);
  require(!max_grad_norm || *max_grad_norm > 0.0, "max_grad_norm must be positive", where);
  require(!target_kl || *target_kl > 0.0, "target_kl must be positive", where);
  require(vf_coef >= 0.0 && ent_coef >= 0.0, "loss coefficients must be non-negative", where);
  require(adam_epsilon > 0.0, "adam_epsilon must be positive", where);
}

}  // namespace tendril::rl
