// BOAC (seed 002 Alg. 1) against a scripted robot whose map is its model's plus a bias: the
// oracle's proportional policy misses on the robot; the GP student coached along the model's
// paths reaches the goal, profile after profile.
#include "tendril/adapt/boac.hpp"

#include <gtest/gtest.h>

#include "scripted_reaching_robot.hpp"
#include "tendril/core/error.hpp"

namespace tendril::adapt {
namespace {

using testing::LinearArm;
using testing::ProportionalPolicy;
using testing::ScriptedReachingRobot;

const Eigen::Vector3d kBias{12.0, -8.0, 4.0};
const Eigen::Vector3d kGoal{9.0, -15.2, -598.7};

BoacOptions small_options() {
  BoacOptions options;
  options.oracle_trials = 4;
  options.best_trials = 3;
  options.oracle_steps = 30;
  options.coach_episodes = 6;
  options.hold_steps = 3;
  options.max_trials_per_profile = 6;
  options.max_trials = 15;
  return options;
}

struct BoacRun {
  AdaptationResult result;
  int robot_resets = 0, model_resets = 0;
};

BoacRun run(const BoacOptions& options, uint64_t seed) {
  ScriptedReachingRobot robot(LinearArm{}, kBias, kGoal);
  ScriptedReachingRobot model(LinearArm{}, Eigen::Vector3d::Zero(), kGoal, /*rest_jitter=*/3.0);
  const ProportionalPolicy oracle(LinearArm{}, kGoal, 0.5);
  BoacRun out;
  out.result = run_boac(robot, model, oracle, options, seed);
  out.robot_resets = robot.resets();
  out.model_resets = model.resets();
  return out;
}

TEST(Boac, TheCoachRaisesTheAccuracyProfileByProfileUntilTheGoal) {
  const BoacRun boac = run(small_options(), 2);
  const AdaptationResult& result = boac.result;
  ASSERT_TRUE(result.goal_flag);
  // The oracle's four trials on the robot come first; each misses by about |b| / 1.5.
  for (int n = 0; n < 4; ++n) {
    EXPECT_EQ(result.trials[n].phase, "oracle");
    EXPECT_NEAR(result.trials[n].final_goal_distance, kBias.norm() / 1.5, 0.5);
  }
  // Then coaching trials whose profiles only ever tighten: 15 → 10 → 5 mm, until a trial ends
  // at the goal.
  const std::vector<std::string> order{"coach 15 mm", "coach 10 mm", "coach 5 mm"};
  std::size_t profile = 0;
  for (std::size_t i = 4; i < result.trials.size(); ++i) {
    while (profile < order.size() && result.trials[i].phase != order[profile]) ++profile;
    ASSERT_LT(profile, order.size()) << "trial " << i << " is " << result.trials[i].phase;
  }
  EXPECT_EQ(result.trials[4].phase, "coach 15 mm");
  // A profile is left on its local flag (its last trial ended within 5 mm of the coach path's
  // end) or when its 6 trials are spent.
  int in_profile = 0;
  for (std::size_t i = 4; i + 1 < result.trials.size(); ++i) {
    ++in_profile;
    if (result.trials[i].phase != result.trials[i + 1].phase) {
      EXPECT_TRUE(result.trials[i].coach_end_distance <= 5.0 || in_profile == 6) << i;
      in_profile = 0;
    }
  }
  EXPECT_LE(result.trials.back().final_goal_distance, 5.98);
  EXPECT_EQ(result.trials_to_goal, static_cast<int>(result.trials.size()) - 4);
  EXPECT_EQ(boac.robot_resets, static_cast<int>(result.trials.size()));
  EXPECT_EQ(boac.model_resets, 6);
  // Coaching trials are the coach path's length plus the hold.
  for (std::size_t i = 4; i < result.trials.size(); ++i) EXPECT_GE(result.trials[i].steps, 4);
}

TEST(Boac, SameSeedSameRunAndBadOptionsAreRefused) {
  const BoacRun a = run(small_options(), 5), b = run(small_options(), 5);
  ASSERT_EQ(a.result.steps.size(), b.result.steps.size());
  for (std::size_t i = 0; i < a.result.steps.size(); ++i) {
    EXPECT_EQ(a.result.steps[i].command, b.result.steps[i].command);
    EXPECT_EQ(a.result.steps[i].reference, b.result.steps[i].reference);
  }
  BoacOptions bad = small_options();
  bad.best_trials = 5;  // more than the oracle's 4
  EXPECT_THROW(run(bad, 0), Error);
  bad = small_options();
  bad.profiles.clear();
  EXPECT_THROW(run(bad, 0), Error);
}

}  // namespace
}  // namespace tendril::adapt
