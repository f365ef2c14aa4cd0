#include "tendril/dynamics/env_model_loader.hpp"

#include <gtest/gtest.h>

#include "support/scratch_directory.hpp"
#include "tendril/core/error.hpp"
#include "tendril/dynamics/model.hpp"
#include "tendril/dynamics/model_file.hpp"
#include "tendril/envs/registry.hpp"
#include "test_models.hpp"

namespace tendril::dynamics {
namespace {

class EnvModelLoader : public testing::ScratchDirectoryTest {
 protected:
  EnvModelLoader() : ScratchDirectoryTest("env_model_loader") {}
};

// SmaLimb/LearnedReach-v0 opened on a run directory steps through the saved model: its first
// prediction from the start window equals the model's own.
TEST_F(EnvModelLoader, TheReachingTaskStepsThroughASavedModel) {
  Model model(testing::small_description(Architecture::kLstm, /*window=*/6), 3);
  save_model(model, directory_ / kModelFileName);
  install_model_loader();
  auto env = envs::make("SmaLimb/LearnedReach-v0",
                        Config::parse("model: " + directory_.string() + "\nseed: 4"));
  const Observation start = env->reset(4);
  envs::BatchMatrix window(1, 6 * 6);
  for (int k = 0; k < 6; ++k) {
    window.row(0).segment(k * 6, 4) = start.head<4>().transpose();
    window.row(0).segment(k * 6 + 4, 2).setZero();
  }
  window.row(0).tail<2>() << 3.0f, -2.0f;
  envs::BatchMatrix expected;
  model.predict(window, expected);
  const Step step = env->step(Eigen::Vector2f(3, -2));
  for (int i = 0; i < 4; ++i) EXPECT_EQ(step.observation[i], expected(0, i)) << i;
  EXPECT_THROW(envs::make("SmaLimb/LearnedReach-v0",
                          Config::parse("model: " + (directory_ / "missing").string())),
               Error);
}

}  // namespace
}  // namespace tendril::dynamics
