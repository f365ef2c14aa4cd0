// Runs that survive faults: a corrupt newest checkpoint, a process killed after its last
// checkpoint, SIGINT/SIGTERM, a second writer, a finished run resumed, a sweep interrupted
// before its first checkpoint, leftovers of interrupted writes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/error_message.hpp"
#include "support/same_run.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/interrupt.hpp"
#include "tendril/core/run_lock.hpp"
#include "tendril/core/scalar_log.hpp"
#include "tendril/rl/trainer.hpp"

namespace tendril::rl {
namespace {

namespace fs = std::filesystem;

// Checkpoints and evaluations every 512 steps (two envs of 128 steps per iteration).
constexpr const char* kExperiment = R"(
algorithm: ppo
env:
  id: Pendulum-v1
  n_envs: 2
  normalize_observation: true
  normalize_reward: true
algo:
  n_steps: 128
  batch_size: 64
  n_epochs: 2
  gamma: 0.9
n_timesteps: 2048
seed: 3
eval: {freq: 512, episodes: 2, save_best: true}
checkpoint_freq: 512
)";

Experiment experiment(int seed = 3) {
  Config config = Config::parse(kExperiment, "faults.yaml");
  config.set("seed", std::to_string(seed));
  return Experiment::from_config(config);
}

const TrainOptions kQuiet{.stop_at = std::nullopt, .quiet = true};

// The scratch run directories of this program, removed when it exits.
struct ScratchRuns {
  std::vector<fs::path> directories;
  ~ScratchRuns() {
    std::error_code ignored;
    for (const fs::path& directory : directories) fs::remove_all(directory, ignored);
  }
};
ScratchRuns scratch_runs;

fs::path fresh(const std::string& name) {
  const fs::path directory =
      fs::temp_directory_path() / ("tendril_faults_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(directory);
  scratch_runs.directories.push_back(directory);
  return directory;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
}

// progress.csv's step column.
std::vector<std::string> logged_steps(const fs::path& run) {
  std::ifstream in(run / "progress.csv");
  std::string line;
  std::getline(in, line);
  std::stringstream header(line);
  std::size_t column = 0;
  for (std::string cell; std::getline(header, cell, ',') && cell != "time/total_timesteps";) {
    ++column;
  }
  std::vector<std::string> steps;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    std::string cell;
    for (std::size_t c = 0; c <= column; ++c) std::getline(cells, cell, ',');
    steps.push_back(cell);
  }
  return steps;
}

void expect_same_run(const fs::path& run, const fs::path& reference) {
  EXPECT_EQ(read_text(run / "model.policy"), read_text(reference / "model.policy"));
  EXPECT_EQ(read_text(run / "best_model.policy"), read_text(reference / "best_model.policy"));
  EXPECT_EQ(read_text(run / "eval.csv"), read_text(reference / "eval.csv"));
  EXPECT_EQ(logged_steps(run), logged_steps(reference));
  EXPECT_EQ(testing::event_scalars(run), testing::event_scalars(reference));
}

class RunFaults : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    reference_ = fresh("reference");
    train(experiment(), reference_, kQuiet);
  }
  void TearDown() override { clear_interrupt(); }
  static fs::path reference_;
};
fs::path RunFaults::reference_;

TEST_F(RunFaults, CorruptNewestCheckpointFallsBackToTheNewestIntactOne) {
  for (const bool truncate : {true, false}) {
    const fs::path run = fresh(truncate ? "truncated" : "flipped");
    train(experiment(), run, {.stop_at = 1024, .quiet = true});
    const fs::path newest = run / "checkpoints" / "step_1024.ckpt";
    std::string bytes = read_text(newest);
    if (truncate) {
      bytes.resize(bytes.size() - 1);
    } else {
      bytes[bytes.size() / 3] = static_cast<char>(bytes[bytes.size() / 3] ^ 0x10);
    }
    write_text(newest, bytes);
    std::vector<std::string> skipped;
    EXPECT_EQ(newest_intact_checkpoint(run, &skipped).filename(), "step_512.ckpt");
    ASSERT_EQ(skipped.size(), 1u);
    EXPECT_NE(skipped[0].find("step_1024.ckpt"), std::string::npos) << skipped[0];

    const TrainResult resumed = resume(run, kQuiet);
    EXPECT_TRUE(resumed.finished);
    EXPECT_EQ(read_text(newest.string() + ".corrupt"), bytes);  // kept for inspection
    expect_same_run(run, reference_);
  }
}

TEST_F(RunFaults, NoIntactCheckpointChangesNothing) {
  const fs::path run = fresh("none_intact");
  train(experiment(), run, {.stop_at = 512, .quiet = true});
  const fs::path only = run / "checkpoints" / "step_512.ckpt";
  write_text(only, read_text(only).substr(0, 100));
  const std::string progress = read_text(run / "progress.csv");
  const std::string message = testing::error_message([&] { resume(run, kQuiet); });
  EXPECT_NE(message.find("no usable checkpoint"), std::string::npos) << message;
  EXPECT_NE(message.find("step_512.ckpt"), std::string::npos) << message;
  EXPECT_EQ(read_text(only).size(), 100u);
  EXPECT_EQ(read_text(run / "progress.csv"), progress);
}

// A process killed after logging past its last checkpoint: the resumed run's logs hold one
// timeline, equal to the uninterrupted run's (rows, evaluations and TensorBoard scalars).
TEST_F(RunFaults, LogsPastTheCheckpointAreDroppedOnResume) {
  const fs::path run = fresh("killed_late");
  train(experiment(), run, {.stop_at = 1536, .quiet = true});
  fs::remove(run / "checkpoints" / "step_1536.ckpt");  // as if killed before writing it
  fs::remove(run / "checkpoints" / "step_1024.ckpt");
  // A record torn by the kill at the end of the event file.
  for (const auto& entry : fs::directory_iterator(run)) {
    if (entry.path().filename().string().rfind("events.out.", 0) == 0) {
      std::ofstream(entry.path(), std::ios::app | std::ios::binary) << "\x20\x00\x00";
    }
  }
  // And rows cut short.
  std::ofstream(run / "progress.csv", std::ios::app) << "1,2";
  std::ofstream(run / "eval.csv", std::ios::app) << "1792,-1";
  resume(run, kQuiet);
  expect_same_run(run, reference_);
}

// Killed after its first checkpoint but before the first evaluation: eval.csv was empty.
TEST_F(RunFaults, EmptyEvalCsvGetsItsHeaderBackOnResume) {
  const fs::path run = fresh("headerless");
  train(experiment(), run, {.stop_at = 1024, .quiet = true});
  const std::string evaluations = read_text(run / "eval.csv");
  const std::string header = evaluations.substr(0, evaluations.find('\n') + 1);
  write_text(run / "eval.csv", evaluations.substr(header.size()));  // rows without header
  resume(run, kQuiet);
  expect_same_run(run, reference_);
}

TEST_F(RunFaults, InterruptWritesACheckpointAndTheResumedRunEqualsTheWholeOne) {
  for (const int signal : {SIGINT, SIGTERM}) {
    const fs::path run = fresh("interrupted_" + std::to_string(signal));
    request_interrupt(signal);  // seen at the end of the first iteration, 256 steps
    const TrainResult first = train(experiment(), run, kQuiet);
    clear_interrupt();
    EXPECT_FALSE(first.finished);
    EXPECT_EQ(first.interrupted, signal);
    EXPECT_EQ(first.timesteps, 256);
    EXPECT_EQ(latest_checkpoint(run).filename(), "step_256.ckpt");
    EXPECT_FALSE(fs::exists(run / "model.policy"));
    EXPECT_TRUE(resume(run, kQuiet).finished);
    expect_same_run(run, reference_);
  }
}

TEST_F(RunFaults, FinishedRunIsNotResumed) {
  const fs::path run = fresh("finished");
  fs::copy(reference_, run, fs::copy_options::recursive);
  const std::string model = read_text(run / "model.policy"), log = read_text(run / "progress.csv");
  const std::string message = testing::error_message([&] { resume(run, kQuiet); });
  EXPECT_NE(message.find("has finished"), std::string::npos) << message;
  EXPECT_EQ(read_text(run / "model.policy"), model);
  EXPECT_EQ(read_text(run / "progress.csv"), log);
}

TEST_F(RunFaults, SecondWriterIsRefusedNamingTheHolder) {
  const fs::path run = fresh("held");
  train(experiment(), run, {.stop_at = 512, .quiet = true});
  const std::string progress = read_text(run / "progress.csv");
  {
    const RunLock held(run);
    const std::string message = testing::error_message([&] { resume(run, kQuiet); });
    EXPECT_NE(message.find("in use by process " + std::to_string(::getpid())), std::string::npos)
        << message;
    const fs::path empty = fresh("held_new");
    fs::create_directories(empty);
    const RunLock held_new(empty);
    EXPECT_NE(testing::error_message([&] { train(experiment(), empty, kQuiet); }).find("in use"),
              std::string::npos);
    EXPECT_FALSE(fs::exists(empty / "config.yaml"));
  }
  EXPECT_EQ(read_text(run / "progress.csv"), progress);
  EXPECT_TRUE(resume(run, kQuiet).finished);  // the lock went with its holder
}

TEST_F(RunFaults, UnstartedRunIsRestartedOnlyWhenAskedAndOnlyForTheSameExperiment) {
  const fs::path run = fresh("unstarted");
  train(experiment(), run, {.stop_at = 512, .quiet = true});
  fs::remove_all(run / "checkpoints");  // killed before its first checkpoint
  write_text(run / "checkpoints.tmp.12345", "torn");
  EXPECT_THROW(train(experiment(), run, kQuiet), Error);
  const std::string message = testing::error_message(
      [&] { train(experiment(4), run, {.stop_at = std::nullopt, .restart_unstarted = true}); });
  EXPECT_NE(message.find("not empty"), std::string::npos) << message;  // another seed
  EXPECT_TRUE(train(experiment(), run, {.quiet = true, .restart_unstarted = true}).finished);
  expect_same_run(run, reference_);
}

TEST_F(RunFaults, LeftoversOfInterruptedWritesAreRemovedOnResume) {
  const fs::path run = fresh("leftovers");
  train(experiment(), run, {.stop_at = 1024, .quiet = true});
  const std::vector<fs::path> leftovers = {run / "checkpoints" / "step_1536.ckpt.tmp.4242",
                                           run / "checkpoints" / "step_1536.buffer",
                                           run / "eval.csv.tmp.77", run / "progress.csv.tmp"};
  for (const fs::path& file : leftovers) write_text(file, "partial");
  write_text(run / "notes.tmp.txt", "not a leftover");
  resume(run, kQuiet);
  for (const fs::path& file : leftovers) EXPECT_FALSE(fs::exists(file)) << file;
  EXPECT_TRUE(fs::exists(run / "notes.tmp.txt"));
}

// One changed byte of config.yaml (seed: 3 → seed: 2) would resume another experiment.
TEST_F(RunFaults, DamagedConfigIsRefusedBeforeUse) {
  const fs::path run = fresh("damaged_config");
  train(experiment(), run, {.stop_at = 512, .quiet = true});
  std::string text = read_text(run / "config.yaml");
  EXPECT_NE(text.find("\n# CRC-32C of the lines above: "), std::string::npos);
  EXPECT_EQ(load_run_experiment(run).seed, 3u);
  const std::size_t seed = text.find("seed: 3");
  ASSERT_NE(seed, std::string::npos);
  text[seed + 6] = '2';
  write_text(run / "config.yaml", text);
  const std::string message = testing::error_message([&] { resume(run, kQuiet); });
  EXPECT_NE(message.find("config.yaml: damaged or edited"), std::string::npos) << message;
  EXPECT_EQ(latest_checkpoint(run).filename(), "step_512.ckpt");
}

TEST(RunInputs, OversizedReplayBufferIsRefusedNamingTheSetting) {
  Config config = Config::parse(
      "algorithm: sac\nenv: {id: Pendulum-v1}\nn_timesteps: 100\nalgo: {buffer_size: "
      "1000000000000}\n",
      "big.yaml");
  const fs::path run = fresh("oversized");
  const std::string message =
      testing::error_message([&] { train(Experiment::from_config(config), run, kQuiet); });
  EXPECT_NE(message.find("algo.buffer_size"), std::string::npos) << message;
  EXPECT_NE(message.find("GiB"), std::string::npos) << message;
  EXPECT_NE(testing::error_message([&] {
              Config wide = Config::parse(
                  "algorithm: sac\nenv: {id: Pendulum-v1}\nn_timesteps: 100\n"
                  "algo: {net_arch: [100000, 100000]}\n",
                  "wide.yaml");
              Experiment::from_config(wide);
            }).find("65536"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::rl
