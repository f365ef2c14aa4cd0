#include "tendril/rl/experiment.hpp"

#include "tendril/core/error.hpp"
#include "tendril/rl/ppo/ppo.hpp"
#include "tendril/rl/trpo/trpo.hpp"

namespace tendril::rl {

namespace {

std::string key(const Config& config, const std::string& name) {
  return config.source() + ": " + (config.path().empty() ? name : config.path() + "." + name);
}

}  // namespace

Experiment Experiment::from_config(Config config) {
  Experiment e;
  e.config = config;
  e.algorithm = config.get<std::string>("algorithm");
  if (e.algorithm != "ppo" && e.algorithm != "trpo") {
    throw Error("unknown algorithm '" + e.algorithm + "' (expected ppo or trpo)",
                key(config, "algorithm"));
  }
  const Config env = config.child("env");
  e.env.id = env.get<std::string>("id");
  e.env.params = env.child("params");
  e.env.n_envs = env.get_or<int>("n_envs", 1);
  e.env.num_threads = env.get_or<int>("num_threads", 1);
  e.env.normalize_observation = env.get_or<bool>("normalize_observation", false);
  e.env.normalize_reward = env.get_or<bool>("normalize_reward", false);
  require(e.env.n_envs >= 1, "must be at least 1", key(env, "n_envs"));
  require(e.env.num_threads >= 1, "must be at least 1", key(env, "num_threads"));
  e.algo = config.child("algo");
  e.n_timesteps = config.get<int64_t>("n_timesteps");
  require(e.n_timesteps >= 1, "must be at least 1", key(config, "n_timesteps"));
  e.seed = config.get_or<uint64_t>("seed", 0);
  const Config eval = config.child("eval");
  e.eval_freq = eval.get_or<int64_t>("freq", 0);
  e.eval_episodes = eval.get_or<int>("episodes", 10);
  e.eval_deterministic = eval.get_or<bool>("deterministic", true);
  require(e.eval_freq >= 0, "must be non-negative", key(eval, "freq"));
  require(e.eval_episodes >= 1, "must be at least 1", key(eval, "episodes"));
  e.checkpoint_freq = config.get_or<int64_t>("checkpoint_freq", 0);
  require(e.checkpoint_freq >= 0, "must be non-negative", key(config, "checkpoint_freq"));
  e.output = config.get_or<std::string>("output", "runs/" + e.algorithm);

  // Build the environment and the algorithm's configuration once: their keys are checked
  // before anything is written (the VecEnv reward discount follows the algorithm's γ).
  if (e.algorithm == "ppo") {
    const PpoConfig ppo = PpoConfig::from_config(e.algo);
    e.env.reward_gamma = ppo.common.gamma;
  } else {
    const TrpoConfig trpo = TrpoConfig::from_config(e.algo);
    e.env.reward_gamma = trpo.common.gamma;
  }
  make_vec_env(VecEnvOptions{e.env.id, e.env.params, 1, 1, false, false, 0.99});
  config.reject_unknown();
  return e;
}

std::unique_ptr<OnPolicyAlgorithm> make_algorithm(const Experiment& experiment, envs::VecEnv& env) {
  if (experiment.algorithm == "ppo") {
    return std::make_unique<Ppo>(env, PpoConfig::from_config(experiment.algo), experiment.seed);
  }
  return std::make_unique<Trpo>(env, TrpoConfig::from_config(experiment.algo), experiment.seed);
}

}  // namespace tendril::rl
