// `tendril record`: episodes of a run's trained policy, recorded into the run's episodes/.
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "command_line.hpp"
#include "commands.hpp"
#include "run_policy.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/wrappers/episode_recorder.hpp"

namespace tendril::apps {

namespace {

namespace fs = std::filesystem;

}  // namespace

int record_command(const std::vector<std::string>& args) {
  const CommandLine line = CommandLine::parse(args, {"episodes", "seed", "out"},
                                              {"best", "deterministic", "stochastic"});
  require(line.positional.size() == 1, "expected one run directory", "command line");
  const fs::path run = line.positional.front();
  require(fs::exists(run / "config.yaml"), "not a run directory (no config.yaml)", run.string());
  const int episodes = static_cast<int>(line.integer("episodes", 1, 1, 100000));
  const uint64_t seed = line.unsigned_integer("seed", 0);
  require(!(line.has("deterministic") && line.has("stochastic")),
          "--deterministic and --stochastic exclude each other", "command line");
  std::optional<bool> deterministic;
  if (line.has("deterministic")) deterministic = true;
  if (line.has("stochastic")) deterministic = false;

  RunPolicy policy = open_run_policy(run, line.has("best"));
  const bool use_deterministic = deterministic.value_or(policy.experiment.eval_deterministic);
  Rng rng(seed, /*stream=*/1);
  const auto act = [&](const Observation& observation) {
    return policy.policy->act(observation, use_deterministic, rng);
  };
  envs::RecordingOptions options;
  options.directory = line.value("out", (run / "episodes").string());
  options.prefix = line.has("best") ? "best" : "episode";
  options.metadata = {{"env", policy.experiment.env.id},
                      {"run", fs::absolute(run).lexically_normal().string()},
                      {"model", policy.source.filename().string()},
                      {"actions", use_deterministic ? "deterministic" : "stochastic"}};
  const auto recorded = envs::record_episodes(*policy.env, act, episodes, seed, options);
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
