// An experiment's environment wrappers (env.wrappers): checked before a run starts, trained
// with, evaluated with, kept in the run's config.yaml and carried through a resume.
#include "tendril/rl/experiment.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/error_message.hpp"
#include "support/evaluation.hpp"
#include "tendril/envs/wrappers/history_stack.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/trainer.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

namespace fs = std::filesystem;
using tendril::testing::error_message;

constexpr const char* kExperiment = R"(
algorithm: ppo
env:
  id: Pendulum-v1
  n_envs: 2
  normalize_observation: true
  wrappers:
    - history_stack: {length: 3}
algo:
  n_steps: 128
  batch_size: 64
  n_epochs: 2
n_timesteps: 1024
seed: 5
eval: {freq: 512, episodes: 2, save_best: true}
checkpoint_freq: 512
)";

Config config() { return Config::parse(kExperiment, "test.yaml"); }

fs::path fresh(const std::string& name) {
  const fs::path directory = fs::temp_directory_path() / ("tendril_experiment_" + name);
  fs::remove_all(directory);
  return directory;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string refused(const std::string& key, const std::string& value) {
  Config changed = config();
  changed.set(key, value);
  return error_message([&] { Experiment::from_config(changed); });
}

TEST(ExperimentWrappers, BadEntriesAreRefusedNamingTheKey) {
  const std::string name = refused("env.wrappers", "[{history_stak: {length: 3}}]");
  EXPECT_NE(name.find("test.yaml: env.wrappers[0].history_stak"), std::string::npos) << name;
  EXPECT_NE(name.find("unknown wrapper"), std::string::npos) << name;
  const std::string key = refused("env.wrappers", "[{history_stack: {length: 3, size: 2}}]");
  EXPECT_NE(key.find("env.wrappers[0].history_stack.size"), std::string::npos) << key;
  const std::string value = refused("env.wrappers", "[{history_stack: {length: -1}}]");
  EXPECT_NE(value.find("test.yaml: env.wrappers[0].history_stack.length"), std::string::npos)
      << value;
  EXPECT_NE(value.find("got -1"), std::string::npos) << value;
  const std::string shape = refused("env.wrappers", "history_stack");
  EXPECT_NE(shape.find("env.wrappers"), std::string::npos) << shape;
}

// Lockstep rods put one pool under every copy; per-env wrappers would go around it.
TEST(ExperimentWrappers, LockstepRodsUnderPerEnvWrappersAreRefused) {
  Config config = Config::parse(kExperiment, "test.yaml");
  config.set("env.id", "Elastica/Tracking3D-v0");
  config.set("env.params", "{lockstep_rods: true}");
  const std::string message = error_message([&] { Experiment::from_config(config); });
  EXPECT_NE(message.find("lockstep_rods"), std::string::npos) << message;
  EXPECT_NE(message.find("wrappers"), std::string::npos) << message;
}

TEST(ExperimentWrappers, EveryEnvironmentOfTheRunCarriesThem) {
  const Experiment experiment = Experiment::from_config(config());
  ASSERT_EQ(experiment.env.wrappers.size(), 1u);
  EXPECT_EQ(make_env(experiment.env)->observation_space().size(), 9);
  auto training = make_vec_env(experiment.env);
  EXPECT_EQ(training->observation_space().size(), 9);
  const auto evaluation = make_evaluation_env(experiment.env, *training);
  EXPECT_EQ(evaluation->observation_space().size(), 9);
  EXPECT_NE(envs::find_wrapper<envs::HistoryStack>(const_cast<Env&>(*evaluation)), nullptr);
}

// The rows of eval.csv as (timesteps, mean return).
std::vector<std::pair<int64_t, double>> evaluations(const fs::path& run) {
  std::ifstream in(run / "eval.csv");
  std::string line;
  std::getline(in, line);
  std::vector<std::pair<int64_t, double>> rows;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    std::string timesteps, mean;
    std::getline(cells, timesteps, ',');
    std::getline(cells, mean, ',');
    rows.emplace_back(std::stoll(timesteps), std::stod(mean));
  }
  return rows;
}

TEST(ExperimentWrappers, ATrainedRunEvaluatesWithItsWrappers) {
  const fs::path run = fresh("trained");
  const TrainResult result =
      train(Experiment::from_config(config()), run, {.stop_at = std::nullopt, .quiet = true});
  ASSERT_TRUE(result.finished);
  ASSERT_TRUE(result.best_eval_mean.has_value());

  // The resolved config.yaml holds the list, and the run's experiment reads it back.
  const std::string saved = read_text(run / "config.yaml");
  EXPECT_NE(saved.find("history_stack"), std::string::npos) << saved;
  const Experiment reloaded = load_run_experiment(run);
  ASSERT_EQ(reloaded.env.wrappers.size(), 1u);

  // The best policy, loaded anew, acts on 3 stacked observations and repeats its evaluation on
  // the run's environment built the way `tendril eval` builds it.
  const std::unique_ptr<Policy> policy = load_policy(run / "best_model.policy");
  const std::unique_ptr<Env> env = make_env(reloaded.env);
  EXPECT_EQ(env->observation_space().size(), 9);
  const envs::RunResult again = testing::evaluate(
      *policy, *env, reloaded.eval_episodes, reloaded.seed + 1000003 + result.best_eval_timesteps);
  EXPECT_EQ(again.mean_return(), *result.best_eval_mean);
  const auto rows = evaluations(run);
  EXPECT_TRUE(std::any_of(rows.begin(), rows.end(),
                          [&](const auto& row) { return row.second == again.mean_return(); }));
}

TEST(ExperimentWrappers, AResumedRunEqualsTheUninterruptedRun) {
  const fs::path whole = fresh("whole"), paused = fresh("paused");
  const TrainResult reference =
      train(Experiment::from_config(config()), whole, {.stop_at = std::nullopt, .quiet = true});
  train(Experiment::from_config(config()), paused, {.stop_at = 500, .quiet = true});
  const TrainResult resumed = resume(paused, {.stop_at = std::nullopt, .quiet = true});
  EXPECT_TRUE(resumed.finished);
  EXPECT_EQ(resumed.final_eval_mean, reference.final_eval_mean);
  EXPECT_EQ(read_text(paused / "eval.csv"), read_text(whole / "eval.csv"));
}

}  // namespace
}  // namespace tendril::rl
