// `tendril eval`: evaluate a run's model on its environment.
#include <cstdio>
#include <filesystem>
#include <string>

#include "command_line.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/evaluation.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/trainer.hpp"

namespace tendril::apps {

int eval_command(const std::vector<std::string>& args) {
  const CommandLine line =
      CommandLine::parse(args, {"episodes", "seed"}, {"deterministic", "best"});
  require(line.positional.size() == 1, "expected one run directory", "command line");
  const std::filesystem::path run = line.positional.front();
  require(std::filesystem::exists(run / "config.yaml"), "not a run directory (no config.yaml)",
          run.string());
  const rl::Experiment experiment =
      rl::Experiment::from_config(Config::load_file(run / "config.yaml"));
  const bool best = line.has("best");
  const std::filesystem::path model = run / (best ? "best_model.policy" : "model.policy");
  require(!best || std::filesystem::exists(model),
          "no best_model.policy (the run's eval.save_best is off)", run.string());
  int episodes = 10;
  uint64_t seed = 0;
  try {
    episodes = std::stoi(line.value("episodes", "10"));
    seed = std::stoull(line.value("seed", "0"));
  } catch (const std::exception&) {
    throw Error("--episodes and --seed expect numbers", "command line");
  }
  require(episodes >= 1, "--episodes must be at least 1", "command line");

  // The finished run's policy file acts on raw observations. A run without one (paused or
  // interrupted) is evaluated from its newest checkpoint, through its training normalization.
  const bool deterministic = line.has("deterministic");
  std::filesystem::path source = model;
  rl::EvaluationResult result;
  if (std::filesystem::exists(model)) {
    const std::unique_ptr<rl::Policy> policy = rl::load_policy(model);
    const std::unique_ptr<Env> env = envs::make(experiment.env.id, experiment.env.params);
    result = rl::evaluate_policy(*policy, *env, episodes, deterministic, seed);
  } else {
    source = rl::latest_checkpoint(run);
    const std::unique_ptr<envs::VecEnv> training_env = rl::make_vec_env(experiment.env);
    const std::unique_ptr<rl::Algorithm> algorithm = rl::make_algorithm(experiment, *training_env);
    algorithm->load(source);
    const std::unique_ptr<Env> env = rl::make_evaluation_env(experiment.env, *training_env);
    result = rl::evaluate_policy(algorithm->policy(), *env, episodes, deterministic, seed);
  }
  std::printf("%s on %s, %d episodes (%s): mean return %.3f +/- %.3f\n", source.string().c_str(),
              experiment.env.id.c_str(), episodes, deterministic ? "deterministic" : "stochastic",
              result.mean_return(), result.std_return());
  for (std::size_t i = 0; i < result.returns.size(); ++i) {
    std::printf("  episode %2zu: return %10.3f  length %lld\n", i, result.returns[i],
                static_cast<long long>(result.lengths[i]));
  }
  return 0;
}

}  // namespace tendril::apps
