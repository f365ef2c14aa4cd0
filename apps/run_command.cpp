// `tendril run`: a trained policy on an environment, through the one policy runner
// (envs/runner): summary statistics, a transition trace, episode files, an open-loop replay.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "run_policy.hpp"
#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/interrupt.hpp"
#include "tendril/core/run_curves.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/runner/episode_files.hpp"
#include "tendril/envs/runner/step_statistics.hpp"
#include "tendril/envs/runner/trace_writer.hpp"
#include "tendril/rl/open_loop.hpp"
#ifdef TENDRIL_WITH_SAFETY
#include "tendril/safety/filtered_policy.hpp"
#include "tendril/safety/safety_critic.hpp"
#endif

namespace tendril::apps {

namespace {

namespace fs = std::filesystem;

// One row per finished episode: index, seed, return, length, then the final info values.
std::string episodes_csv(const envs::RunResult& result) {
  std::ostringstream csv;
  csv.precision(17);
  const Info& first = result.episodes.front().final_info;
  csv << "episode,seed,return,length";
  for (const auto& entry : first.entries()) csv << "," << entry.first;
  csv << "\n";
  for (const envs::EpisodeOutcome& episode : result.episodes) {
    if (!episode.finished) continue;
    csv << episode.index << "," << episode.seed << "," << episode.episode_return << ","
        << episode.length;
    for (const auto& entry : first.entries()) {
      csv << "," << episode.final_info.get(entry.first).value_or(0.0);
    }
    csv << "\n";
  }
  return csv.str();
}

void print_summary(const envs::RunResult& result, const envs::StepStatistics& steps,
                   const std::string& source, const std::string& env_id, const std::string& how) {
  std::vector<double> returns, lengths;
  for (const envs::EpisodeOutcome& episode : result.episodes) {
    if (!episode.finished) continue;
    returns.push_back(episode.episode_return);
    lengths.push_back(static_cast<double>(episode.length));
  }
  std::printf("%s on %s (%s): %lld steps, %zu episode%s finished\n", source.c_str(), env_id.c_str(),
              how.c_str(), static_cast<long long>(result.steps), returns.size(),
              returns.size() == 1 ? "" : "s");
  if (result.episodes.size() <= 20) {
    for (const envs::EpisodeOutcome& episode : result.episodes) {
      std::printf("  episode %2lld (seed %llu): return %10.3f  length %lld%s",
                  static_cast<long long>(episode.index),
                  static_cast<unsigned long long>(episode.seed), episode.episode_return,
                  static_cast<long long>(episode.length), episode.finished ? "" : " (cut short)");
      for (const auto& [name, value] : episode.final_info.entries()) {
        std::printf("  %s %.6g", name.c_str(), value);
      }
      std::printf("\n");
    }
  }
  if (!returns.empty()) {
    const Spread r = spread_of(returns), l = spread_of(lengths);
    std::printf("over the finished episodes (mean +/- sd):\n");
    std::printf("  %-24s %.6g +/- %.6g\n", "return", r.mean, r.std);
    std::printf("  %-24s %.6g +/- %.6g\n", "length", l.mean, l.std);
    // Each info value at the episodes' ends (a success flag's mean is the success rate).
    for (const auto& entry : result.episodes.front().final_info.entries()) {
      std::vector<double> values;
      for (const envs::EpisodeOutcome& episode : result.episodes) {
        if (episode.finished) values.push_back(episode.final_info.get(entry.first).value_or(0.0));
      }
      const Spread v = spread_of(values);
      std::printf("  %-24s %.6g +/- %.6g\n", ("final " + entry.first).c_str(), v.mean, v.std);
    }
  }
  if (steps.steps() > 0) {
    std::printf("per step (mean over %lld steps):\n", static_cast<long long>(steps.steps()));
    std::printf("  %-24s %.6g\n", "reward", steps.mean_reward());
    for (const auto& [name, mean] : steps.info_means()) {
      std::printf("  %-24s %.6g\n", name.c_str(), mean);
    }
  }
}

// A policy file run on an environment named by --env: its parameters from --set env.params.*.
RunPolicy open_policy_file(const fs::path& file, const Arguments& line) {
  require(line.has("env"), "a policy file runs on the environment --env ID names", file.string());
  Config params;
  for (const auto& [key, value] : line.overrides) {
    require(key.rfind("env.params.", 0) == 0,
            "with a policy file, --set sets only env.params.<name>, got '" + key + "'", "--set");
    params.set(key.substr(std::string("env.params.").size()), value);
  }
  RunPolicy opened;
  opened.experiment.env.id = line.value("env");
  opened.source = file;
  opened.policy = rl::load_policy(file);
  opened.env = envs::make(opened.experiment.env.id, params);
  return opened;
}

}  // namespace

int run_command(const Arguments& line) {
  line.exclusive("episodes", "steps");
  line.exclusive("best", "checkpoint");
  constexpr int64_t kMost = int64_t{1} << 40;
  envs::RunSettings settings;
  settings.steps = line.integer("steps", 0, 1, kMost);
  settings.episodes = settings.steps > 0 ? 0 : line.integer("episodes", 10, 1, kMost);
  settings.seed = line.unsigned_integer("seed", 0);
  settings.deterministic = !line.has("stochastic");
  // Ctrl-C (or SIGTERM) ends the run after the current step, with its summary; on a robot the
  // bridge then holds it safe.
  catch_interrupts();
  settings.stop_requested = [] { return interrupt_signal() != 0; };

  const fs::path source = line.positional.front();
  const bool policy_file = fs::is_regular_file(source);
  // Outputs are refused before the work, so that nothing is overwritten.
  for (const char* option : {"trace", "episodes-csv"}) {
    if (line.has(option)) {
      require(!fs::exists(line.value(option)), "exists already; choose another file",
              line.value(option));
    }
  }
  RunPolicy opened;
  if (policy_file) {
    require(!line.has("best") && !line.has("open-loop"),
            "--best and --open-loop need a run directory", source.string());
    opened = open_policy_file(source, line);
  } else {
    std::vector<std::pair<std::string, std::string>> overrides = line.overrides;
    if (line.has("env")) overrides.emplace_back("env.id", line.value("env"));
    opened = open_run_policy(source, line.has("best"), overrides);
  }
  Env& env = *opened.env;

  std::optional<envs::TraceWriter> trace;
  if (line.has("trace")) trace.emplace(line.value("trace"));
  std::optional<envs::EpisodeFiles> recording;
  if (line.has("record")) {
    envs::RecordingOptions options;
    options.directory = line.value("record");
    options.prefix = line.has("best") ? "best" : "episode";
    options.metadata = {{"env", opened.experiment.env.id},
                        {"run", fs::absolute(source).lexically_normal().string()},
                        {"model", opened.source.filename().string()},
                        {"actions", settings.deterministic ? "deterministic" : "stochastic"}};
    recording.emplace(std::move(options));
  }
  envs::StepStatistics steps;
  std::vector<envs::RunObserver*> observers{&steps};
  if (trace) observers.push_back(&*trace);
  if (recording) observers.push_back(&*recording);

  // The safety filter (seed 001 eq. 6.5) as a policy around the trained one.
  const Policy* policy = opened.policy.get();
#ifdef TENDRIL_WITH_SAFETY
  std::unique_ptr<safety::SafetyCritic> critic;
  std::unique_ptr<safety::FilteredPolicy> filtered;
  if (line.has("filter")) {
    require(line.has("epsilon"), "the filter needs its threshold: --epsilon E", "--filter");
    fs::path critic_file = line.value("filter");
    if (fs::is_directory(critic_file)) critic_file /= "safety.critic";
    critic = safety::load_safety_critic(critic_file);
    filtered = std::make_unique<safety::FilteredPolicy>(*policy, *critic,
                                                        line.number("epsilon", 0.0, -1e300, 1e300));
    policy = filtered.get();
  }
#else
  require(!line.has("filter"), "this build has no safety layer", "--filter");
#endif
  envs::RunResult result;
  std::string how = settings.deterministic ? "deterministic" : "stochastic";
  if (line.has("filter"))
    how += ", through the safety filter at epsilon_2 " + line.value("epsilon");
  if (line.has("open-loop")) {
    require(settings.episodes > 0 && !trace && !recording && !line.has("filter"),
            "--open-loop replays whole episodes, without --trace, --record or --filter",
            "--open-loop");
    // The policy acts once in the run's own environment; its actions replay on this one.
    const RunPolicy trained = open_run_policy(source, line.has("best"));
    const std::vector<Action> actions =
        rl::recorded_actions(*trained.policy, *trained.env, settings.deterministic, settings.seed);
    how = "open loop: the " + std::to_string(actions.size()) + " actions of one episode on " +
          trained.experiment.env.id + ", replayed";
    result = rl::replay_actions(actions, env, static_cast<int>(settings.episodes), settings.seed);
  } else {
    result = envs::run_policy(*policy, env, settings, observers);
  }
  if (trace) trace->close();
  print_summary(result, steps, opened.source.string(), opened.experiment.env.id, how);
  if (result.stopped) std::printf("stopped by %s\n", signal_name(interrupt_signal()));
#ifdef TENDRIL_WITH_SAFETY
  if (filtered) {
    std::printf("safety filter: %lld interventions in %lld steps (%.3f)\n",
                static_cast<long long>(filtered->filter().interventions()),
                static_cast<long long>(filtered->filter().decisions()),
                filtered->filter().intervention_rate());
  }
#endif
  if (recording) {
    for (const auto& episode : recording->episodes()) {
      std::printf("recorded %s (%lld steps)\n", episode.file.c_str(),
                  static_cast<long long>(episode.summary.steps));
    }
    std::printf("replay: tendril serve %s\n", line.value("record").c_str());
  }
  if (trace) std::printf("transitions -> %s\n", line.value("trace").c_str());
  if (line.has("episodes-csv") && result.finished_episodes() > 0) {
    write_file_atomically(line.value("episodes-csv"), episodes_csv(result), "--episodes-csv");
    std::printf("episodes -> %s\n", line.value("episodes-csv").c_str());
  }
  return 0;
}

}  // namespace tendril::apps
