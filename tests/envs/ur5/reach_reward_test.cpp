// Each term of UR5/Reach-v0's reward on hand-computed states.
#include "tendril/envs/ur5/reach_reward.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/error_message.hpp"

namespace tendril::envs::ur5 {
namespace {

const Eigen::VectorXd kNoAction = Eigen::VectorXd::Zero(6);

TEST(ReachReward, ProgressPaysTenPerMetreGainedAndChargesTenPerMetreLost) {
  const ReachRewardWeights w;
  EXPECT_NEAR(reach_reward(w, 0.40, 0.37, 0.0, 0.0, kNoAction, false, false).progress, 0.3, 1e-14);
  EXPECT_NEAR(reach_reward(w, 0.37, 0.40, 0.0, 0.0, kNoAction, false, false).progress, -0.3, 1e-14);
}

TEST(ReachReward, ExponentialDistanceTermIsTwoAtTheTargetAndFallsWithSensitivityFour) {
  // 2·exp(−4d): 2 at d = 0, 2/e at d = 0.25 m, 0.8987 at 0.2 m (seed 004 Sec. 3.1.1).
  const ReachRewardWeights w;
  EXPECT_DOUBLE_EQ(reach_reward(w, 0.0, 0.0, 0.0, 0.0, kNoAction, false, false).distance, 2.0);
  EXPECT_DOUBLE_EQ(reach_reward(w, 0.0, 0.25, 0.0, 0.0, kNoAction, false, false).distance,
                   2.0 / std::numbers::e);
  EXPECT_NEAR(reach_reward(w, 0.0, 0.2, 0.0, 0.0, kNoAction, false, false).distance, 0.8987, 1e-4);
}

TEST(ReachReward, OrientationPenaltyIsZeroWhenAlignedAndItsWeightWhenReversed) {
  ReachRewardWeights w;
  const double half_turn = std::numbers::pi;
  EXPECT_DOUBLE_EQ(reach_reward(w, 0, 0, 0.0, 0, kNoAction, false, false).orientation, 0.0);
  EXPECT_DOUBLE_EQ(reach_reward(w, 0, 0, half_turn / 2, 0, kNoAction, false, false).orientation,
                   -0.05);
  EXPECT_DOUBLE_EQ(reach_reward(w, 0, 0, half_turn, 0, kNoAction, false, false).orientation, -0.1);
  w.orientation = 1.0;  // the tuned weight: distance : orientation goes from 20:1 to 2:1
  EXPECT_DOUBLE_EQ(reach_reward(w, 0, 0, half_turn, 0, kNoAction, false, false).orientation, -1.0);
}

TEST(ReachReward, TheBoundedOrientationFormPaysItsWeightWhenAligned) {
  ReachRewardWeights w;
  w.orientation_penalty = false;
  const double half_turn = std::numbers::pi;
  EXPECT_DOUBLE_EQ(reach_reward(w, 0, 0, 0.0, 0, kNoAction, false, false).orientation, 0.1);
  EXPECT_DOUBLE_EQ(reach_reward(w, 0, 0, half_turn / 2, 0, kNoAction, false, false).orientation,
                   0.05);
  EXPECT_DOUBLE_EQ(reach_reward(w, 0, 0, half_turn, 0, kNoAction, false, false).orientation, 0.0);
}

TEST(ReachReward, ActionPenaltyIsLambdaTimesTheSquaredNorm) {
  const ReachRewardWeights w;
  Eigen::VectorXd action(6);
  action << 1.0, -0.5, 0.0, 0.5, 0.0, 0.0;  // ‖a‖² = 1.5
  EXPECT_DOUBLE_EQ(reach_reward(w, 0, 0, 0, 0.05, action, false, false).action, -0.075);
  EXPECT_DOUBLE_EQ(reach_reward(w, 0, 0, 0, 0.01, action, false, false).action, -0.015);
}

TEST(ReachReward, TimeSuccessAndCollisionTerms) {
  const ReachRewardWeights w;
  const ReachRewardTerms plain = reach_reward(w, 0.3, 0.3, 0, 0, kNoAction, false, false);
  EXPECT_DOUBLE_EQ(plain.time, -0.01);
  EXPECT_EQ(plain.success, 0.0);
  EXPECT_EQ(plain.collision, 0.0);
  EXPECT_DOUBLE_EQ(reach_reward(w, 0.3, 0.3, 0, 0, kNoAction, true, false).success, 300.0);
  EXPECT_DOUBLE_EQ(reach_reward(w, 0.3, 0.3, 0, 0, kNoAction, false, true).collision, -10.0);
}

TEST(ReachReward, TotalIsTheSumAndZeroWeightsSwitchTermsOff) {
  // The seed's base model: progress only (and the fixed time, success and collision terms).
  ReachRewardWeights w;
  w.distance = 0.0;
  w.orientation = 0.0;
  Eigen::VectorXd action = Eigen::VectorXd::Constant(6, 0.5);
  const ReachRewardTerms t = reach_reward(w, 0.5, 0.45, 0.2, 0.0, action, false, false);
  EXPECT_DOUBLE_EQ(t.distance, 0.0);
  EXPECT_DOUBLE_EQ(t.orientation, 0.0);
  EXPECT_DOUBLE_EQ(t.action, 0.0);
  EXPECT_DOUBLE_EQ(t.total(), 0.5 - 0.01);
}

TEST(ReachReward, WeightsAreReadFromParamsAndNegativeOnesRejected) {
  const Config params = Config::parse(
      "{progress_weight: 5, distance_weight: 0, orientation_weight: 1.0, success_bonus: 50, "
      "orientation_form: bounded}");
  const ReachRewardWeights w = ReachRewardWeights::from_config(params);
  EXPECT_EQ(w.progress, 5.0);
  EXPECT_EQ(w.distance, 0.0);
  EXPECT_EQ(w.orientation, 1.0);
  EXPECT_EQ(w.success, 50.0);
  EXPECT_EQ(w.collision, 10.0);
  EXPECT_FALSE(w.orientation_penalty);
  EXPECT_TRUE(ReachRewardWeights::from_config(Config::parse("{}")).orientation_penalty);
  const Config unknown_form = Config::parse("{orientation_form: cosine}", "exp.yaml");
  EXPECT_NE(testing::error_message([&] {
              ReachRewardWeights::from_config(unknown_form);
            }).find("orientation_form"),
            std::string::npos);
  const Config bad = Config::parse("{time_penalty: -1}", "exp.yaml");
  EXPECT_NE(
      testing::error_message([&] { ReachRewardWeights::from_config(bad); }).find("time_penalty"),
      std::string::npos);
}

}  // namespace
}  // namespace tendril::envs::ur5
