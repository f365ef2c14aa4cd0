#include "tendril/core/run_curves.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"

// The one implementation of grouping runs by seed and of their statistics over seeds, which the
// sweep summaries, `tendril plot curves` (tests/plot/tendril_plot_test.py checks it is this one)
// and the dashboard (/api/curves, tests/dashboard/server_test.cpp) read.
namespace tendril {
namespace {

namespace fs = std::filesystem;

TEST(SeedGroup, DropsTheSeedTokenAndTheSeparatorsItLeaves) {
  EXPECT_EQ(seed_group("n_steps_256-seed_3"), "n_steps_256");
  EXPECT_EQ(seed_group("ppo_case1_seed0"), "ppo_case1");
  EXPECT_EQ(seed_group("seed_3-tau_0.01"), "tau_0.01");
  EXPECT_EQ(seed_group("n_steps_64-seed_12-gamma_0.9"), "n_steps_64-gamma_0.9");
  EXPECT_EQ(seed_group("PPO_Seed7"), "PPO");
  EXPECT_EQ(seed_group("seed_42", "ur5_ppo_base"), "ur5_ppo_base");
  EXPECT_EQ(seed_group("seed_42"), "seeds");
  EXPECT_EQ(seed_group("tau_0.01"), "tau_0.01");  // no seed: a group of its own
  // `tendril train`'s default names: seeds of one experiment group, whenever each was trained.
  EXPECT_EQ(seed_group("ppo_pendulum-seed1-20261128-093000"), "ppo_pendulum");
  EXPECT_EQ(seed_group("ppo_pendulum-seed2-20261128-093512"), "ppo_pendulum");
  EXPECT_EQ(seed_group("lr_0.001-20261128-093000"), "lr_0.001");
}

TEST(SpreadOf, MeanPopulationStdMinMax) {
  const Spread s = spread_of({1.0, 2.0, 3.0, 4.0});
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(1.25));  // (2.25 + 0.25 + 0.25 + 2.25) / 4
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  EXPECT_EQ(s.count, 4);
  EXPECT_TRUE(std::isnan(spread_of({}).mean));
}

// Lines y = a x over different x ranges: on the common range every interpolated value is
// exact, so the mean is mean(a) x and the std std(a) |x| at each grid point.
TEST(AggregateCurves, MeanAndSpreadOnTheRangeEveryCurveCovers) {
  const double slopes[] = {1.0, 2.0, 6.0};
  const double starts[] = {0.0, 2.0, 1.0}, ends[] = {10.0, 12.0, 8.0};
  std::vector<Curve> curves;
  for (int k = 0; k < 3; ++k) {
    Curve c;
    for (double x = starts[k]; x <= ends[k] + 1e-9; x += 0.5 + k * 0.25) {
      c.x.push_back(x);
      c.y.push_back(slopes[k] * x);
    }
    c.x.push_back(ends[k]);  // the last point exactly at the end (a repeated x is harmless)
    c.y.push_back(slopes[k] * ends[k]);
    curves.push_back(c);
  }
  curves.push_back(Curve{});  // a run without data is left out
  const CurveStats stats = aggregate_curves(curves, 13);
  ASSERT_EQ(stats.x.size(), 13u);
  EXPECT_EQ(stats.curves, 3);
  EXPECT_DOUBLE_EQ(stats.x.front(), 2.0);
  EXPECT_DOUBLE_EQ(stats.x.back(), 8.0);
  const double std_slope = std::sqrt(((1 - 3.0) * (1 - 3.0) + 1 + 9) / 3.0);
  for (std::size_t i = 0; i < stats.x.size(); ++i) {
    const double x = stats.x[i];
    EXPECT_NEAR(x, 2.0 + 0.5 * i, 1e-12);
    EXPECT_NEAR(stats.mean[i], 3.0 * x, 1e-9);
    EXPECT_NEAR(stats.std[i], std_slope * x, 1e-9);
    EXPECT_NEAR(stats.min[i], 1.0 * x, 1e-9);
    EXPECT_NEAR(stats.max[i], 6.0 * x, 1e-9);
  }
  // Ranges that do not overlap give no curve.
  EXPECT_TRUE(aggregate_curves({Curve{{0, 1}, {0, 1}}, Curve{{2, 3}, {0, 1}}}).x.empty());
}

// The live view's span: from the first curve's start to the last one's end, each point
// averaging the curves that reach it. Lines y = a x again, so each point is exact.
TEST(AggregateCurves, TheSpanOfAnyCurveAveragesTheCurvesThatReachEachPoint) {
  const Curve first{{0, 10}, {0, 10}};    // y = x over [0, 10]
  const Curve second{{5, 20}, {15, 60}};  // y = 3 x over [5, 20]
  const CurveStats stats = aggregate_curves({first, second}, 21, CurveSpan::kAny);
  ASSERT_EQ(stats.x.size(), 21u);
  EXPECT_EQ(stats.curves, 2);
  for (std::size_t i = 0; i < stats.x.size(); ++i) {
    const double x = stats.x[i];
    EXPECT_DOUBLE_EQ(x, static_cast<double>(i));
    const bool both = x >= 5 && x <= 10;
    EXPECT_EQ(stats.count[i], both ? 2 : 1) << x;
    const double mean = both ? 2 * x : (x < 5 ? x : 3 * x);
    EXPECT_NEAR(stats.mean[i], mean, 1e-12) << x;
    EXPECT_NEAR(stats.std[i], both ? x : 0.0, 1e-12) << x;
  }
  // The common span of the same curves is [5, 10], each point from both.
  const CurveStats common = aggregate_curves({first, second}, 6);
  ASSERT_EQ(common.x.size(), 6u);
  EXPECT_DOUBLE_EQ(common.x.front(), 5.0);
  EXPECT_DOUBLE_EQ(common.x.back(), 10.0);
  for (const int n : common.count) EXPECT_EQ(n, 2);
  // Ranges that do not overlap still give a curve, one run at each point.
  const CurveStats apart =
      aggregate_curves({Curve{{0, 1}, {0, 1}}, Curve{{2, 3}, {0, 1}}}, 7, CurveSpan::kAny);
  EXPECT_EQ(apart.x.size(), 7u);
  EXPECT_EQ(apart.count, (std::vector<int>{1, 1, 1, 0, 1, 1, 1}));
  EXPECT_TRUE(std::isnan(apart.mean[3]));  // x = 1.5 lies between the two runs
  EXPECT_EQ(testing::error_message([] {
              aggregate_curves({Curve{{0, 1}, {0}}});
            }),
            "a curve's x and y differ in length");
}

// Runs are grouped by their names without the seed, a name that is only a seed by the directory
// holding it, in order of first appearance.
TEST(GroupBySeed, GroupsInOrderOfFirstAppearance) {
  const std::vector<RunGroup> groups =
      group_by_seed({"out/lr_0.1-seed_0", "out/lr_0.3-seed_0", "out/lr_0.1-seed_1/",
                     "sweeps/ur5_ppo/seed_42", "sweeps/ur5_ppo/seed_55", "out/lr_0.3-seed_1"});
  ASSERT_EQ(groups.size(), 3u);
  EXPECT_EQ(groups[0].name, "lr_0.1");
  EXPECT_EQ(groups[0].members, (std::vector<int>{0, 2}));
  EXPECT_EQ(groups[1].name, "lr_0.3");
  EXPECT_EQ(groups[1].members, (std::vector<int>{1, 5}));
  EXPECT_EQ(groups[2].name, "ur5_ppo");
  EXPECT_EQ(groups[2].members, (std::vector<int>{3, 4}));
}

class RunCurveFiles : public testing::ScratchDirectoryTest {
 protected:
  RunCurveFiles() : ScratchDirectoryTest("run_curves") {}
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(directory_ / name) << text;
  }
};

TEST_F(RunCurveFiles, ReadsTheMetricsOfPlotAndDashboard) {
  write("progress.csv",
        "time/total_timesteps,rollout/ep_rew_mean,train/loss\n"
        "200,-5,nan\n100,-7,0.5\n300,,0.25\n"
        "time/total_timesteps,rollout/ep_rew_mean,train/loss\n"  // a resume's repeated header
        "400,-2,0.125\n500,-1");  // the last line is still being written
  write("eval.csv", "timesteps,mean_return,std_return,success_rate\n100,-9,1,0\n300,-3,1,0.5\n");
  const Curve train = read_run_curve(directory_, "rollout/ep_rew_mean");
  EXPECT_EQ(train.x, (std::vector<double>{100, 200, 400}));  // sorted, the empty cell left out
  EXPECT_EQ(train.y, (std::vector<double>{-7, -5, -2}));
  const Curve loss = read_run_curve(directory_, "train/loss");
  EXPECT_EQ(loss.x, (std::vector<double>{100, 300, 400}));
  const Curve eval = read_run_curve(directory_, "eval");
  EXPECT_EQ(eval.y, (std::vector<double>{-9, -3}));
  const Curve success = read_run_curve(directory_, "eval:success_rate");
  EXPECT_EQ(success.y, (std::vector<double>{0, 0.5}));
  const Curve by_return = read_run_curve(directory_, "train/loss", "rollout/ep_rew_mean");
  EXPECT_EQ(by_return.x, (std::vector<double>{-7, -2}));

  const std::string eval_file = (directory_ / "eval.csv").string();
  EXPECT_EQ(testing::error_message([&] { read_run_curve(directory_, "eval:nope"); }),
            eval_file + ": has no column 'nope' (it has: mean_return, std_return, " +
                "success_rate, timesteps)");
  fs::remove(directory_ / "eval.csv");
  EXPECT_EQ(testing::error_message([&] { read_run_curve(directory_, "eval"); }),
            eval_file + ": no such file");
}

}  // namespace
}  // namespace tendril
