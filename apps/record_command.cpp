// `tendril record`: episodes of a run's trained policy, recorded into the run's episodes/.
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "command_line.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/wrappers/episode_recorder.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/rl/trainer.hpp"

namespace tendril::apps {

namespace {

namespace fs = std::filesystem;

// A run's trained policy on a fresh evaluation environment (raw rewards, the run's frozen
// observation statistics), as `tendril eval` builds it.
struct RunPolicy {
  std::unique_ptr<Env> env;
  std::function<Action(const Observation&)> act;
  std::string env_id;
  fs::path model;
  bool deterministic = true;
};

// The one place that reaches into rl/: rebuilds the run's algorithm and loads its model.
RunPolicy load_run_policy(const fs::path& run, bool best, std::optional<bool> deterministic) {
  const rl::Experiment experiment =
      rl::Experiment::from_config(Config::load_file(run / "config.yaml"));
  RunPolicy policy;
  policy.model = fs::exists(run / "model.pt") ? run / "model.pt" : rl::latest_checkpoint(run);
  if (best) {
    policy.model = run / "best_model.pt";
    require(fs::exists(policy.model), "no best_model.pt (the run's eval.save_best is off)",
            run.string());
  }
  auto training_env = std::shared_ptr<envs::VecEnv>(rl::make_vec_env(experiment.env));
  auto algorithm = std::shared_ptr<rl::Algorithm>(rl::make_algorithm(experiment, *training_env));
  algorithm->load(policy.model);
  policy.env = rl::make_evaluation_env(experiment.env, *training_env);
  policy.env_id = experiment.env.id;
  policy.deterministic = deterministic.value_or(experiment.eval_deterministic);
  policy.act = [training_env, algorithm, d = policy.deterministic](const Observation& o) {
    return algorithm->predict(o, d);
  };
  return policy;
}

}  // namespace

int record_command(const std::vector<std::string>& args) {
  const CommandLine line = CommandLine::parse(args, {"episodes", "seed", "out"},
                                              {"best", "deterministic", "stochastic"});
  require(line.positional.size() == 1, "expected one run directory", "command line");
  const fs::path run = line.positional.front();
  require(fs::exists(run / "config.yaml"), "not a run directory (no config.yaml)", run.string());
  int episodes = 1;
  uint64_t seed = 0;
  try {
    episodes = std::stoi(line.value("episodes", "1"));
    seed = std::stoull(line.value("seed", "0"));
  } catch (const std::exception&) {
    throw Error("--episodes and --seed expect numbers", "command line");
  }
  require(episodes >= 1, "--episodes must be at least 1", "command line");
  require(!(line.has("deterministic") && line.has("stochastic")),
          "--deterministic and --stochastic exclude each other", "command line");
  std::optional<bool> deterministic;
  if (line.has("deterministic")) deterministic = true;
  if (line.has("stochastic")) deterministic = false;

  RunPolicy policy = load_run_policy(run, line.has("best"), deterministic);
  envs::RecordingOptions options;
  options.directory = line.value("out", (run / "episodes").string());
  options.prefix = line.has("best") ? "best" : "episode";
  options.metadata = {{"env", policy.env_id},
                      {"run", fs::absolute(run).lexically_normal().string()},
                      {"model", policy.model.filename().string()},
                      {"actions", policy.deterministic ? "deterministic" : "stochastic"}};
  const auto recorded = envs::record_episodes(*policy.env, policy.act, episodes, seed, options);
  for (const envs::RecordedEpisode& episode : recorded) {
    std::printf("%s: %lld steps, return %.3f%s\n", episode.file.string().c_str(),
                static_cast<long long>(episode.summary.steps), episode.summary.episode_return,
                episode.summary.terminated ? " (terminated)" : "");
  }
  std::printf("replay: tendril serve %s\n",
              run.parent_path().empty() ? "." : run.parent_path().string().c_str());
  return 0;
}

}  // namespace tendril::apps
