// Warm starts: a new run begins from another run's learned state and keeps its own counters.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "support/error_message.hpp"
#include "tendril/core/config.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/rl/trainer.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSac = R"(
algorithm: sac
env:
  id: Pendulum-v1
  n_envs: 2
algo:
  learning_starts: 200
  batch_size: 32
  net_arch: [32, 32]
n_timesteps: 800
seed: 5
checkpoint_freq: 800
)";

// Each test runs in a process of its own (ctest -j), and each builds its own source run: the
// process id keeps their directories apart.
fs::path fresh(const std::string& name) {
  const fs::path directory =
      fs::temp_directory_path() / ("tendril_warm_start_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(directory);
  return directory;
}

Experiment sac(const std::vector<std::pair<std::string, std::string>>& set = {}) {
  Config config = Config::parse(kSac, "sac.yaml");
  for (const auto& [key, value] : set) config.set(key, value);
  return Experiment::from_config(config);
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The source run: 800 SAC steps, one checkpoint at the end.
const fs::path& source_run() {
  static const fs::path run = [] {
    const fs::path directory = fresh("source");
    train(sac(), directory, {.quiet = true});
    return directory;
  }();
  return run;
}

// Observations over Pendulum's box, the same for every call.
envs::BatchMatrix probe_observations() {
  Rng rng(11);
  envs::BatchMatrix observations(16, 3);
  for (int i = 0; i < observations.rows(); ++i) {
    const double angle = rng.uniform(-3.14159, 3.14159);
    observations.row(i) << static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle)),
        static_cast<float>(rng.uniform(-8.0, 8.0));
  }
  return observations;
}

TEST(WarmStart, InstallsTheSourcesWeightsAndKeepsTheRunsOwnCounters) {
  const fs::path checkpoint = latest_checkpoint(source_run());
  const Experiment experiment = sac({{"seed", "9"}});
  auto env_a = make_vec_env(experiment.env);
  auto env_b = make_vec_env(experiment.env);
  std::unique_ptr<Algorithm> warm = make_algorithm(experiment, *env_a);
  std::unique_ptr<Algorithm> resumed = make_algorithm(experiment, *env_b);
  const envs::BatchMatrix before = warm->predict(probe_observations(), true);
  warm->warm_start(checkpoint);
  resumed->load(checkpoint);
  // The source's actor, bit for bit; a fresh seed-9 actor acts otherwise.
  const envs::BatchMatrix after = warm->predict(probe_observations(), true);
  EXPECT_EQ(after, resumed->predict(probe_observations(), true));
  EXPECT_NE(after, before);
  // This run's own counters and seed, not the source's.
  EXPECT_EQ(warm->num_timesteps(), 0);
  EXPECT_EQ(warm->iterations(), 0);
  EXPECT_EQ(warm->seed(), 9u);
  EXPECT_EQ(resumed->num_timesteps(), 800);
}

TEST(WarmStart, ANewRunStartsFromARunsNewestCheckpointRecordsItAndRepeats) {
  const fs::path checkpoint = latest_checkpoint(source_run());
  const Experiment experiment = sac({{"warm_start", source_run().string()},
                                     {"seed", "9"},
                                     {"n_timesteps", "400"},
                                     {"checkpoint_freq", "0"},
                                     {"eval.freq", "400"},
                                     {"eval.episodes", "2"}});
  EXPECT_EQ(fs::path(experiment.warm_start), checkpoint);
  const fs::path first = fresh("first"), second = fresh("second");
  const TrainResult a = train(experiment, first, {.quiet = true});
  const TrainResult b = train(experiment, second, {.quiet = true});
  EXPECT_TRUE(a.finished);
  EXPECT_EQ(a.timesteps, 400);
  // config.yaml names the checkpoint file, not the directory, whose newest file may change.
  EXPECT_NE(read_text(first / "config.yaml").find(checkpoint.filename().string()),
            std::string::npos);
  EXPECT_EQ(read_text(first / "eval.csv"), read_text(second / "eval.csv"));
  EXPECT_EQ(a.final_eval_mean, b.final_eval_mean);
}

TEST(WarmStart, ASourceThatDoesNotFitIsRefusedByName) {
  const std::string checkpoint = latest_checkpoint(source_run()).string();
  // Another algorithm.
  Config td3 = Config::parse(kSac, "td3.yaml");
  td3.set("algorithm", "td3");
  td3.set("warm_start", checkpoint);
  const std::string other = testing::error_message([&] { Experiment::from_config(td3); });
  EXPECT_NE(other.find("checkpoint of SAC, not TD3"), std::string::npos) << other;
  // Another network.
  EXPECT_NE(testing::error_message([&] {
              sac({{"warm_start", checkpoint}, {"algo.net_arch", "[64, 64]"}});
            }).find(checkpoint),
            std::string::npos);
  // Normalized observations: the weights would meet other statistics.
  EXPECT_NE(testing::error_message([&] {
              sac({{"warm_start", checkpoint}, {"env.normalize_observation", "true"}});
            }).find("warm_start"),
            std::string::npos);
  // A missing file: refused before the run directory exists.
  const fs::path run = fresh("missing");
  const std::string message = testing::error_message([&] {
    train(sac({{"warm_start", (source_run() / "no_such.ckpt").string()}}), run, {.quiet = true});
  });
  EXPECT_NE(message.find("no checkpoint file"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(run));
}

}  // namespace
}  // namespace tendril::rl
