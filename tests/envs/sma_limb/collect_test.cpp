// Count-based exploration (Algorithm 1), motor babbling and the collection loop.
#include "tendril/envs/sma_limb/collect.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/envs/sma_limb/sma_limb_env.hpp"
#include "tendril/envs/sma_limb/twin_limb_robot.hpp"

namespace tendril::envs::sma_limb {
namespace {

TEST(VisitGrid, MapsAnglesToSixBySixCellsOverPlusMinus100Degrees) {
  VisitGrid grid;
  EXPECT_EQ(grid.cells(), 36);
  EXPECT_EQ(grid.cell(Eigen::Vector2d(-99.0, -99.0)), 0);
  EXPECT_EQ(grid.cell(Eigen::Vector2d(99.0, -99.0)), 5);
  EXPECT_EQ(grid.cell(Eigen::Vector2d(-99.0, 99.0)), 30);
  EXPECT_EQ(grid.cell(Eigen::Vector2d(0.1, 0.1)), 3 * 6 + 3);
  EXPECT_EQ(grid.cell(Eigen::Vector2d(-150.0, 400.0)), 30) << "outside: the edge cells";
  // Cells are 33.3° wide: centres at ±16.7°, ±50°, ±83.3°.
  EXPECT_NEAR(grid.centre(0).x(), -100.0 + 100.0 / 6.0, 1e-12);
  EXPECT_NEAR(grid.centre(21).x(), 100.0 / 6.0, 1e-12);
  EXPECT_NEAR(grid.centre(21).y(), 100.0 / 6.0, 1e-12);
}

// Evenness = entropy / log(cells): 1 for equal visits, 0 for one cell, log 2 / log 36 for two
// equally visited cells.
TEST(VisitGrid, MeasuresCoverageAndEvenness) {
  VisitGrid grid;
  EXPECT_EQ(grid.evenness(), 0.0);
  grid.visit(Eigen::Vector2d(0.0, 0.0));
  grid.visit(Eigen::Vector2d(1.0, 1.0));
  EXPECT_EQ(grid.visited_cells(), 1);
  EXPECT_EQ(grid.evenness(), 0.0);
  grid.visit(Eigen::Vector2d(90.0, 90.0));
  grid.visit(Eigen::Vector2d(90.0, 80.0));
  EXPECT_EQ(grid.visited_cells(), 2);
  EXPECT_NEAR(grid.evenness(), std::log(2.0) / std::log(36.0), 1e-12);
  EXPECT_EQ(grid.max_count(), 2);
  VisitGrid even;
  for (int c = 0; c < 36; ++c) even.visit(even.centre(c));
  EXPECT_NEAR(even.evenness(), 1.0, 1e-12);
}

// SampleCell draws cell c with probability (m + 1 − g[c]) / Σ: after visits 3, 1 to two cells
// (m = 3) the weights are 1, 3 and 4 for the 34 unvisited cells.
TEST(CountBasedExploration, SamplesLessVisitedCellsMoreOften) {
  CountBasedExploration exploration;
  const Eigen::Vector2d crowded(0.0, 0.0), visited(50.0, 50.0);
  for (int k = 0; k < 3; ++k) exploration.observe(crowded);
  exploration.observe(visited);
  const int crowded_cell = exploration.grid().cell(crowded);
  const int visited_cell = exploration.grid().cell(visited);
  Rng rng(11);
  std::vector<int> draws(36, 0);
  const int n = 200000;
  for (int k = 0; k < n; ++k) ++draws[exploration.sample_cell(rng)];
  const double total = 1.0 + 3.0 + 34 * 4.0;
  EXPECT_NEAR(draws[crowded_cell] / static_cast<double>(n), 1.0 / total, 0.002);
  EXPECT_NEAR(draws[visited_cell] / static_cast<double>(n), 3.0 / total, 0.003);
  EXPECT_NEAR(draws[0] / static_cast<double>(n), 4.0 / total, 0.003);
}

// The thesis' ComputeAction pushes each axis towards the target cell's centre (a positive
// throttle raises the angle), with a magnitude uniform in 1 … 10.
TEST(CountBasedExploration, UniformThrottlesPointTowardsTheTarget) {
  CountBasedExploration exploration(CountBasedExploration::Rule::kUniform);
  Rng rng(2);
  const int target = exploration.grid().cell(Eigen::Vector2d(90.0, -90.0));
  std::vector<int> magnitudes(11, 0);
  for (int k = 0; k < 5000; ++k) {
    const Eigen::Vector2i u = exploration.uniform_action(Eigen::Vector2d(10.0, 10.0), target, rng);
    ASSERT_GE(u.x(), 1);
    ASSERT_LE(u.y(), -1);
    ++magnitudes[u.x()];
  }
  for (int m = 1; m <= 10; ++m) EXPECT_NEAR(magnitudes[m], 500, 80) << m;
  const Eigen::Vector2i back = exploration.uniform_action(Eigen::Vector2d(95.0, -95.0),
                                                          exploration.grid().cell({0, 0}), rng);
  EXPECT_LT(back.x(), 0);
  EXPECT_GT(back.y(), 0);
}

// The firmware's rule: the throttles walk towards the target's column and row by 0 … 3 levels a
// hold, saturate at ±10, and relax towards zero along an axis already aligned with the target.
TEST(CountBasedExploration, RandomWalkThrottlesStepTowardsTheTarget) {
  CountBasedExploration exploration;
  Rng rng(4);
  const Eigen::Vector2d state(-90.0, 0.1);                                  // column 0, row 3
  const int target = exploration.grid().cell(Eigen::Vector2d(90.0, 10.0));  // column 5, row 3
  Eigen::Vector2i previous = exploration.throttles();
  for (int k = 0; k < 40; ++k) {
    const Eigen::Vector2i u = exploration.walk_action(state, target, rng);
    ASSERT_GE(u.x() - previous.x(), 0);
    ASSERT_LE(u.x() - previous.x(), 3);
    ASSERT_EQ(u.y(), 0) << "aligned and at zero: stays";
    previous = u;
  }
  EXPECT_EQ(previous.x(), 10) << "saturates";
  // In the target's column (70° below its centre): x relaxes towards zero, y walks up.
  const Eigen::Vector2d aligned(80.0, -60.0);
  for (int k = 0; k < 30; ++k) {
    const Eigen::Vector2i u = exploration.walk_action(aligned, target, rng);
    ASSERT_LE(std::abs(u.x()), std::max(std::abs(previous.x()), 3));
    ASSERT_GE(u.y(), previous.y());
    previous = u;
  }
  EXPECT_LE(std::abs(previous.x()), 3);
  EXPECT_EQ(previous.y(), 10);
}

// The author's babbling: one coil or two neighbouring ones, levels 0 … 10. By hand, per axis
// P(u = ±k) = 3/88 for k = 1 … 10 (the coil alone, as the first of two, or as the neighbour:
// 1/88 each) and P(u = 0) = 28/88; both axes on only for two coils at non-zero levels,
// ½ (10/11)².
TEST(MotorBabbling, DrawsTheFirmwaresCoilsAndLevels) {
  MotorBabbling babbling;
  Rng rng(3);
  std::vector<int> counts(21, 0);
  int both = 0;
  const int n = 88000;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2i u = babbling.next(Eigen::Vector2d::Zero(), rng);
    ++counts[u.x() + 10];
    ASSERT_LE(std::abs(u.y()), 10);
    both += u.x() != 0 && u.y() != 0;
  }
  for (int level = 0; level < 21; ++level) {
    EXPECT_NEAR(counts[level], level == 10 ? 28000 : 3000, level == 10 ? 600 : 250) << level;
  }
  EXPECT_NEAR(both / static_cast<double>(n), 0.5 * 100.0 / 121.0, 0.01);
}

std::unique_ptr<SmaLimbEnv> twin_env(const std::string& limb) {
  physics::SmaLimbSpec spec = physics::SmaLimbSpec::variant(limb);
  LimbCalibration calibration = LimbCalibration::nominal(limb);
  calibration.zero_offset_deg = spec.sensor.zero_offset;
  return std::make_unique<SmaLimbEnv>(std::make_unique<TwinLimbRobot>(spec), calibration, 0);
}

TEST(Collect, LogsEveryReadingWithWhatDroveItAndRepeatsWithTheSeed) {
  auto run = [](uint64_t seed) {
    auto env = twin_env("stiff");
    CountBasedExploration exploration;
    CollectSettings settings;
    settings.duration_s = 30.0;
    return collect(*env, exploration, settings, seed);
  };
  const LimbLog log = run(4);
  ASSERT_GT(log.size(), 30.0 / 0.075);
  ASSERT_LT(log.size(), 30.0 / 0.055 + 1);
  EXPECT_EQ(log.time_s.front(), 0.0);
  EXPECT_LT(log.time_s.back(), 30.0);
  for (std::size_t k = 1; k < log.size(); ++k) {
    ASSERT_GT(log.time_s[k], log.time_s[k - 1]);
    // Throttles are held for ten readings at a time.
    if (k % 10 != 0) {
      ASSERT_EQ(log.throttles[k], log.throttles[k - 1]) << k;
    }
  }
  // The PWM is the table's for the throttles (the limb never reached the cut-off here).
  const LimbCalibration nominal = LimbCalibration::nominal("stiff");
  for (std::size_t k = 0; k < log.size(); ++k) {
    ASSERT_EQ(log.pwm[k], nominal.pwm_for(log.throttles[k].x(), log.throttles[k].y())) << k;
  }
  const LimbLog again = run(4), other = run(5);
  EXPECT_EQ(again.time_s, log.time_s);
  EXPECT_EQ(again.angles_deg, log.angles_deg);
  EXPECT_EQ(again.throttles, log.throttles);
  EXPECT_NE(other.throttles, log.throttles);
}

TEST(OpenLoopInputs, FollowTheThreeTestSignals) {
  const ThrottleSequence sine = open_loop_inputs("sine", 800);
  EXPECT_NEAR(sine(0, 0), 0.0, 1e-12);
  EXPECT_NEAR(sine(0, 1), 10.0, 1e-12);
  EXPECT_NEAR(sine(200, 0), 10.0, 1e-12);  // a quarter circle
  EXPECT_NEAR(sine(200, 1), 0.0, 1e-9);
  const ThrottleSequence square = open_loop_inputs("square", 800);
  EXPECT_EQ(square.row(0), Eigen::RowVector2d(10, 10));
  EXPECT_EQ(square.row(199), Eigen::RowVector2d(10, 10));
  EXPECT_EQ(square.row(200), Eigen::RowVector2d(10, -10));
  EXPECT_EQ(square.row(400), Eigen::RowVector2d(-10, -10));
  EXPECT_EQ(square.row(799), Eigen::RowVector2d(-10, 10));
  const ThrottleSequence saw = open_loop_inputs("sawtooth", 801);
  EXPECT_EQ(saw(0, 0), -10.0);
  EXPECT_NEAR(saw(1, 0) - saw(0, 0), 10 * 0.0025, 1e-12);  // 0.0025 per step, ×10
  EXPECT_EQ(saw(0, 1), -5.0);     // a quarter period ahead: −1 + 2 · 200/800 = −0.5
  EXPECT_EQ(saw(800, 0), -10.0);  // wraps after one period
  EXPECT_THROW(open_loop_inputs("triangle", 10), Error);
  EXPECT_THROW(open_loop_inputs("sine", 10, 10.0, 6), Error);
}

// The drive sends one rounded input per reading, ignores the readings, and logs the reading the
// last input led to; the twin bends towards the throttles' sign.
TEST(DriveOpenLoop, SendsOneRoundedInputPerReadingAndRepeatsWithTheSeed) {
  ThrottleSequence inputs(300, 2);
  for (Eigen::Index k = 0; k < inputs.rows(); ++k) inputs.row(k) << 6.4, -2.6;
  inputs.row(0) << 0.5, -0.5;  // rounds away from zero: 1, −1
  auto env = twin_env("stiff");
  const LimbLog log = drive_open_loop(*env, inputs, 3);
  ASSERT_EQ(log.size(), 301u);
  EXPECT_EQ(log.throttles[0], Eigen::Vector2i(1, -1));
  for (std::size_t k = 1; k < 300; ++k) ASSERT_EQ(log.throttles[k], Eigen::Vector2i(6, -3)) << k;
  EXPECT_EQ(log.throttles[300], Eigen::Vector2i::Zero());
  EXPECT_EQ(log.time_s[0], 0.0);
  for (std::size_t k = 1; k < log.size(); ++k) ASSERT_GT(log.time_s[k], log.time_s[k - 1]);
  // 300 readings of 55–75 ms: about 20 s, long enough for the coils to bend the limb.
  EXPECT_GT(log.angles_deg.back().x(), 10.0);
  EXPECT_LT(log.angles_deg.back().y(), -2.0);
  const LimbCalibration nominal = LimbCalibration::nominal("stiff");
  EXPECT_EQ(log.pwm[5], nominal.pwm_for(6, -3));
  auto again = twin_env("stiff");
  EXPECT_EQ(drive_open_loop(*again, inputs, 3).angles_deg, log.angles_deg);
}

// Fig. 4.2 of the thesis: over the same 10 minutes of robot time, count-based exploration covers
// the 6 × 6 grid more evenly than babbling (evenness: the visit entropy over log 36), both with
// the firmware sketches' 20 s cool-down after the cut-off. On the soft limb, whose babbling hits
// the cut-off often, the margin is large; on the stiff limb it is small and depends on the seed
// (docs/results/sma_limb.md), so only the soft limb is asserted here.
class ExplorationVersusBabbling : public ::testing::TestWithParam<std::string> {};

TEST_P(ExplorationVersusBabbling, ExplorationCoversTheGridMoreEvenly) {
  CollectSettings settings;
  settings.duration_s = 600.0;
  settings.cutoff_cooldown_s = 20.0;
  auto evenness = [&](ThrottleSource& source) {
    auto env = twin_env(GetParam());
    const LimbLog log = collect(*env, source, settings, 21);
    VisitGrid grid;
    for (const Eigen::Vector2d& angles : log.angles_deg) grid.visit(angles);
    return grid.evenness();
  };
  CountBasedExploration exploration;
  MotorBabbling babbling;
  const double explored = evenness(exploration), babbled = evenness(babbling);
  EXPECT_GT(explored, babbled + 0.05) << GetParam() << ": " << explored << " vs " << babbled;
}

INSTANTIATE_TEST_SUITE_P(Limbs, ExplorationVersusBabbling, ::testing::Values("soft"));

}  // namespace
}  // namespace tendril::envs::sma_limb
