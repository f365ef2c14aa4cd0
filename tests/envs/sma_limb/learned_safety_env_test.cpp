#include "tendril/envs/sma_limb/learned_safety_env.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/sma_limb/linear_limb_model.hpp"

namespace tendril::envs::sma_limb {
namespace {

// The linear stand-in, remembering the throttles of its last prediction.
class RecordingModel : public DynamicsModel {
 public:
  int state_dim() const override { return 4; }
  int input_dim() const override { return 2; }
  int window_length() const override { return inner_.window_length(); }
  double sample_period() const override { return inner_.sample_period(); }
  void predict(const BatchMatrix& windows, BatchMatrix& next_states) override {
    inputs = windows.rightCols(2);
    inner_.predict(windows, next_states);
  }
  BatchMatrix inputs;

 private:
  LinearLimbModel inner_;
};

TEST(LearnedSafetyEnv, MovesAreTheFourDiagonalsAtFullThrottle) {
  // u1 upper right, u2 upper left, u3 lower left, u4 lower right (thesis Fig. 3.1).
  EXPECT_EQ(LearnedSafetyEnv::throttles(0), Eigen::Vector2d(10, 10));
  EXPECT_EQ(LearnedSafetyEnv::throttles(1), Eigen::Vector2d(-10, 10));
  EXPECT_EQ(LearnedSafetyEnv::throttles(2), Eigen::Vector2d(-10, -10));
  EXPECT_EQ(LearnedSafetyEnv::throttles(3), Eigen::Vector2d(10, -10));
  EXPECT_THROW(LearnedSafetyEnv::throttles(4), Error);
  auto model = std::make_shared<RecordingModel>();
  LearnedSafetyEnv env(model, {}, 0);
  env.reset(3);
  env.step(Action::Constant(1, 1.0f));
  EXPECT_FLOAT_EQ(model->inputs(0, 0), -10.0f);
  EXPECT_FLOAT_EQ(model->inputs(0, 1), 10.0f);
}

TEST(LearnedSafetyEnv, StartsInsideTheDiscAndEndsWhenLeavingIt) {
  LearnedSafetyEnv env(std::make_shared<LinearLimbModel>(), {}, 0);
  for (uint64_t seed = 0; seed < 50; ++seed) {
    const Observation x = env.reset(seed);
    EXPECT_LT(std::hypot(x[0], x[1]), 30.0f);
    EXPECT_LE(std::abs(x[2]), 30.0f);
    EXPECT_EQ(x[4], 0.0f);
  }
  // From rest at (25°, 0) full throttle up-right bends past 30° (the stand-in settles at 90°).
  env.set_state(Eigen::Vector4d(25.0, 0.0, 0.0, 0.0));
  Step step;
  int steps = 0;
  do {
    step = env.step(Action::Constant(1, 0.0f));
    ++steps;
    EXPECT_NEAR(step.observation[4], steps / 500.0, 1e-6);
  } while (!step.terminated && steps < 100);
  ASSERT_TRUE(step.terminated);
  EXPECT_EQ(*step.info.get("unsafe"), 1.0);
  EXPECT_EQ(*step.info.get("cost"), 1.0);
  EXPECT_LE(*step.info.get("safety_margin"), 0.0);
  EXPECT_NEAR(*step.info.get("safety_margin"),
              30.0 - std::hypot(step.observation[0], step.observation[1]), 1e-4);
}

TEST(LearnedSafetyEnv, KeepsGoingWhenToldAndTruncatesAtTheHorizon) {
  auto env = make("SmaLimb/LearnedSafety-v0",
                  Config::parse("terminate_on_unsafe: false\nhorizon: 40\nvelocity_limit: 1000"));
  env->reset(1);
  Step step;
  for (int k = 0; k < 40; ++k) {
    ASSERT_FALSE(step.terminated || step.truncated) << k;
    step = env->step(Action::Constant(1, 0.0f));
  }
  EXPECT_TRUE(step.truncated);
  EXPECT_EQ(*step.info.get("unsafe"), 1.0);  // it left the disc and went on
  EXPECT_THROW(make("SmaLimb/LearnedSafety-v0", Config::parse("safe_radius: 0")), Error);
  EXPECT_THROW(make("SmaLimb/LearnedSafety-v0", Config::parse("safe_radus: 20")), Error);
}

}  // namespace
}  // namespace tendril::envs::sma_limb
