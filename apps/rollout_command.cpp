// `tendril rollout`: a run's trained policy on its environment for a number of episodes or
// steps. Prints the mean per step of the reward and of every value the environment reports in
// its info (the per-step means seed 003's tables give: distance error, velocity error, energy
// term, ...), and optionally writes every transition as a CSV row — the data behind trajectory
// figures (e.g. the UR5 flange paths of docs/results/ur5.md, the beam's tip paths).
// CSV columns: episode, step, time (s, the scene's clock), reward, terminated, truncated,
// observation_i (before the step), action_i (environment units), next_observation_i, then the
// step's info values and the scene's named values by name. Episode k starts from
// reset(seed + k); observations are the environment's own (not normalized).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "command_line.hpp"
#include "commands.hpp"
#include "run_policy.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/scene.hpp"

namespace tendril::apps {

namespace {

namespace fs = std::filesystem;

std::string exact(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// Sums of named values in the order they first appear.
struct Sums {
  std::vector<std::pair<std::string, double>> entries;
  void add(const std::string& name, double value) {
    for (auto& [existing, sum] : entries) {
      if (existing == name) {
        sum += value;
        return;
      }
    }
    entries.emplace_back(name, value);
  }
};

class TraceFile {
 public:
  explicit TraceFile(const fs::path& file) : file_(file), out_(file) {
    require(out_.good(), "cannot write", file.string());
  }

  void write(int64_t episode, int64_t step_index, const Scene& scene,
             const Observation& observation, const Action& action, const Step& step) {
    if (!header_written_) write_header(observation, action, step, scene);
    std::string row = std::to_string(episode) + ',' + std::to_string(step_index) + ',' +
                      exact(scene.time) + ',' + exact(step.reward) + ',' +
                      (step.terminated ? "1" : "0") + ',' + (step.truncated ? "1" : "0");
    for (double v : observation) row += ',' + exact(v);
    for (double v : action) row += ',' + exact(v);
    for (double v : step.observation) row += ',' + exact(v);
    for (const std::string& name : columns_) {
      std::optional<double> value = step.info.get(name);
      if (!value) {
        for (const auto& [key, scene_value] : scene.values) {
          if (key == name) value = scene_value;
        }
      }
      row += ',' + (value ? exact(*value) : std::string());
    }
    out_ << row << '\n';
    require(out_.good(), "writing failed", file_.string());
  }

 private:
  void write_header(const Observation& observation, const Action& action, const Step& step,
                    const Scene& scene) {
    std::string header = "episode,step,time,reward,terminated,truncated";
    for (std::size_t i = 0; i < observation.size(); ++i)
      header += ",observation_" + std::to_string(i);
    for (std::size_t i = 0; i < action.size(); ++i) header += ",action_" + std::to_string(i);
    for (std::size_t i = 0; i < observation.size(); ++i) {
      header += ",next_observation_" + std::to_string(i);
    }
    for (const auto& [name, value] : step.info.entries()) columns_.push_back(name);
    for (const auto& [name, value] : scene.values) {
      if (!step.info.get(name)) columns_.push_back(name);
    }
    for (const std::string& name : columns_) header += ',' + name;
    out_ << header << '\n';
    header_written_ = true;
  }

  fs::path file_;
  std::ofstream out_;
  std::vector<std::string> columns_;
  bool header_written_ = false;
};

}  // namespace

int rollout_command(const std::vector<std::string>& args) {
  const CommandLine line = CommandLine::parse(args, {"episodes", "steps", "seed", "out"},
                                              {"best", "deterministic", "stochastic"});
  require(line.positional.size() == 1, "expected one run directory", "command line");
  const fs::path run = line.positional.front();
  require(fs::exists(run / "config.yaml"), "not a run directory (no config.yaml)", run.string());
  require(!(line.has("episodes") && line.has("steps")), "--episodes and --steps exclude each other",
          "command line");
  require(!(line.has("deterministic") && line.has("stochastic")),
          "--deterministic and --stochastic exclude each other", "command line");
  constexpr int64_t kMost = int64_t{1} << 40;
  const int64_t steps = line.integer("steps", 0, 1, kMost);
  const int64_t episodes = line.has("steps") ? 0 : line.integer("episodes", 5, 1, kMost);
  const uint64_t seed = line.unsigned_integer("seed", 0);
  std::optional<TraceFile> trace;
  if (line.has("out")) {
    const fs::path out = line.value("out", "");
    require(!fs::exists(out), "exists already; choose another file", out.string());
    trace.emplace(out);
  }

  RunPolicy policy = open_run_policy(run, line.has("best"), line.overrides);
  const bool deterministic = line.has("deterministic") ? true
                             : line.has("stochastic")  ? false
                                                       : policy.experiment.eval_deterministic;
  Rng rng(seed, /*stream=*/1);
  Env& env = *policy.env;

  Sums sums;
  double reward_sum = 0.0, return_sum = 0.0;
  int64_t steps_done = 0, episodes_done = 0;
  for (int64_t episode = 0; steps > 0 || episode < episodes; ++episode) {
    Observation observation = env.reset(seed + static_cast<uint64_t>(episode));
    int64_t step_index = 0;
    double episode_return = 0.0;
    bool done = false;
    while (!done && !(steps > 0 && steps_done == steps)) {
      const Action action = policy.policy->act(observation, deterministic, rng);
      Step step = env.step(action);
      reward_sum += step.reward;
      episode_return += step.reward;
      for (const auto& [name, value] : step.info.entries()) sums.add(name, value);
      if (trace) {
        Scene scene;
        env.describe_scene(scene);
        trace->write(episode, step_index, scene, observation, action, step);
      }
      ++step_index;
      ++steps_done;
      done = step.terminated || step.truncated;
      observation = std::move(step.observation);
    }
    if (done) {
      ++episodes_done;
      return_sum += episode_return;
    }
    if (steps > 0 && steps_done == steps) break;
  }
  std::printf("%s on %s, %lld steps (%s), %lld episodes ended", policy.source.string().c_str(),
              policy.experiment.env.id.c_str(), static_cast<long long>(steps_done),
              deterministic ? "deterministic" : "stochastic",
              static_cast<long long>(episodes_done));
  if (episodes_done > 0) {
    std::printf(", mean return %.5f", return_sum / static_cast<double>(episodes_done));
  }
  std::printf("\n");
  const double n = static_cast<double>(steps_done);
  std::printf("  %-24s %14.6g\n", "reward per step", reward_sum / n);
  for (const auto& [name, sum] : sums.entries)
    std::printf("  %-24s %14.6g\n", name.c_str(), sum / n);
  return 0;
}

}  // namespace tendril::apps
