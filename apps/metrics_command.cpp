// `tendril metrics`: a run's model on its environment for a number of steps, with the mean per
// step of the reward and of every value the environment reports in its info (the per-step
// means seed 003's tables give: distance error, velocity error, energy term, …).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "command_line.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/rl/trainer.hpp"

namespace tendril::apps {

namespace {

struct Means {
  std::vector<std::pair<std::string, double>> sums;  // in the order the env reports them
  void add(const Info& info) {
    for (const auto& [name, value] : info.entries()) {
      auto found = std::find_if(sums.begin(), sums.end(),
                                [&](const auto& entry) { return entry.first == name; });
      if (found == sums.end()) {
        sums.emplace_back(name, value);
      } else {
        found->second += value;
      }
    }
  }
};

}  // namespace

int metrics_command(const std::vector<std::string>& args) {
  const CommandLine line =
      CommandLine::parse(args, {"steps", "seed", "trace"}, {"stochastic", "best"});
  require(line.positional.size() == 1, "expected one run directory", "command line");
  const std::filesystem::path run = line.positional.front();
  require(std::filesystem::exists(run / "config.yaml"), "not a run directory (no config.yaml)",
          run.string());
  Config config = Config::load_file(run / "config.yaml");
  for (const auto& [key, value] : line.overrides) config.set(key, value);
  const rl::Experiment experiment = rl::Experiment::from_config(config);
  std::filesystem::path model =
      std::filesystem::exists(run / "model.pt") ? run / "model.pt" : rl::latest_checkpoint(run);
  if (line.has("best")) {
    model = run / "best_model.pt";
    require(std::filesystem::exists(model), "no best_model.pt (the run's eval.save_best is off)",
            run.string());
  }
  int64_t steps = 3000;
  uint64_t seed = 0;
  try {
    steps = std::stoll(line.value("steps", "3000"));
    seed = std::stoull(line.value("seed", "0"));
  } catch (const std::exception&) {
    throw Error("--steps and --seed expect numbers", "command line");
  }
  require(steps >= 1, "--steps must be at least 1", "command line");
  std::ofstream trace;
  if (line.has("trace")) {
    const std::filesystem::path file = line.value("trace", "");
    require(!std::filesystem::exists(file), "will not overwrite an existing file", file.string());
    trace.open(file);
    require(trace.good(), "cannot write", file.string());
  }

  const std::unique_ptr<envs::VecEnv> training_env = rl::make_vec_env(experiment.env);
  const std::unique_ptr<rl::Algorithm> algorithm = rl::make_algorithm(experiment, *training_env);
  algorithm->load(model);
  const std::unique_ptr<Env> env = rl::make_evaluation_env(experiment.env, *training_env);
  const bool deterministic = !line.has("stochastic");

  Observation observation = env->reset(seed);
  Means means;
  double reward_sum = 0.0;
  int64_t episodes = 0;
  int64_t episode = 0;
  bool header = false;
  for (int64_t t = 0; t < steps; ++t) {
    Step step = env->step(algorithm->predict(observation, deterministic));
    reward_sum += step.reward;
    means.add(step.info);
    if (trace.is_open()) {
      Scene scene;
      env->describe_scene(scene);
      if (!header) {
        trace << "step,episode,time,reward";
        for (const auto& entry : step.info.entries()) trace << ',' << entry.first;
        for (const auto& entry : scene.values) {
          if (!step.info.has(entry.first)) trace << ',' << entry.first;
        }
        trace << '\n';
        header = true;
      }
      trace << t << ',' << episode << ',' << scene.time << ',' << step.reward;
      for (const auto& entry : step.info.entries()) trace << ',' << entry.second;
      for (const auto& entry : scene.values) {
        if (!step.info.has(entry.first)) trace << ',' << entry.second;
      }
      trace << '\n';
    }
    if (step.terminated || step.truncated) {
      ++episodes;
      ++episode;
      observation = env->reset();
    } else {
      observation = std::move(step.observation);
    }
  }
  std::printf("%s on %s, %lld steps (%s), %lld episodes ended\n", model.string().c_str(),
              experiment.env.id.c_str(), static_cast<long long>(steps),
              deterministic ? "deterministic" : "stochastic", static_cast<long long>(episodes));
  const double n = static_cast<double>(steps);
  std::printf("  %-22s %12.5f\n", "mean reward per step", reward_sum / n);
  for (const auto& [name, sum] : means.sums) std::printf("  %-22s %12.5f\n", name.c_str(), sum / n);
  return 0;
}

}  // namespace tendril::apps
