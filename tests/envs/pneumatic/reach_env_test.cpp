#include "tendril/envs/pneumatic/reach_env.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/error_message.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::envs::pneumatic {
namespace {

using testing::error_message;

// PneumaticArm/Reach-v0 on the deterministic twin, without the registry's time limit.
std::unique_ptr<Env> reach(const std::string& yaml = "") {
  return ReachEnv::create_on_robot(
      Config::parse("robot: {stochastic: false}\n" + yaml, "reach.yaml"));
}

ReachEnv& as_reach(Env& env) { return dynamic_cast<ReachEnv&>(env); }

Action delta_on(int chamber, float value) {
  Action action = Action::Zero(9);
  action[chamber] = value;
  return action;
}

TEST(ReachEnv, DeltasAccumulateIntoACappedCommand) {
  const auto env = reach();
  EXPECT_EQ(env->action_space().describe(), "Box(9, [-0.2, 0.2])");
  EXPECT_EQ(env->observation_space().size(), 11);
  env->reset(0);
  ReachEnv& task = as_reach(*env);
  EXPECT_EQ(task.command(), ChamberVector::Constant(-1.0));  // all vented
  for (int t = 1; t <= 12; ++t) {
    env->step(delta_on(4, 0.2f));
    // −1 + 0.2 t, capped at 1 (the 1.5 bar ceiling) after ten steps.
    EXPECT_NEAR(task.command()[4], std::min(1.0, -1.0 + 0.2 * t), 1e-6) << t;
  }
  env->step(delta_on(4, -0.2f));
  EXPECT_NEAR(task.command()[4], 0.8, 1e-6);
  EXPECT_EQ(ReachEnv::pressure_of(-1.0), 0.0);
  EXPECT_EQ(ReachEnv::pressure_of(1.0), 1.5);
}

// Seed 002 §IV-A3: a change beyond the 0.15 bar safety threshold is not taken, and the usual
// penalty applies. With a 0.075 bar limit (0.1 normalised), a 0.15 delta is refused.
TEST(ReachEnv, DeltasBeyondTheRateLimitAreNotTaken) {
  const auto env = reach("rate_limit_bar: 0.075\n");
  env->reset(0);
  Step step = env->step(delta_on(0, 0.15f));
  EXPECT_EQ(as_reach(*env).command()[0], -1.0);
  EXPECT_EQ(*step.info.get("rate_limited"), 1.0);
  EXPECT_LE(step.reward, -2.0);
  step = env->step(delta_on(0, 0.1f));
  EXPECT_NEAR(as_reach(*env).command()[0], -0.9, 1e-6);
  EXPECT_EQ(*step.info.get("rate_limited"), 0.0);
}

// An absolute command (BOAC's student) is held with its change scaled down as a whole to the rate
// limit, and observation_of(tips) is the observation a step ending at those tips returns.
TEST(ReachEnv, AbsoluteCommandsAreRateLimitedAndObservationsFollowTheTips) {
  // A limit of 0.09375 bar (0.125 normalised).
  const auto env = reach("observe_command: true\nrate_limit_bar: 0.09375\n");
  const auto same = reach("observe_command: true\nrate_limit_bar: 0.09375\n");
  env->reset(0);
  same->reset(0);
  ReachEnv& task = as_reach(*env);
  ChamberVector wanted = ChamberVector::Constant(-1.0);
  wanted[2] = 0.5;    // 1.5 above the held −1
  wanted[5] = -0.25;  // 0.75 above: the change keeps its direction, scaled by 0.125 / 1.5
  Step step = task.step_command(wanted);
  EXPECT_NEAR(task.command()[2], -0.875, 1e-15);
  EXPECT_NEAR(task.command()[5], -0.9375, 1e-15);
  EXPECT_EQ(task.command()[0], -1.0);
  EXPECT_EQ(*step.info.get("rate_limited"), 1.0);
  // The same command as deltas through step() gives the same arm.
  Action delta = Action::Zero(9);
  delta[2] = 0.125f;
  delta[5] = 0.0625f;
  const Step by_delta = same->step(delta);
  EXPECT_LT((as_reach(*same).tips() - task.tips()).norm(), 1e-9);
  EXPECT_EQ(task.observation_of(task.tips()), step.observation);
  EXPECT_LT((by_delta.observation.head(11) - step.observation.head(11)).norm(), 1e-5);
  // Within the limit a command is taken as it is; beyond [−1, 1] it is capped first.
  wanted = task.command();
  wanted[5] = -0.9;
  wanted[7] = -3.0;
  step = task.step_command(wanted);
  EXPECT_EQ(task.command()[5], -0.9);
  EXPECT_EQ(task.command()[7], -1.0);
  EXPECT_EQ(*step.info.get("rate_limited"), 0.0);
  // Other tips: their own distances, the held command.
  TipVector elsewhere = task.tips();
  elsewhere.tail<3>() = Eigen::Vector3d(-30.0, -120.0, -620.0);  // the main goal
  const Observation at_goal = task.observation_of(elsewhere);
  EXPECT_FLOAT_EQ(at_goal[9], -1.0f);  // G = 0 → 2·0/300 − 1
  EXPECT_EQ(at_goal.tail(9), step.observation.tail(9));
  ChamberVector bad = wanted;
  bad[0] = NAN;
  EXPECT_THROW(task.step_command(bad), Error);
}

// The observation is the tips normalised per coordinate by the configured bounds, then
// 2 G/scale − 1 and 2 O/scale − 1; the reward is eq. (2) at module 3's tip.
TEST(ReachEnv, ObservesNormalisedTipsAndDistancesAndRewardsEquationTwo) {
  const auto env = reach(
      "normalization: {tip_min_mm: [-10, -10, -210, -20, -20, -410, -30, -30, -610],\n"
      "                tip_max_mm: [10, 10, -190, 20, 20, -390, 30, 30, -590],\n"
      "                distance_scale_mm: 200}\n");
  env->reset(0);
  ReachEnv& task = as_reach(*env);
  Eigen::Vector3d previous = task.tips().tail<3>();
  for (int t = 0; t < 6; ++t) {
    const Step step = env->step(delta_on(3 * (t % 3), 0.2f));
    const TipVector& tips = task.tips();
    const ReachOutcome expected = evaluate_reach_step(task.task(), previous, tips.tail<3>());
    previous = tips.tail<3>();
    EXPECT_DOUBLE_EQ(step.reward, expected.reward);
    EXPECT_NEAR(step.observation[6], 2.0 * (tips[6] + 30.0) / 60.0 - 1.0, 1e-5);
    EXPECT_NEAR(step.observation[8], 2.0 * (tips[8] + 610.0) / 20.0 - 1.0, 1e-5);
    EXPECT_NEAR(step.observation[9], 2.0 * expected.goal_distance / 200.0 - 1.0, 1e-6);
    EXPECT_NEAR(step.observation[10], 2.0 * expected.obstacle_distance / 200.0 - 1.0, 1e-6);
    EXPECT_NEAR(*step.info.get("distance"), 1e-3 * expected.goal_distance, 1e-12);
  }
  EXPECT_EQ(reach("observe_command: true\n")->observation_space().size(), 20);
}

// Bending toward −y drives module 3's tip into the plate at y = −50: the episode ends with a
// collision (the plate is crossed or approached within 10 mm) and its −10000.
TEST(ReachEnv, DrivingIntoThePlateIsACollision) {
  const auto env = reach();
  env->reset(0);
  // Chambers 2 (120°) and 1 (0°) of each module at 2 : 1 bend the arm toward 270°, i.e. −y.
  Action toward_minus_y = Action::Zero(9);
  for (int m = 0; m < 3; ++m) {
    toward_minus_y[3 * m] = 0.1f;
    toward_minus_y[3 * m + 1] = 0.2f;
  }
  Step step;
  int steps = 0;
  do {
    step = env->step(toward_minus_y);
    ++steps;
  } while (!step.terminated && steps < 100);
  ASSERT_TRUE(step.terminated);
  EXPECT_EQ(*step.info.get("collision"), 1.0);
  EXPECT_EQ(*step.info.get("is_success"), 0.0);
  EXPECT_LT(step.reward, -10000.0);
}

TEST(ReachEnv, ReachingTheGoalOrLeavingTheBoundaryEndsTheEpisode) {
  // A goal at the rest position of module 3's tip is reached on the first step.
  const auto at_rest = reach("goal_mm: [0, 0, -598.8]\n");
  at_rest->reset(0);
  const Step reached = at_rest->step(Action::Zero(9));
  EXPECT_TRUE(reached.terminated);
  EXPECT_EQ(*reached.info.get("is_success"), 1.0);
  EXPECT_EQ(reached.reward, -2.0);

  const auto tight = reach("boundary_min_mm: [-5, -5, -610]\nboundary_max_mm: [5, 5, -590]\n");
  tight->reset(0);
  Step step;
  for (int t = 0; t < 20 && !step.terminated; ++t) step = tight->step(delta_on(0, 0.2f));
  ASSERT_TRUE(step.terminated);
  EXPECT_EQ(*step.info.get("outside_boundary"), 1.0);
  EXPECT_LT(step.reward, -102.0);
}

TEST(ReachEnv, DescribesTheArmGoalPlateAndBoundary) {
  const auto env = reach("task: G3\n");
  env->reset(0);
  Scene scene;
  ASSERT_TRUE(env->describe_scene(scene));
  EXPECT_EQ(scene.rods.size(), 1u);
  ASSERT_EQ(scene.boxes.size(), 2u);
  EXPECT_EQ(scene.boxes[0].role, "obstacle");
  EXPECT_NEAR(scene.boxes[0].centre.z(), -0.635, 1e-12);
  EXPECT_EQ(scene.boxes[1].role, "boundary");
  const auto goal = std::find_if(scene.spheres.begin(), scene.spheres.end(),
                                 [](const Scene::Sphere& s) { return s.role == "goal"; });
  ASSERT_NE(goal, scene.spheres.end());
  EXPECT_TRUE(goal->centre.isApprox(Eigen::Vector3d(-0.045, -0.1, -0.645)));
}

TEST(ReachEnv, BadParametersAreNamed) {
  EXPECT_NE(error_message([] { reach("task: G4\n"); }).find("reach.yaml: task"), std::string::npos);
  EXPECT_NE(error_message([] { reach("goal_mm: [1, 2]\n"); }).find("goal_mm"), std::string::npos);
  EXPECT_NE(error_message([] { reach("boundary: wide\n"); }).find("boundary"), std::string::npos);
  EXPECT_NE(error_message([] {
              reach(
                  "normalization: {tip_min_mm: [0, 0, 0, 0, 0, 0, 0, 0, 0],\n"
                  "                tip_max_mm: [0, 0, 0, 0, 0, 0, 0, 0, 0]}\n");
            }).find("normalization"),
            std::string::npos);
  EXPECT_NE(error_message([] {
              make(ReachEnv::kRobotId, Config::parse("robot: {scenari: S1}\n"));
            }).find("robot.scenari"),
            std::string::npos);
  const auto env = reach();
  env->reset(0);
  EXPECT_THROW(env->step(Action::Zero(3)), Error);
}

}  // namespace
}  // namespace tendril::envs::pneumatic
