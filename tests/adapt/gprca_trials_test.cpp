// GPRCA's trials on a robot (seed 002 Alg. 2) against a scripted robot whose dynamics are its
// model's plus a constant bias: the compensator learns the model's one-step error, so the policy
// sees the model's prediction (eq. (5): s = x + c, c → e = x̂ − x).
#include "tendril/adapt/gprca_trials.hpp"

#include <gtest/gtest.h>

#include "scripted_reaching_robot.hpp"
#include "tendril/core/error.hpp"

namespace tendril::adapt {
namespace {

using testing::LinearArm;
using testing::ProportionalPolicy;
using testing::ScriptedHistoryModel;
using testing::ScriptedReachingRobot;

const Eigen::Vector3d kBias{12.0, -8.0, 4.0};  // |b| = 15 mm
const Eigen::Vector3d kGoal{9.0, -15.2, -598.7};
constexpr double kLag = 0.5;

GprcaTrialsOptions options(int max_trials) {
  GprcaTrialsOptions options;
  options.max_trials = max_trials;
  options.steps_per_trial = 40;
  return options;
}

// With x_{t+1} = x_t + α (rest + b + B a − x_t) and the model's x̂_{t+1} = x_t + α (rest + B a −
// x_t), the motor error is e = −α b on every step: once trained, c = −α b and the policy sees s_t =
// x_t − α b, the model's prediction of x_t.
TEST(GprcaTrials, TheCompensationBecomesTheModelsOneStepErrorAndThePolicySeesItsPrediction) {
  ScriptedReachingRobot robot(LinearArm{}, kBias, kGoal, 0.0, kLag);
  ScriptedHistoryModel model(LinearArm{}, kLag);
  const ProportionalPolicy policy(LinearArm{}, kGoal, 0.5);
  const AdaptationResult result = run_gprca(robot, model, policy, options(3), 3);
  // Hiding the error from a proportional policy does not bring the robot to the goal: it
  // settles at g + b (1 + kα)/(1 + k), 12.5 mm away; every trial runs its full length.
  EXPECT_FALSE(result.goal_flag);
  ASSERT_EQ(result.trials.size(), 3u);
  EXPECT_EQ(result.trials_to_goal, 3);
  for (const AdaptationTrial& trial : result.trials) {
    EXPECT_EQ(trial.phase, "gprca");
    EXPECT_EQ(trial.steps, 40);
  }
  EXPECT_NEAR(result.trials.back().final_goal_distance, kBias.norm() * 1.25 / 1.5, 1e-3);
  const Eigen::Vector3d error = -kLag * kBias;
  for (std::size_t i = 41; i < result.steps.size(); ++i) {  // trials 2 and 3
    if (result.steps[i].step == 0) continue;                // c_0 = 0 at a trial's start
    const Eigen::Vector3d seen = result.steps[i].reference - result.steps[i - 1].state;
    EXPECT_LT((seen - error).norm(), 1e-6 * error.norm()) << i;
  }
  EXPECT_EQ(model.follows(), 120);
  EXPECT_EQ(model.resets(), 3);
  EXPECT_EQ(robot.resets(), 3);
}

TEST(GprcaTrials, AMatchedRobotReachesTheGoalAndTrialsAfterTheGoalRun) {
  ScriptedReachingRobot robot(LinearArm{}, Eigen::Vector3d::Zero(), kGoal, 0.0, kLag);
  ScriptedHistoryModel model(LinearArm{}, kLag);
  const ProportionalPolicy policy(LinearArm{}, kGoal, 0.5);
  GprcaTrialsOptions more = options(5);
  more.trials_after_goal = 2;
  const AdaptationResult result = run_gprca(robot, model, policy, more, 1);
  ASSERT_TRUE(result.goal_flag);
  EXPECT_EQ(result.trials_to_goal, 1);
  ASSERT_EQ(result.trials.size(), 3u);
  for (const AdaptationTrial& trial : result.trials) {
    EXPECT_TRUE(trial.success);
    EXPECT_LT(trial.steps, 40);  // ends at the goal
    EXPECT_LE(trial.final_goal_distance, 5.98);
  }
  // The model matches, so the error and the compensation stay (numerically) zero.
  for (const AdaptationStep& step : result.steps) {
    EXPECT_LT(step.update_seconds, 1.0);
    EXPECT_EQ(step.command.size(), 3);
  }
}

TEST(GprcaTrials, SameSeedSameTrialsAndBadOptionsAreRefused) {
  std::vector<AdaptationResult> runs;
  for (int run = 0; run < 2; ++run) {
    ScriptedReachingRobot robot(LinearArm{}, kBias, kGoal, /*rest_jitter=*/2.0, kLag);
    ScriptedHistoryModel model(LinearArm{}, kLag);
    const ProportionalPolicy policy(LinearArm{}, kGoal, 0.5);
    runs.push_back(run_gprca(robot, model, policy, options(2), 7));
  }
  ASSERT_EQ(runs[0].steps.size(), runs[1].steps.size());
  for (std::size_t i = 0; i < runs[0].steps.size(); ++i) {
    EXPECT_EQ(runs[0].steps[i].state, runs[1].steps[i].state);
    EXPECT_EQ(runs[0].steps[i].reference, runs[1].steps[i].reference);
  }
  ScriptedReachingRobot robot(LinearArm{}, kBias, kGoal);
  ScriptedHistoryModel model(LinearArm{});
  const ProportionalPolicy policy(LinearArm{}, kGoal, 0.5);
  GprcaTrialsOptions bad = options(3);
  bad.max_trials = 0;
  EXPECT_THROW(run_gprca(robot, model, policy, bad, 0), Error);
  bad = options(3);
  bad.compensator.retrain_every = 0;
  EXPECT_THROW(run_gprca(robot, model, policy, bad, 0), Error);
}

}  // namespace
}  // namespace tendril::adapt
