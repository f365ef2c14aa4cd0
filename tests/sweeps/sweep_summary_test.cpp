#include "tendril/sweeps/sweep_summary.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/sweeps/runs_report.hpp"
#include "tendril/sweeps/sweep.hpp"

namespace tendril::sweeps {
namespace {

namespace fs = std::filesystem;

class SweepSummaries : public testing::ScratchDirectoryTest {
 protected:
  SweepSummaries() : ScratchDirectoryTest("sweep_summary") {}
  // A run directory as the trainer leaves it: progress.csv, eval.csv, model.policy if finished.
  void write_run(const std::string& name, const std::string& progress, const std::string& eval,
                 bool finished) const {
    const fs::path run = directory_ / "out" / name;
    fs::create_directories(run);
    std::ofstream(run / "progress.csv") << progress;
    std::ofstream(run / "eval.csv") << "timesteps,mean_return,std_return,mean_length,episodes\n"
                                    << eval;
    if (finished) std::ofstream(run / "model.policy") << "policy";
  }
  Sweep sweep() const {
    std::ofstream(directory_ / "base.yaml")
        << "algorithm: ppo\nenv: {id: Pendulum-v1, n_envs: 2}\nalgo: {n_steps: 64}\n"
           "n_timesteps: 1000\nseed: 0\n";
    std::ofstream(directory_ / "sweep.yaml")
        << "experiment: base.yaml\ngrid:\n  - {key: algo.n_steps, values: [64, 128]}\n"
           "  - {key: seed, values: [0, 1, 2]}\noutput: "
        << (directory_ / "out").string() << "\n";
    return Sweep::load(directory_ / "sweep.yaml");
  }
};

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST_F(SweepSummaries, RunStepsPerSecondAddsTheStretchesOfEveryProcess) {
  // A run trained 200 steps in 2 s (100 steps/s), then resumed for 450 steps in 1.5 s: the
  // clock restarts at the resume. A last line without its newline is being written: ignored.
  write_run("r",
            "time/total_timesteps,time/fps,time/time_elapsed,rollout/ep_rew_mean\n"
            "100,100,1,-5\n200,100,2,-4\n350,300,0.5,-3\n650,300,1.5,-1\n700,1,1",
            "100,-9,1,10,2\n650,-2.5,0.5,10,2\n", true);
  const RunSummary run = summarize_run(directory_ / "out" / "r");
  EXPECT_TRUE(run.finished);
  EXPECT_EQ(run.steps, 650);
  EXPECT_DOUBLE_EQ(run.seconds, 3.5);
  EXPECT_DOUBLE_EQ(run.steps_per_second, 650.0 / 3.5);
  EXPECT_EQ(*run.final_eval_mean, -2.5);
  EXPECT_EQ(*run.final_eval_std, 0.5);
  EXPECT_EQ(run.final_eval_steps, 650);
  EXPECT_EQ(run.train.x, (std::vector<double>{100, 200, 350, 650}));
  EXPECT_EQ(run.train.y, (std::vector<double>{-5, -4, -3, -1}));
  EXPECT_EQ(*run.final_train_mean, -1.0);
}

// Configurations of known final evaluations: n_steps 64 over seeds with 1, 2, 3 (mean 2, std
// sqrt(2/3)); n_steps 128 with 10 and 20 finished and a third run unfinished (mean 15, std 5).
TEST_F(SweepSummaries, ConfigurationsAreMeansAndSpreadsOverSeeds) {
  const Sweep s = sweep();
  const std::string header =
      "time/total_timesteps,time/fps,time/time_elapsed,rollout/ep_rew_mean\n";
  const double finals[] = {1, 2, 3, 10, 20, 99};
  const auto runs = s.runs();
  for (int i = 0; i < 6; ++i) {
    // Training curves y = (i + 1) x over steps 0..1000 (the unfinished one reaches 500).
    std::ostringstream progress;
    progress << header;
    const int last = i == 5 ? 500 : 1000;
    for (int step = 0; step <= last; step += 100) {
      progress << step << ",1000," << (step + 1) / 1000.0 << "," << (i + 1) * step << "\n";
    }
    std::ostringstream eval;
    eval << "500,0,0,10,2\n" << last << "," << finals[i] << ",1,10,2\n";
    write_run(runs[i].name, progress.str(), eval.str(), i != 5);
  }
  // Two ranks from 1000.5 to 1130.5; after an idle gap one process for 10 s, then one killed
  // (no end): wall time 1999.5 s from first to last event, busy 130 + 10 s.
  std::ofstream(directory_ / "out" / "sweep_log.csv")
      << "event,unix_time,host,pid,rank,ranks\nstart,1000.5,a,1,0,2\nstart,1001,b,2,1,2\n"
         "end,1100,b,2,1,2\nend,1130.5,a,1,0,2\nstart,2000,a,7,0,1\nend,2010,a,7,0,1\n"
         "start,3000,a,8,0,1\n";

  const SweepSummary summary = summarize_sweep(s);
  ASSERT_EQ(summary.configurations.size(), 2u);
  const ConfigurationSummary& a = summary.configurations[0];
  const ConfigurationSummary& b = summary.configurations[1];
  EXPECT_EQ(a.name, "n_steps_64");
  EXPECT_EQ(a.settings, (std::vector<std::pair<std::string, std::string>>{{"algo.n_steps", "64"}}));
  EXPECT_EQ(a.runs, (std::vector<int>{0, 1, 2}));
  EXPECT_DOUBLE_EQ(a.final_eval.mean, 2.0);
  EXPECT_DOUBLE_EQ(a.final_eval.std, std::sqrt(2.0 / 3.0));
  EXPECT_EQ(b.name, "n_steps_128");
  EXPECT_EQ(b.final_eval.count, 2);
  EXPECT_DOUBLE_EQ(b.final_eval.mean, 15.0);
  EXPECT_DOUBLE_EQ(b.final_eval.std, 5.0);
  // Learning curves: slopes 1, 2, 3 → mean 2x, std sqrt(2/3) x over 0..1000; slopes 4, 5, 6
  // cut to 0..500, where the unfinished run ends.
  EXPECT_DOUBLE_EQ(a.train.x.back(), 1000.0);
  EXPECT_NEAR(a.train.mean.back(), 2000.0, 1e-9);
  EXPECT_NEAR(a.train.std.back(), 1000.0 * std::sqrt(2.0 / 3.0), 1e-9);
  EXPECT_DOUBLE_EQ(b.train.x.back(), 500.0);
  EXPECT_NEAR(b.train.mean.back(), 2500.0, 1e-9);
  EXPECT_EQ(b.train.curves, 3);
  EXPECT_DOUBLE_EQ(summary.wall_seconds, 1999.5);
  EXPECT_DOUBLE_EQ(summary.busy_seconds, 140.0);
  EXPECT_EQ(summary.processes, 4);
  EXPECT_EQ(summary.ended_processes, 3);

  write_sweep_summary(s, summary, directory_ / "out" / "summary", {{"training.png", "curves"}});
  const std::string table = read(directory_ / "out" / "summary" / "configurations.csv");
  EXPECT_NE(table.find("configuration,algo.n_steps,seeds,finished,final_eval_mean,"),
            std::string::npos);
  EXPECT_NE(table.find("n_steps_64,64,3,3,2,0.8164965809,1,3,"), std::string::npos) << table;
  EXPECT_NE(table.find("n_steps_128,128,3,2,15,5,10,20,"), std::string::npos) << table;
  // Each run's last training return beside its final evaluation: run 0 ends at 1 × 1000.
  const std::string runs_csv = read(directory_ / "out" / "summary" / "runs.csv");
  EXPECT_NE(runs_csv.find(",final_eval_mean,final_eval_std,final_train_mean\n"), std::string::npos);
  EXPECT_NE(runs_csv.find(",1000,1,1,1000\n"), std::string::npos) << runs_csv;
  const std::string page = read(directory_ / "out" / "summary" / "summary.md");
  EXPECT_NE(page.find("| n_steps_64 | 64 | 3 / 3 | 2.00 ± 0.82 | 1.00 | 3.00 |"), std::string::npos)
      << page;
  EXPECT_NE(page.find("| n_steps_128 | 128 | 2 / 3 | 15.00 ± 5.00 | 10.00 | 20.00 |"),
            std::string::npos);
  EXPECT_NE(page.find("Wall time: 1999.5 s"), std::string::npos);
  EXPECT_NE(page.find("Busy wall time: 140.0 s (0.04 h), while at least one process ran (the 3 "
                      "process(es) that logged their end)"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("![curves](training.png)"), std::string::npos);
  const std::string curve =
      read(directory_ / "out" / "summary" / "curves" / "n_steps_64.train.csv");
  EXPECT_EQ(curve.substr(0, curve.find('\n')), "steps,mean,std,min,max,seeds");
  EXPECT_NE(curve.find("\n1000,2000,816.496580"), std::string::npos) << curve.substr(0, 300);
}

// Runs outside a sweep: a_seed0, a_seed1 (finals 2 and 4; training means y = step / 100 and
// y = 3 step / 100 at steps 100..1000) and b_seed0 (final 10, trained to 500 steps, unfinished).
TEST_F(SweepSummaries, RunsOutsideASweepGroupBySeedTokenAndReport) {
  const std::string header =
      "time/total_timesteps,time/fps,time/time_elapsed,rollout/ep_rew_mean\n";
  const struct {
    const char* name;
    double slope, final_eval;
    int last;
    bool finished;
  } runs[] = {
      {"a_seed0", 1, 2, 1000, true}, {"a_seed1", 3, 4, 1000, true}, {"b_seed0", 5, 10, 500, false}};
  for (const auto& r : runs) {
    std::ostringstream progress;
    progress << header;
    for (int step = 100; step <= r.last; step += 100) {
      progress << step << ",100," << step / 100.0 << "," << r.slope * step / 100.0 << "\n";
    }
    write_run(r.name, progress.str(),
              std::to_string(r.last) + "," + std::to_string(r.final_eval) + ",0.5,10,2\n",
              r.finished);
  }
  const fs::path out = directory_ / "out";
  // A directory of runs adds them in name order; a run named directly is taken as it is.
  const std::vector<fs::path> found = run_directories({out, out / "a_seed1"});
  EXPECT_EQ(found, (std::vector<fs::path>{out / "a_seed0", out / "a_seed1", out / "b_seed0",
                                          out / "a_seed1"}));
  EXPECT_EQ(testing::error_message([&] { run_directories({directory_}); }),
            directory_.string() + ": holds no run (a directory with a progress.csv)");
  EXPECT_EQ(testing::error_message([&] { run_directories({out / "missing"}); }),
            (out / "missing").string() + ": is not a directory");

  const SweepSummary summary = summarize_runs(run_directories({out}));
  ASSERT_EQ(summary.configurations.size(), 2u);
  EXPECT_EQ(summary.configurations[0].name, "a");
  EXPECT_EQ(summary.configurations[0].runs, (std::vector<int>{0, 1}));
  EXPECT_DOUBLE_EQ(summary.configurations[0].final_eval.mean, 3.0);
  EXPECT_DOUBLE_EQ(summary.configurations[0].final_eval.std, 1.0);
  EXPECT_EQ(summary.configurations[1].name, "b");
  EXPECT_EQ(summary.configurations[1].final_eval.count, 0);  // unfinished
  EXPECT_DOUBLE_EQ(summary.run_seconds, 10 + 10 + 5);
  EXPECT_TRUE(std::isnan(summary.wall_seconds));

  // The last row at or before the step; none before the first row or past the run's steps.
  const RunSummary& a1 = summary.runs[1];
  EXPECT_EQ(training_mean_at(a1, 250), std::optional<double>(6.0));
  EXPECT_EQ(training_mean_at(a1, 300), std::optional<double>(9.0));
  EXPECT_EQ(training_mean_at(a1, 1000), std::optional<double>(30.0));
  EXPECT_EQ(training_mean_at(a1, 99), std::nullopt);
  EXPECT_EQ(training_mean_at(summary.runs[2], 600), std::nullopt);

  // At 600: a's runs 6 and 18 (mean 12, std 6); b has not reached it. At the end: 10 and 30,
  // and b's 25. Final evaluations 2 and 4 (3 ± 1); b unfinished has none.
  const std::string report = runs_report(summary, {600});
  EXPECT_NE(report.find("| configuration | training mean at 600 | training mean at the end | "
                        "final evaluation | runs | training time (s) |"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find("| a | 12.00 ± 6.00 | 20.00 ± 10.00 | 3.00 ± 1.00 | 2 | 20.0 |"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find("| b | – | 25.00 ± 0.00 | – | 1 | 5.0 |"), std::string::npos) << report;
  EXPECT_NE(report.find("| a_seed1 | 18.00 | 30.00 | 4.00 ± 0.50 at 1000 | 1000 | 10.0 | 100 |"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find("| b_seed0 | – | 25.00 | – | 500 | 5.0 | 100 |"), std::string::npos)
      << report;
  EXPECT_NE(report.find("3 runs (2 finished) in 2 configurations"), std::string::npos);
}

}  // namespace
}  // namespace tendril::sweeps
