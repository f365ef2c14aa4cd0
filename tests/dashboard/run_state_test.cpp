// A run's state from its files: running while a process holds its lock, finished, paused at a
// checkpoint or stopped; its steps, budget and last returns; model fits told from training.
#include "tendril/dashboard/run_state.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>

#include "support/scratch_directory.hpp"
#include "tendril/core/run_lock.hpp"

namespace tendril::dashboard {
namespace {

namespace fs = std::filesystem;

class RunStateTest : public testing::ScratchDirectoryTest {
 protected:
  RunStateTest() : ScratchDirectoryTest("run_state") {}

  fs::path training_run(const std::string& name) {
    const fs::path run = directory_ / name;
    fs::create_directories(run / "checkpoints");
    std::ofstream(run / "config.yaml") << "algorithm: ppo\nenv: {id: Pendulum-v1}\n"
                                          "n_timesteps: 10000\n";
    std::ofstream(run / "progress.csv") << "time/total_timesteps,rollout/ep_rew_mean,train/loss\n"
                                           "2048,-1200.5,0.3\n4096,-900.25,0.2\n";
    std::ofstream(run / "eval.csv") << "timesteps,mean_return,std_return\n4096,-850.5,12\n";
    return run;
  }

  RunState state_of(const fs::path& run) const {
    std::optional<Config> config;
    if (fs::exists(run / "config.yaml")) config = Config::load_file(run / "config.yaml");
    return read_run_state(ServedRoot(directory_), run, config ? &*config : nullptr, held_locks());
  }
};

TEST_F(RunStateTest, TrainingRunIsStoppedPausedRunningOrFinished) {
  const fs::path run = training_run("ppo");
  RunState state = state_of(run);
  EXPECT_EQ(state.kind, "training");
  EXPECT_EQ(state.status, "stopped");  // no checkpoint, no model, no process
  EXPECT_EQ(state.steps, 4096.0);
  EXPECT_EQ(state.total, 10000.0);
  EXPECT_EQ(state.last_return, -900.25);
  EXPECT_EQ(state.last_eval, -850.5);
  EXPECT_TRUE(std::isnan(state.last_loss));

  std::ofstream(run / "checkpoints" / "step_2048.ckpt") << "x";
  std::ofstream(run / "checkpoints" / "step_4096.ckpt") << "x";
  std::ofstream(run / "checkpoints" / "step_4096.buffer") << "x";
  state = state_of(run);
  EXPECT_EQ(state.status, "paused");
  EXPECT_EQ(state.checkpoint, 4096);

  {
    const RunLock lock(run);  // this process trains it now
    state = state_of(run);
    EXPECT_EQ(state.status, "running");
    EXPECT_EQ(state.pid, static_cast<int64_t>(::getpid()));
  }
  // Released (the file stays, emptied): not running any more — files changed a moment ago
  // say nothing.
  EXPECT_EQ(state_of(run).status, "paused");

  std::ofstream(run / "model.policy") << "x";
  EXPECT_EQ(state_of(run).status, "finished");
}

TEST_F(RunStateTest, ModelFitCountsEpochsAndLoss) {
  const fs::path run = directory_ / "fit";
  fs::create_directories(run);
  std::ofstream(run / "config.yaml") << "model: {architecture: lstm}\ntraining: {epochs: 3}\n";
  std::ofstream(run / "progress.csv")
      << "train/loss,train/val_loss,time/epochs,time/windows\n0.5,0.6,1,100\n0.25,0.375,2,200\n";
  RunState state = state_of(run);
  EXPECT_EQ(state.kind, "fit");
  EXPECT_EQ(state.status, "stopped");
  EXPECT_EQ(state.steps, 2.0);
  EXPECT_EQ(state.total, 3.0);
  EXPECT_EQ(state.last_loss, 0.375);
  EXPECT_TRUE(std::isnan(state.last_return));
  std::ofstream(run / "evaluation.csv") << "metric,horizon_s,group,unit,rmse,points,rollouts\n";
  EXPECT_EQ(state_of(run).status, "finished");
}

TEST_F(RunStateTest, LogsFromElsewhereHaveNoStatus) {
  const fs::path run = directory_ / "sb3";
  fs::create_directories(run);
  std::ofstream(run / "progress.csv") << "rollout/ep_rew_mean,time/total_timesteps\n-5,100\n";
  const RunState state = state_of(run);
  EXPECT_EQ(state.kind, "");
  EXPECT_EQ(state.status, "");
  EXPECT_EQ(state.steps, 100.0);
  EXPECT_EQ(state.last_return, -5.0);
}

// Only the last complete line counts: a row being written waits; a long file is read from its
// tail (its middle rows are never parsed).
TEST_F(RunStateTest, LastRowIsTheLastCompleteLine) {
  const fs::path file = directory_ / "progress.csv";
  {
    std::ofstream out(file);
    out << "a,b\n";
    for (int i = 0; i < 20000; ++i) out << i << "," << 2 * i << "\n";
    out << "20000,4";  // unterminated
  }
  LastRow row = last_csv_row(file);
  ASSERT_EQ(row.columns, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(row.value("a"), 19999.0);
  EXPECT_EQ(row.value("b"), 39998.0);
  EXPECT_TRUE(std::isnan(row.value("c")));

  std::ofstream(file) << "a,b\n";
  EXPECT_TRUE(last_csv_row(file).values.empty());
  std::ofstream(file) << "a,b\n1,\n";
  row = last_csv_row(file);
  EXPECT_EQ(row.value("a"), 1.0);
  EXPECT_TRUE(std::isnan(row.value("b")));
  EXPECT_TRUE(last_csv_row(directory_ / "missing.csv").values.empty());
}

}  // namespace
}  // namespace tendril::dashboard
