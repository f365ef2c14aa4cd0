// `tendril rollout`: run a trained policy for a few episodes and write every transition as a CSV
// row — the data behind trajectory figures (e.g. the UR5 flange paths of docs/results/ur5.md).
// Columns: episode, step, reward, terminated, truncated, observation_i, action_i,
// next_observation_i, then the environment's info values by name. Episode k starts from
// reset(seed + k); observations are the environment's own (not normalized).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "command_line.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/wrappers/normalize_observation.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/rl/trainer.hpp"

namespace tendril::apps {

namespace {

std::string exact(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

}  // namespace

int rollout_command(const std::vector<std::string>& args) {
  const CommandLine line =
      CommandLine::parse(args, {"episodes", "seed", "out"}, {"deterministic", "best"});
  require(line.positional.size() == 1, "expected one run directory", "command line");
  require(line.has("out"), "--out FILE.csv is required", "command line");
  const std::filesystem::path run = line.positional.front();
  const std::filesystem::path out = line.value("out", "");
  require(std::filesystem::exists(run / "config.yaml"), "not a run directory (no config.yaml)",
          run.string());
  require(!std::filesystem::exists(out), "exists already; choose another file", out.string());
  const rl::Experiment experiment =
      rl::Experiment::from_config(Config::load_file(run / "config.yaml"));
  std::filesystem::path model =
      std::filesystem::exists(run / "model.pt") ? run / "model.pt" : rl::latest_checkpoint(run);
  if (line.has("best")) model = run / "best_model.pt";
  int episodes = 5;
  uint64_t seed = 0;
  try {
    episodes = std::stoi(line.value("episodes", "5"));
    seed = std::stoull(line.value("seed", "0"));
  } catch (const std::exception&) {
    throw Error("--episodes and --seed expect numbers", "command line");
  }
  require(episodes >= 1, "--episodes must be at least 1", "command line");

  const std::unique_ptr<envs::VecEnv> training_env = rl::make_vec_env(experiment.env);
  const std::unique_ptr<rl::Algorithm> algorithm = rl::make_algorithm(experiment, *training_env);
  algorithm->load(model);
  // The policy sees normalized observations (if the run normalized them); the file gets the
  // environment's own.
  std::unique_ptr<Env> evaluation_env = rl::make_evaluation_env(experiment.env, *training_env);
  auto* normalizer = envs::find_wrapper<envs::NormalizeObservation>(*evaluation_env);
  Env& env = normalizer != nullptr ? normalizer->inner() : *evaluation_env;
  const bool deterministic = line.has("deterministic");

  std::ofstream file(out);
  require(file.good(), "cannot write", out.string());
  const int observation_size = env.observation_space().size();
  const int action_size = env.action_space().size();
  bool header_written = false;
  for (int episode = 0; episode < episodes; ++episode) {
    Observation observation = env.reset(seed + static_cast<uint64_t>(episode));
    int64_t step_index = 0;
    double episode_return = 0.0;
    bool done = false;
    while (!done) {
      const Observation policy_input =
          normalizer != nullptr ? normalizer->normalize(observation) : observation;
      const Action action = algorithm->predict(policy_input, deterministic);
      const Step step = env.step(action);
      if (!header_written) {
        file << "episode,step,reward,terminated,truncated";
        for (int i = 0; i < observation_size; ++i) file << ",observation_" << i;
        for (int i = 0; i < action_size; ++i) file << ",action_" << i;
        for (int i = 0; i < observation_size; ++i) file << ",next_observation_" << i;
        for (const auto& entry : step.info.entries()) file << ',' << entry.first;
        file << '\n';
        header_written = true;
      }
      // A transition: the observation the action was chosen on, the action, what the step
      // returned (reward, ends, next observation) and its info.
      file << episode << ',' << step_index << ',' << exact(step.reward) << ',' << step.terminated
           << ',' << step.truncated;
      for (int i = 0; i < observation_size; ++i) file << ',' << exact(observation[i]);
      for (int i = 0; i < action_size; ++i) file << ',' << exact(action[i]);
      for (int i = 0; i < observation_size; ++i) file << ',' << exact(step.observation[i]);
      for (const auto& entry : step.info.entries()) file << ',' << exact(entry.second);
      file << '\n';
      episode_return += step.reward;
      observation = step.observation;
      ++step_index;
      done = step.terminated || step.truncated;
    }
    std::printf("episode %d: return %.3f, %lld steps\n", episode, episode_return,
                static_cast<long long>(step_index));
  }
  require(file.good(), "writing failed", out.string());
  std::printf("wrote %s\n", out.string().c_str());
  return 0;
}

}  // namespace tendril::apps
