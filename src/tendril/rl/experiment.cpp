#include "tendril/rl/experiment.hpp"

#include <algorithm>
#include <filesystem>
#include <new>
#include <string>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/core/file_kind.hpp"
#include "tendril/rl/algorithm_registry.hpp"
#include "tendril/rl/trainer.hpp"

namespace tendril::rl {

namespace {

std::string key(const Config& config, const std::string& name) {
  return config.source() + ": " + (config.path().empty() ? name : config.path() + "." + name);
}

}  // namespace

Experiment Experiment::from_config(Config config) {
  expect_kind(config, file_kind::kExperiment);
  Experiment e;
  e.config = config;
  e.algorithm = config.get<std::string>("algorithm");
  const AlgorithmSpec& algorithm = algorithm_spec(e.algorithm, key(config, "algorithm"));
  const Config env = config.child("env");
  e.env.id = env.get<std::string>("id");
  e.env.params = env.child("params");
  e.env.wrappers = env.children("wrappers");
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
  e.eval_record = eval.get_or<int>("record", 0);
  require(e.eval_freq >= 0, "must be non-negative", key(eval, "freq"));
  require(e.eval_episodes >= 1, "must be at least 1", key(eval, "episodes"));
  require(e.eval_record >= 0 && e.eval_record <= e.eval_episodes,
          "must lie in [0, eval.episodes] (it is " + std::to_string(e.eval_record) + ")",
          key(eval, "record"));
  e.eval_n_envs = eval.get_or<int>("n_envs", 1);
  require(e.eval_n_envs >= 1, "must be at least 1", key(eval, "n_envs"));
  require(e.eval_n_envs == 1 || (e.eval_record == 0 && !e.env.normalize_observation),
          "evaluating over several envs needs raw observations and no recording (eval.record 0)",
          key(eval, "n_envs"));
  const Config eval_env = eval.child("env");
  for (const std::string& name : eval_env.keys()) {
    e.eval_env_overrides.emplace_back(name, eval_env.get<std::string>(name));
  }
  e.checkpoint_freq = config.get_or<int64_t>("checkpoint_freq", 0);
  require(e.checkpoint_freq >= 0, "must be non-negative", key(config, "checkpoint_freq"));
  e.save_replay_buffer = config.get_or<bool>("save_replay_buffer", false);
  e.output = config.get_or<std::string>("output", "runs/" + e.algorithm);
  e.warm_start = config.get_or<std::string>("warm_start", "");
  if (!e.warm_start.empty()) {
    require(!e.env.normalize_observation,
            "a warm start carries the learned weights, not the observation statistics they were "
            "learned on: train without env.normalize_observation",
            key(config, "warm_start"));
    if (std::filesystem::is_directory(e.warm_start)) {
      try {
        e.warm_start = newest_intact_checkpoint(e.warm_start).string();
      } catch (const Error& error) {
        throw Error(std::string(error.what()) +
                        " (a warm start reads the source run's checkpoints: train it with "
                        "checkpoint_freq > 0)",
                    key(config, "warm_start"));
      }
      config.set("warm_start", e.warm_start);
      e.config = config;
    }
  }

  // Read the algorithm's configuration (the reward discount follows its γ), then build the
  // algorithm once on one copy of the environment: bad keys, and an action space the algorithm
  // cannot handle (DQN on a Box, SAC on unbounded actions), are refused before anything is
  // written. (A replay buffer's memory is reserved, not touched, so this costs little.)
  e.env.reward_gamma = algorithm.gamma(e.algo);
  VecEnvOptions probe_options = e.env;
  probe_options.n_envs = 1;
  probe_options.num_threads = 1;
  probe_options.normalize_observation = probe_options.normalize_reward = false;
  auto probe = make_vec_env(probe_options);
  try {
    const std::unique_ptr<Algorithm> probe_algorithm = algorithm.factory(*probe, e.algo, e.seed);
    // The source must fit (algorithm, spaces, network); one that no longer exists is refused by
    // a new run (rl::train), not by a resumed one, which no longer needs it.
    if (!e.warm_start.empty() && std::filesystem::is_regular_file(e.warm_start)) {
      probe_algorithm->warm_start(e.warm_start);
    }
  } catch (const std::bad_alloc&) {
    throw Error(out_of_memory_message(e), config.source());
  }
  // An evaluation environment once, so that eval.env's keys are checked too.
  if (!e.eval_env_overrides.empty()) make_env(evaluation_env_options(e));
  // Last: the environment's own parameters are read by the environment.
  config.reject_unknown();
  return e;
}

VecEnvOptions evaluation_env_options(const Experiment& experiment) {
  VecEnvOptions options = experiment.env;
  if (experiment.eval_env_overrides.empty()) return options;
  options.params = Config::parse(experiment.env.params.dump(), experiment.config.source());
  for (const auto& [name, value] : experiment.eval_env_overrides) options.params.set(name, value);
  return options;
}

std::string out_of_memory_message(const Experiment& experiment) {
  std::string text = "out of memory building or training the run; the sizes that decide it:";
  for (const char* name : {"buffer_size", "batch_size", "n_steps"}) {
    if (experiment.algo.has(name)) {
      text += std::string(" algo.") + name + " = " +
              std::to_string(experiment.algo.get<int64_t>(name)) + ",";
    }
  }
  if (experiment.algo.has("net_arch")) text += " algo.net_arch,";
  return text + " env.n_envs = " + std::to_string(experiment.env.n_envs);
}

std::unique_ptr<Algorithm> make_algorithm(const Experiment& experiment, envs::VecEnv& env) {
  return algorithm_spec(experiment.algorithm, "experiment")
      .factory(env, experiment.algo, experiment.seed);
}

}  // namespace tendril::rl
