#include "tendril/adapt/oracle_rollout.hpp"

#include <gtest/gtest.h>

#include "scripted_reaching_robot.hpp"

namespace tendril::adapt {
namespace {

using testing::LinearArm;
using testing::ProportionalPolicy;
using testing::ScriptedReachingRobot;

const Eigen::Vector3d kGoal{9.0, -15.2, -598.7};

TEST(OracleRollout, RunsThePolicyUntilTheGoalAndRecordsEveryStep) {
  ScriptedReachingRobot robot(LinearArm{}, Eigen::Vector3d::Zero(), kGoal);
  const ProportionalPolicy policy(LinearArm{}, kGoal, 0.5);
  const OracleEpisode episode = run_oracle(robot, policy, 50, 0);
  const int steps = static_cast<int>(episode.statuses.size());
  ASSERT_GT(steps, 1);
  EXPECT_LT(steps, 50);  // the goal ends it
  EXPECT_TRUE(episode.statuses.back().success);
  EXPECT_EQ(episode.states.rows(), steps + 1);
  EXPECT_EQ(episode.commands.rows(), steps);
  // The matched robot settles in one step, so each state is the map of the command before it.
  for (int t = 0; t < steps; ++t) {
    const Eigen::Vector3d command = episode.commands.row(t).transpose();
    EXPECT_LT((episode.states.row(t + 1).transpose() - LinearArm{}.at(command)).norm(), 1e-9);
  }
  // The step limit.
  EXPECT_EQ(run_oracle(robot, policy, 2, 0).statuses.size(), 2u);
  std::vector<AdaptationStep> logged;
  log_oracle_episode(episode, 4, logged);
  ASSERT_EQ(static_cast<int>(logged.size()), steps);
  EXPECT_EQ(logged.front().trial, 4);
  EXPECT_EQ(logged.back().state, episode.states.bottomRows<1>().transpose());
}

// Eq. (2) summed over the steps with the goal's accuracy reduced to the radius.
TEST(OracleRollout, TheReducedAccuracyReturnIsEquationTwoSummed) {
  std::vector<ReachStatus> statuses(4);
  statuses[0].goal_distance = 40.0;  // −2 − 40
  statuses[0].obstacle_distance = 50.0;
  statuses[1].goal_distance = 12.0;  // within 15: −2 only, and the band 10 < O ≤ 20: −5·4
  statuses[1].obstacle_distance = 16.0;
  statuses[2].goal_distance = 14.0;  // −2, outside the boundary −100
  statuses[2].obstacle_distance = 30.0;
  statuses[2].outside = true;
  statuses[3].goal_distance = 30.0;  // −2 − 30 − 10000
  statuses[3].obstacle_distance = 5.0;
  statuses[3].collision = true;
  EXPECT_DOUBLE_EQ(reduced_accuracy_return(statuses, 15.0), -42.0 - 22.0 - 102.0 - 10032.0);
  // At 5 mm accuracy the two near steps pay their distance too.
  EXPECT_DOUBLE_EQ(reduced_accuracy_return(statuses, 5.0), -42.0 - 34.0 - 116.0 - 10032.0);
}

}  // namespace
}  // namespace tendril::adapt
