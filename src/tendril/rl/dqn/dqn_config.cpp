#include "tendril/rl/dqn/dqn_config.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::rl {

DqnConfig DqnConfig::sb3() {
  DqnConfig config;
  config.common.batch_size = 32;
  config.common.tau = 1.0;
  config.common.train_freq = 4;
  config.common.learning_rate = {1e-4, false};
  config.common.net_arch = {64, 64};
  return config;
}

DqnConfig DqnConfig::from_config(const Config& algo) {
  read_preset(algo, {"sb3"}, "DQN");
  DqnConfig config = sb3();
  config.common.read(algo);
  config.target_update_interval =
      algo.get_or<int64_t>("target_update_interval", config.target_update_interval);
  config.exploration_fraction =
      algo.get_or<double>("exploration_fraction", config.exploration_fraction);
  config.exploration_initial_eps =
      algo.get_or<double>("exploration_initial_eps", config.exploration_initial_eps);
  config.exploration_final_eps =
      algo.get_or<double>("exploration_final_eps", config.exploration_final_eps);
  config.max_grad_norm = algo.get_optional("max_grad_norm", config.max_grad_norm);
  config.double_q = algo.get_or<bool>("double_q", config.double_q);
  config.q_bound = algo.get_optional("q_bound", config.q_bound);
  algo.reject_unknown();
  config.validate();
  return config;
}

void DqnConfig::validate() const {
  const std::string where = "DQN config";
  common.validate(where);
  require(target_update_interval >= 1, "target_update_interval must be at least 1", where);
  require(exploration_fraction > 0.0 && exploration_fraction <= 1.0,
          "exploration_fraction must lie in (0, 1]", where);
  const auto probability = [](double p) { return p >= 0.0 && p <= 1.0; };
  require(probability(exploration_initial_eps) && probability(exploration_final_eps),
          "exploration rates must lie in [0, 1]", where);
  require(!max_grad_norm || *max_grad_norm > 0.0, "max_grad_norm must be positive", where);
  require(!q_bound || (*q_bound > 0.0 && std::isfinite(*q_bound)),
          "q_bound must be a positive number or none", where);
}

}  // namespace tendril::rl
