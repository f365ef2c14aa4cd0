// `tendril eval`: evaluate a run's model on its environment.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>

#include "command_line.hpp"
#include "commands.hpp"
#include "run_policy.hpp"
#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/runner/policy_runner.hpp"
#include "tendril/rl/open_loop.hpp"

namespace tendril::apps {

namespace {

template <typename T>
double mean_of(const std::vector<T>& values) {
  double sum = 0.0;
  for (T value : values) sum += static_cast<double>(value);
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

template <typename T>
double sd_of(const std::vector<T>& values) {
  const double mean = mean_of(values);
  double sum = 0.0;
  for (T value : values)
    sum += (static_cast<double>(value) - mean) * (static_cast<double>(value) - mean);
  return values.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(values.size()));
}

// One row per episode: episode, return, length, then the final step's info values.
std::string episodes_csv(const envs::RunResult& result) {
  std::ostringstream csv;
  csv.precision(10);
  csv << "episode,return,length";
  const Info& first = result.episodes.front().final_info;
  for (const auto& entry : first.entries()) csv << "," << entry.first;
  csv << "\n";
  for (const envs::EpisodeOutcome& episode : result.episodes) {
    csv << episode.index << "," << episode.episode_return << "," << episode.length;
    for (const auto& entry : first.entries()) {
      csv << "," << episode.final_info.get(entry.first).value_or(0.0);
    }
    csv << "\n";
  }
  return csv.str();
}

}  // namespace

int eval_command(const std::vector<std::string>& args) {
  const CommandLine line =
      CommandLine::parse(args, {"episodes", "seed", "out"}, {"deterministic", "best", "open-loop"});
  require(line.positional.size() == 1, "expected one run directory", "command line");
  const std::filesystem::path run = line.positional.front();
  const int episodes = static_cast<int>(line.integer("episodes", 10, 1, 1000000));
  const uint64_t seed = line.unsigned_integer("seed", 0);

  const bool deterministic = line.has("deterministic");
  const std::filesystem::path out = line.value("out", "");
  // Refused before the work: nothing is overwritten.
  if (!out.empty())
    require(!std::filesystem::exists(out), "exists; nothing is overwritten", out.string());
  const RunPolicy policy = open_run_policy(run, line.has("best"), line.overrides);
  envs::RunResult result;
  if (line.has("open-loop")) {
    // The policy acts once in the run's own environment; its actions replay on this one.
    const RunPolicy trained = open_run_policy(run, line.has("best"));
    const std::vector<Action> actions =
        rl::recorded_actions(*trained.policy, *trained.env, deterministic, seed);
    std::printf("open loop: %zu actions of one episode on %s, replayed\n", actions.size(),
                trained.experiment.env.id.c_str());
    result = rl::replay_actions(actions, *policy.env, episodes, seed);
  } else {
    envs::RunSettings settings;
    settings.episodes = episodes;
    settings.seed = seed;
    settings.deterministic = deterministic;
    result = envs::run_policy(*policy.policy, *policy.env, settings);
  }
  std::printf("%s on %s, %d episodes (%s): mean return %.3f +/- %.3f\n",
              policy.source.string().c_str(), policy.experiment.env.id.c_str(), episodes,
              line.has("open-loop") ? "open loop"
              : deterministic       ? "deterministic"
                                    : "stochastic",
              result.mean_return(), result.std_return());
  for (const envs::EpisodeOutcome& episode : result.episodes) {
    std::printf("  episode %2lld: return %10.3f  length %lld",
                static_cast<long long>(episode.index), episode.episode_return,
                static_cast<long long>(episode.length));
    for (const auto& [name, value] : episode.final_info.entries()) {
      std::printf("  %s %.6g", name.c_str(), value);
    }
    std::printf("\n");
  }
  // Each info value at the episodes' ends: mean and standard deviation over the episodes (a
  // success flag's mean is the success rate).
  if (!result.episodes.empty()) {
    std::printf("at the end of the episodes (mean +/- sd over %zu):\n", result.episodes.size());
    std::vector<int64_t> lengths;
    for (const envs::EpisodeOutcome& episode : result.episodes) lengths.push_back(episode.length);
    std::printf("  %-24s %.6g +/- %.6g\n", "length", mean_of(lengths), sd_of(lengths));
    for (const auto& entry : result.episodes.front().final_info.entries()) {
      std::vector<double> values;
      for (const envs::EpisodeOutcome& episode : result.episodes)
        values.push_back(episode.final_info.get(entry.first).value_or(0.0));
      std::printf("  %-24s %.6g +/- %.6g\n", entry.first.c_str(), mean_of(values), sd_of(values));
    }
  }
  if (!out.empty()) {
    write_file_atomically(out, episodes_csv(result), "evaluation episodes");
    std::printf("episodes -> %s\n", out.string().c_str());
  }
  return 0;
}

}  // namespace tendril::apps
