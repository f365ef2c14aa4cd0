#include "tendril/dynamics/open_loop.hpp"

#include <gtest/gtest.h>

#include "tendril/envs/sma_limb/open_loop_inputs.hpp"
#include "test_models.hpp"

namespace tendril::dynamics {
namespace {

TEST(OpenLoop, RolloutStartsAtRestAndAppliesEachInput) {
  Model model(testing::small_description(Architecture::kSeq2Seq), 4);
  const RowMatrixXd inputs = envs::sma_limb::open_loop_inputs("square", 12);
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
