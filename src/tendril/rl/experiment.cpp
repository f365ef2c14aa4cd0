#include "tendril/rl/experiment.hpp"

#include <algorithm>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/rl/dqn/dqn.hpp"
#include "tendril/rl/ppo/ppo.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/td3/td3.hpp"
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
  const std::vector<std::string> known{"ppo", "trpo", "sac", "td3", "ddpg", "dqn"};
  if (std::find(known.begin(), known.end(), e.algorithm) == known.end()) {
    throw Error(
        "unknown algorithm '" + e.algorithm + "' (expected ppo, trpo, sac, td3, ddpg or dqn)",
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
  e.eval_save_best = eval.get_or<bool>("save_best", false);
  require(e.eval_freq >= 0, "must be non-negative", key(eval, "freq"));
  require(e.eval_episodes >= 1, "must be at least 1", key(eval, "episodes"));
  e.checkpoint_freq = config.get_or<int64_t>("checkpoint_freq", 0);
  require(e.checkpoint_freq >= 0, "must be non-negative", key(config, "checkpoint_freq"));
  e.save_replay_buffer = config.get_or<bool>("save_replay_buffer", false);
  e.output = config.get_or<std::string>("output", "runs/" + e.algorithm);

  // Build the environment and the algorithm's configuration once: their keys are checked
  // before anything is written (the VecEnv reward discount follows the algorithm's γ).
  if (e.algorithm == "ppo") {
    e.env.reward_gamma = PpoConfig::from_config(e.algo).common.gamma;
  } else if (e.algorithm == "trpo") {
    e.env.reward_gamma = TrpoConfig::from_config(e.algo).common.gamma;
  } else if (e.algorithm == "sac") {
    e.env.reward_gamma = SacConfig::from_config(e.algo).common.gamma;
  } else if (e.algorithm == "td3" || e.algorithm == "ddpg") {
    e.env.reward_gamma = Td3Config::from_config(e.algo, e.algorithm == "ddpg").common.gamma;
  } else {
    e.env.reward_gamma = DqnConfig::from_config(e.algo).common.gamma;
  }
  // The algorithm on one copy of the environment: an action space it cannot handle (DQN on a
  // Box, SAC on unbounded actions) is refused here. (A replay buffer's memory is reserved, not
  // touched, so this costs little.)
  auto probe = make_vec_env(VecEnvOptions{e.env.id, e.env.params, 1, 1, false, false, 0.99});
  make_algorithm(e, *probe);
  // Last: the environment's own parameters are read by the environment.
  config.reject_unknown();
  return e;
}

std::unique_ptr<Algorithm> make_algorithm(const Experiment& experiment, envs::VecEnv& env) {
  const std::string& name = experiment.algorithm;
  const uint64_t seed = experiment.seed;
  if (name == "ppo")
    return std::make_unique<Ppo>(env, PpoConfig::from_config(experiment.algo), seed);
  if (name == "trpo") {
    return std::make_unique<Trpo>(env, TrpoConfig::from_config(experiment.algo), seed);
  }
  if (name == "sac")
    return std::make_unique<Sac>(env, SacConfig::from_config(experiment.algo), seed);
  if (name == "td3" || name == "ddpg") {
    return std::make_unique<Td3>(env, Td3Config::from_config(experiment.algo, name == "ddpg"),
                                 seed);
  }
  return std::make_unique<Dqn>(env, DqnConfig::from_config(experiment.algo), seed);
}

}  // namespace tendril::rl
