#include "tendril/dynamics/open_loop.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"
#include "test_models.hpp"

namespace tendril::dynamics {
namespace {

TEST(OpenLoop, InputsFollowTheThreeTestSignals) {
  const RowMatrixXd sine = open_loop_inputs("sine", 800);
  EXPECT_NEAR(sine(0, 0), 0.0, 1e-12);
  EXPECT_NEAR(sine(0, 1), 10.0, 1e-12);
  EXPECT_NEAR(sine(200, 0), 10.0, 1e-12);  // a quarter circle
  EXPECT_NEAR(sine(200, 1), 0.0, 1e-9);
  const RowMatrixXd square = open_loop_inputs("square", 800);
  EXPECT_EQ(square.row(0), Eigen::RowVector2d(10, 10));
  EXPECT_EQ(square.row(199), Eigen::RowVector2d(10, 10));
  EXPECT_EQ(square.row(200), Eigen::RowVector2d(10, -10));
  EXPECT_EQ(square.row(400), Eigen::RowVector2d(-10, -10));
  EXPECT_EQ(square.row(799), Eigen::RowVector2d(-10, 10));
  const RowMatrixXd saw = open_loop_inputs("sawtooth", 801);
  EXPECT_EQ(saw(0, 0), -10.0);
  EXPECT_NEAR(saw(1, 0) - saw(0, 0), 10 * 0.0025, 1e-12);  // 0.0025 per step, ×10
  EXPECT_EQ(saw(0, 1), -5.0);     // a quarter period ahead: −1 + 2 · 200/800 = −0.5
  EXPECT_EQ(saw(800, 0), -10.0);  // wraps after one period
  EXPECT_THROW(open_loop_inputs("triangle", 10), Error);
}

TEST(OpenLoop, RolloutStartsAtRestAndAppliesEachInput) {
  Model model(testing::small_description(Architecture::kSeq2Seq), 4);
  const RowMatrixXd inputs = open_loop_inputs("square", 12);
  const Eigen::Vector4d start(5, -5, 0, 0);
  const RowMatrixXd trajectory = open_loop_rollout(model, start, inputs);
  ASSERT_EQ(trajectory.rows(), 13);
  EXPECT_EQ(trajectory.row(0), start.transpose());
  // The first prediction reads the rest window with the first input.
  envs::HistoryWindows windows(1, model.window_length(), 4, 2);
  windows.reset(0, start.cast<float>());
  windows.set_input(0, inputs.row(0).transpose().cast<float>());
  envs::BatchMatrix next;
  model.predict(windows.windows(), next);
  EXPECT_EQ(trajectory.row(1), next.row(0).cast<double>());
}

}  // namespace
}  // namespace tendril::dynamics
