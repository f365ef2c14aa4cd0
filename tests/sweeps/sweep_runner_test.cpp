#include "tendril/sweeps/sweep_runner.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/scratch_directory.hpp"
#include "tendril/core/run_lock.hpp"

namespace tendril::sweeps {
namespace {

namespace fs = std::filesystem;

class SweepRuns : public testing::ScratchDirectoryTest {
 protected:
  SweepRuns() : ScratchDirectoryTest("sweep_runner") {}
  // Four seeds of a short PPO run (8 iterations of 128 steps, a checkpoint every 256 steps).
  Sweep sweep() const {
    std::ofstream(directory_ / "base.yaml")
        << "algorithm: ppo\nenv: {id: Pendulum-v1, n_envs: 2}\nalgo: {n_steps: 64}\n"
           "n_timesteps: 1024\ncheckpoint_freq: 256\neval: {freq: 512, episodes: 1}\nseed: 0\n";
    std::ofstream(directory_ / "sweep.yaml")
        << "experiment: base.yaml\ngrid:\n  - {key: seed, values: [0, 1, 2, 3]}\noutput: "
        << (directory_ / "out").string() << "\n";
    return Sweep::load(directory_ / "sweep.yaml");
  }
};

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<SweepRunStatus> statuses(const std::vector<SweepRunRecord>& records) {
  std::vector<SweepRunStatus> result;
  for (const SweepRunRecord& r : records) result.push_back(r.status);
  return result;
}

// A sweep found in every state a killed sweep leaves: run 0 finished, run 1 interrupted after a
// checkpoint, run 2 killed before its first one (with the stale lock of its dead process), run
// 3 held by a live process. The rerun keeps run 0, resumes run 1, starts run 2 again and leaves
// run 3 alone; runs 1 and 2 end bit for bit as uninterrupted runs of their seeds do.
TEST_F(SweepRuns, AnInterruptedSweepResumesWhereEachRunStopped) {
  const Sweep s = sweep();
  const auto runs = s.runs();
  const rl::TrainOptions quiet{.stop_at = std::nullopt, .quiet = true};
  ASSERT_EQ(statuses(train_sweep_runs(s, {0}, quiet)),
            std::vector<SweepRunStatus>{SweepRunStatus::started});
  const std::string policy0 = read(s.directory(runs[0]) / "model.policy");
  const auto time0 = fs::last_write_time(s.directory(runs[0]) / "model.policy");

  const rl::TrainOptions paused{.stop_at = 256, .quiet = true};
  rl::train(rl::Experiment::from_config(s.experiment(runs[1])), s.directory(runs[1]), paused);
  rl::train(rl::Experiment::from_config(s.experiment(runs[2])), s.directory(runs[2]), paused);
  fs::remove_all(s.directory(runs[2]) / "checkpoints");  // killed before its first checkpoint
  std::ofstream(s.directory(runs[2]) / "run.lock") << "999999\n";
  ASSERT_FALSE(fs::exists(s.directory(runs[1]) / "model.policy"));
  ASSERT_FALSE(fs::exists(s.directory(runs[2]) / "model.policy"));
  fs::create_directories(s.directory(runs[3]));
  std::optional<RunLock> holder(RunLock(s.directory(runs[3])));  // another writer

  std::vector<std::pair<int, bool>> seen;
  const auto records = train_sweep_runs(
      s, {0, 1, 2, 3}, quiet,
      [&](const SweepRunRecord& r, bool done) { seen.emplace_back(r.index, done); });
  EXPECT_EQ(statuses(records),
            (std::vector<SweepRunStatus>{SweepRunStatus::finished_earlier, SweepRunStatus::resumed,
                                         SweepRunStatus::restarted, SweepRunStatus::busy}));
  EXPECT_EQ(seen, (std::vector<std::pair<int, bool>>{
                      {0, true}, {1, false}, {1, true}, {2, false}, {2, true}, {3, true}}));
  EXPECT_EQ(read(s.directory(runs[0]) / "model.policy"), policy0);
  EXPECT_EQ(fs::last_write_time(s.directory(runs[0]) / "model.policy"), time0);
  EXPECT_EQ(records[1].result.timesteps, 1024);
  EXPECT_TRUE(records[1].result.finished);
  EXPECT_EQ(records[2].result.timesteps, 1024);
  EXPECT_FALSE(fs::exists(s.directory(runs[3]) / "config.yaml"));
  EXPECT_FALSE(sweep_finished(s));
  for (const int i : {1, 2}) {
    const fs::path whole = directory_ / ("whole_" + std::to_string(i));
    rl::train(rl::Experiment::from_config(s.experiment(runs[i])), whole, quiet);
    EXPECT_EQ(read(s.directory(runs[i]) / "model.policy"), read(whole / "model.policy")) << i;
    EXPECT_EQ(read(s.directory(runs[i]) / "eval.csv"), read(whole / "eval.csv")) << i;
  }

  // Once its holder lets go, the next pass trains run 3 and keeps the others.
  holder.reset();
  EXPECT_EQ(statuses(train_sweep_runs(s, {0, 1, 2, 3}, quiet)),
            (std::vector<SweepRunStatus>{
                SweepRunStatus::finished_earlier, SweepRunStatus::finished_earlier,
                SweepRunStatus::finished_earlier, SweepRunStatus::started}));
  EXPECT_TRUE(sweep_finished(s));
}

TEST_F(SweepRuns, EachProcessLogsItsStartAndEnd) {
  const Sweep s = sweep();
  log_sweep_event(s, "start", SweepShare{1, 2, ""});
  log_sweep_event(s, "end", SweepShare{1, 2, ""});
  const std::string log = read(directory_ / "out" / "sweep_log.csv");
  EXPECT_EQ(log.substr(0, log.find('\n')), "event,unix_time,host,pid,rank,ranks");
  EXPECT_NE(log.find("\nstart,"), std::string::npos);
  EXPECT_NE(log.find(",1,2\nend,"), std::string::npos);
  // A second writer of the summary is turned away while the first holds its lock.
  bool inner = true;
  EXPECT_TRUE(with_summary_lock(s, [&] { inner = with_summary_lock(s, [] {}); }));
  EXPECT_FALSE(inner);
}

}  // namespace
}  // namespace tendril::sweeps
