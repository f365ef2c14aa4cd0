#include "tendril/rl/trpo/trpo_config.hpp"

#include "tendril/core/error.hpp"

namespace tendril::rl {

TrpoConfig TrpoConfig::sb3() { return TrpoConfig{}; }

TrpoConfig TrpoConfig::trpo_v2() {
  TrpoConfig config;
  config.common.n_steps = 1024;
  config.common.gamma = 0.99;
  config.common.gae_lambda = 0.98;
  config.target_kl = 0.01;
  config.cg_max_steps = 10;
  config.cg_damping = 0.01;
  config.n_critic_updates = 3;
  config.batch_size = 128;
  config.learning_rate = 3e-4;
  return config;
}

TrpoConfig TrpoConfig::from_config(const Config& algo) {
  const std::string preset = algo.get_or<std::string>("preset", "sb3");
  TrpoConfig config;
  if (preset == "trpo_v2") {
    config = trpo_v2();
  } else if (preset != "sb3") {
    throw Error("unknown TRPO preset '" + preset + "', expected sb3 or trpo_v2",
                algo.source() + ": " + (algo.path().empty() ? "" : algo.path() + ".") + "preset");
  }
  config.common.read(algo);
  config.target_kl = algo.get_or<double>("target_kl", config.target_kl);
  config.cg_max_steps = algo.get_or<int64_t>("cg_max_steps", config.cg_max_steps);
  config.cg_damping = algo.get_or<double>("cg_damping", config.cg_damping);
  config.line_search_shrinking_factor =
      algo.get_or<double>("line_search_shrinking_factor", config.line_search_shrinking_factor);
  config.line_search_max_iter =
      algo.get_or<int64_t>("line_search_max_iter", config.line_search_max_iter);
  config.n_critic_updates = algo.get_or<int64_t>("n_critic_updates", config.n_critic_updates);
  config.batch_size = algo.get_or<int64_t>("batch_size", config.batch_size);
  config.learning_rate = algo.get_or<double>("learning_rate", config.learning_rate);
  config.adam_epsilon = algo.get_or<double>("adam_epsilon", config.adam_epsilon);
  algo.reject_unknown();
  config.validate();
  return config;
}

void TrpoConfig::validate() const {
  const std::string where = "TRPO config";
  common.validate(where);
  require(!common.policy.shared_trunk, "TRPO needs separate policy and value trunks", where);
  require(target_kl > 0.0, "target_kl must be positive", where);
  require(cg_max_steps >= 1, "cg_max_steps must be at least 1", where);
  require(cg_damping >= 0.0, "cg_damping must be non-negative", where);
  require(line_search_shrinking_factor > 0.0 && line_search_shrinking_factor < 1.0,
          "line_search_shrinking_factor must lie in (0, 1)", where);
  require(line_search_max_iter >= 1, "line_search_max_iter must be at least 1", where);
  require(n_critic_updates >= 0, "n_critic_updates must be non-negative", where);
  require(batch_size >= 1, "batch_size must be at least 1", where);
  require(learning_rate > 0.0 && adam_epsilon > 0.0,
          "learning_rate and adam_epsilon must be positive", where);
}

}  // namespace tendril::rl
