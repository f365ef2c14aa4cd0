#include "tendril/dashboard/run_index.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "support/scratch_directory.hpp"

namespace tendril::dashboard {
namespace {

namespace fs = std::filesystem;

class RunIndexTest : public testing::ScratchDirectoryTest {
 protected:
  RunIndexTest() : ScratchDirectoryTest("run_index") {}
  void make_run(const fs::path& run, const std::string& config) {
    fs::create_directories(run / "checkpoints" / "nested_run_lookalike");
    std::ofstream(run / "config.yaml") << config;
    std::ofstream(run / "progress.csv") << "time/total_timesteps\n1\n";
    // A directory inside a run that looks like a run is not listed: runs are not searched.
    std::ofstream(run / "checkpoints" / "nested_run_lookalike" / "config.yaml") << "seed: 0\n";
  }
};

TEST_F(RunIndexTest, FindsRunsAndTheSweepsThatHoldThem) {
  const std::string ppo = "algorithm: ppo\nenv: {id: Elastica/Tracking3D-v0}\nseed: 0\n";
  make_run(directory_ / "results" / "ppo_seed0", ppo);
  make_run(directory_ / "results" / "ppo_seed1", ppo);
  make_run(directory_ / "sweeps" / "batch" / "n_steps_256-seed_0", "algorithm: trpo\n");
  make_run(directory_ / "single", "algorithm: [not, a, string\n");
  fs::create_directories(directory_ / "single" / "episodes");
  std::ofstream(directory_ / "single" / "episodes" / "episode_0000.tep") << "x";
  std::ofstream(directory_ / "single" / "episodes" / "notes.txt") << "x";
  fs::create_directories(directory_ / ".hidden" / "run");
  std::ofstream(directory_ / ".hidden" / "run" / "eval.csv") << "timesteps\n";

  const RunIndex index = index_runs(ServedRoot(directory_));
  ASSERT_EQ(index.runs.size(), 4u);
  EXPECT_EQ(index.runs[0].path, "results/ppo_seed0");
  EXPECT_EQ(index.runs[0].name, "ppo_seed0");
  EXPECT_EQ(index.runs[0].algorithm, "ppo");
  EXPECT_EQ(index.runs[0].env_id, "Elastica/Tracking3D-v0");
  EXPECT_TRUE(index.runs[0].has_progress);
  EXPECT_FALSE(index.runs[0].has_eval);
  EXPECT_GT(index.runs[0].modified, 1.6e9);
  EXPECT_EQ(index.runs[1].path, "results/ppo_seed1");
  EXPECT_EQ(index.runs[2].path, "single");
  EXPECT_EQ(index.runs[2].episodes, 1);
  EXPECT_NE(index.runs[2].problem.find("config.yaml"), std::string::npos);
  EXPECT_EQ(index.runs[3].path, "sweeps/batch/n_steps_256-seed_0");
  EXPECT_EQ(index.runs[3].algorithm, "trpo");

  ASSERT_EQ(index.sweeps.size(), 1u);  // a directory with one run is no sweep
  EXPECT_EQ(index.sweeps[0].path, "results");
  EXPECT_EQ(index.sweeps[0].runs,
            (std::vector<std::string>{"results/ppo_seed0", "results/ppo_seed1"}));
}

// Runs side by side in the served directory itself are the list, not a sweep; a sweep's summary
// and its figures are found.
TEST_F(RunIndexTest, TheRootIsNoSweepAndSummariesAreFound) {
  make_run(directory_ / "a_seed0", "algorithm: ppo\n");
  make_run(directory_ / "a_seed1", "algorithm: ppo\n");
  make_run(directory_ / "sweep" / "only_seed0", "algorithm: ppo\n");
  fs::create_directories(directory_ / "sweep" / "summary" / "curves");
  std::ofstream(directory_ / "sweep" / "summary" / "summary.md") << "# Sweep\n";
  std::ofstream(directory_ / "sweep" / "summary" / "training.png") << "png";
  std::ofstream(directory_ / "sweep" / "summary" / "eval.svg") << "svg";
  std::ofstream(directory_ / "sweep" / "summary" / "runs.csv") << "run\n";
  const RunIndex index = index_runs(ServedRoot(directory_));
  EXPECT_EQ(index.runs.size(), 3u);
  ASSERT_EQ(index.sweeps.size(), 1u);  // one run and a summary: a sweep; the root: none
  EXPECT_EQ(index.sweeps[0].path, "sweep");
  EXPECT_EQ(index.sweeps[0].summary, "sweep/summary/summary.md");
  EXPECT_EQ(index.sweeps[0].figures,
            (std::vector<std::string>{"sweep/summary/eval.svg", "sweep/summary/training.png"}));
  EXPECT_EQ(index.runs[0].state.kind, "training");
  EXPECT_EQ(index.runs[0].state.status, "stopped");
}

TEST_F(RunIndexTest, TheRootItselfCanBeARun) {
  make_run(directory_, "algorithm: sac\n");
  const RunIndex index = index_runs(ServedRoot(directory_));
  ASSERT_EQ(index.runs.size(), 1u);
  EXPECT_EQ(index.runs[0].path, "");
  EXPECT_EQ(index.runs[0].algorithm, "sac");
}

}  // namespace
}  // namespace tendril::dashboard
