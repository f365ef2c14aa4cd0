// UR5/Reach-v0: spaces, action scaling and limits, collisions, reward terms in the running
// environment, the λ_u schedule, success and termination, errors, reproducibility, and the
// scene's promise that the box hides every target from the straight path.
#include "tendril/envs/ur5/ur5_reach.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/error_message.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::envs::ur5 {
namespace {

using testing::error_message;
using Joints = physics::Ur5Arm::Joints;

Joints home() { return Ur5Reach::Params{}.home; }

Action constant_action(float value) { return Action::Constant(6, value); }

// Parameters with every reward term off but the ones a test sets.
Ur5Reach::Params silent_reward() {
  Ur5Reach::Params params;
  params.reward = {0, 0, 4.0, 0, 0, 0, 0};
  params.action_penalty = StepSchedule::constant(0.0);
  return params;
}

TEST(Ur5Reach, SpacesAreNineteenObservationsAndSixBoundedDeltas) {
  Ur5Reach env;
  EXPECT_EQ(env.observation_space().size(), 19);
  EXPECT_EQ(env.action_space().describe(), "Box(6, [-1, 1])");
  const Observation observation = env.reset(4);
  // q, q̇ (at rest), flange, target, collision flag.
  EXPECT_TRUE(observation.segment<6>(0).isApprox(env.arm().joint_positions().cast<float>()));
  EXPECT_EQ(observation.segment<6>(6), Eigen::VectorXf::Zero(6));
  EXPECT_TRUE(observation.segment<3>(12).isApprox(env.arm().flange_position().cast<float>()));
  EXPECT_TRUE(observation.segment<3>(15).isApprox(env.target().cast<float>()));
  EXPECT_EQ(observation[18], 0.0f);
  EXPECT_EQ(
      make("UR5/Reach-v0", Config::parse("{action_space: unbounded}"))->action_space().bounded(),
      false);
}

TEST(Ur5Reach, AnActionMovesEachServoTargetByFivePercentOfARadianPerUnit) {
  Ur5Reach env;
  env.plant(home(), Eigen::Vector3d(0.6, 0.0, 0.2));
  Action action(6);
  action << 1.0f, -1.0f, 0.5f, -0.5f, 0.2f, 0.0f;
  env.step(action);
  // The targets are the angles before the step plus 0.05·a.
  const Joints expected = home() + 0.05 * action.cast<double>();
  EXPECT_LT((env.arm().targets() - expected).cwiseAbs().maxCoeff(), 1e-6);  // float action
}

TEST(Ur5Reach, ActionsBeyondOneSaturateAndTargetsStopAtTheJointLimits) {
  Ur5Reach env;
  Joints near_limit = home();
  near_limit[2] = std::numbers::pi - 0.01;  // the elbow, 10 mrad from its limit
  near_limit[1] = -1.2;                     // upper arm raised, away from the forearm
  env.plant(near_limit, Eigen::Vector3d(0.6, 0.0, 0.2));
  env.step(constant_action(3.0f));
  const Joints targets = env.arm().targets();
  EXPECT_DOUBLE_EQ(targets[2], std::numbers::pi);
  EXPECT_NEAR(targets[0], near_limit[0] + 0.05, 1e-12);  // 3 acts as 1

  auto unbounded = make("UR5/Reach-v0", Config::parse("{action_space: unbounded}"));
  auto bounded = make("UR5/Reach-v0");
  unbounded->reset(8);
  bounded->reset(8);
  const Step far = unbounded->step(constant_action(-40.0f));
  const Step unit = bounded->step(constant_action(-1.0f));
  EXPECT_EQ(far.observation, unit.observation);
  EXPECT_THROW(bounded->step(Action::Constant(6, NAN)), Error);
  EXPECT_THROW(bounded->step(Action::Zero(5)), Error);
}

TEST(Ur5Reach, APoseInsideTheBoxIsACollisionThatEndsTheEpisode) {
  Ur5Reach env;
  Joints inside_box;
  inside_box << 2.865, -1.401, 2.381, -2.551, -1.571, -0.276;  // flange at the box's centre
  env.plant(inside_box, Eigen::Vector3d(0.6, 0.0, 0.2));
  const Step step = env.step(constant_action(0.0f));
  EXPECT_TRUE(step.terminated);
  EXPECT_FALSE(step.truncated);
  EXPECT_EQ(*step.info.get("collision"), 1.0);
  EXPECT_GT(*step.info.get("contacts"), 0.0);
  EXPECT_EQ(*step.info.get("is_success"), 0.0);
  EXPECT_EQ(step.observation[18], 1.0f);
  // −10 for the collision on top of the other terms, which a silent reward leaves out.
  Ur5Reach::Params params = silent_reward();
  params.reward.collision = 10.0;
  Ur5Reach silent(params);
  silent.plant(inside_box, Eigen::Vector3d(0.6, 0.0, 0.2));
  EXPECT_DOUBLE_EQ(silent.step(constant_action(0.0f)).reward, -10.0);
}

TEST(Ur5Reach, EachRewardTermInTheRunningEnvironment) {
  // Standing still at home (the servos hold the pose exactly): no progress, the distance and
  // orientation terms at the planted state, the time penalty, λ_u‖a‖² for the action given.
  const Eigen::Vector3d target(0.6, 0.1, 0.2);
  auto reward_with = [&](auto set, const Action& action) {
    Ur5Reach::Params params = silent_reward();
    set(params);
    Ur5Reach env(params);
    env.plant(home(), target);
    return env.step(action);
  };
  Ur5Reach probe;
  probe.plant(home(), target);
  const double d = (probe.arm().flange_position() - target).norm();
  const double theta = probe.orientation_error();
  const Action still = constant_action(0.0f);

  EXPECT_NEAR(reward_with([](auto& p) { p.reward.distance = 2.0; }, still).reward,
              2.0 * std::exp(-4.0 * d), 1e-9);
  EXPECT_NEAR(reward_with([](auto& p) { p.reward.orientation = 1.0; }, still).reward,
              -theta / std::numbers::pi, 1e-9);
  EXPECT_NEAR(reward_with([](auto& p) { p.reward.time = 0.01; }, still).reward, -0.01, 1e-15);
  EXPECT_NEAR(reward_with([](auto& p) { p.reward.progress = 10.0; }, still).reward, 0.0, 1e-9);
  // λ_u = 0.05 on a = (0.2, …, 0.2): 0.05·6·0.04.
  EXPECT_NEAR(reward_with([](auto& p) { p.action_penalty = StepSchedule::constant(0.05); },
                          constant_action(0.2f))
                  .reward,
              -0.05 * 6 * 0.04, 1e-7);
  // Progress: 10 × the distance gained, read from the info before and after.
  Ur5Reach::Params params = silent_reward();
  params.reward.progress = 10.0;
  Ur5Reach env(params);
  env.plant(home(), target);
  Action towards(6);
  towards << 0.5f, 0.3f, -0.3f, 0.0f, 0.0f, 0.0f;
  const Step step = env.step(towards);
  EXPECT_NEAR(step.reward, 10.0 * (d - *step.info.get("distance")), 1e-9);
  EXPECT_NE(step.reward, 0.0);
}

TEST(Ur5Reach, TheActionPenaltyFollowsItsScheduleInThisInstancesSteps) {
  auto env = make("UR5/Reach-v0",
                  Config::parse("{action_penalty_schedule: {start: 0.01, end: 0.05, steps: 100}}"));
  env->reset(1);
  std::vector<double> weights;
  for (int i = 0; i < 120; ++i) {
    const Step step = env->step(constant_action(0.0f));
    weights.push_back(*step.info.get("action_penalty_weight"));
    if (step.terminated || step.truncated) env->reset();
  }
  EXPECT_DOUBLE_EQ(weights[0], 0.01);
  EXPECT_DOUBLE_EQ(weights[50], 0.03);
  EXPECT_DOUBLE_EQ(weights[100], 0.05);
  EXPECT_DOUBLE_EQ(weights[119], 0.05);

  // Resets do not restart the count.
  Ur5Reach::Params params;
  params.action_penalty = StepSchedule::linear(0.01, 0.05, 100);
  Ur5Reach reach(params);
  reach.reset(1);
  for (int i = 0; i < 50; ++i) reach.step(constant_action(0.0f));
  reach.reset();
  EXPECT_DOUBLE_EQ(*reach.step(constant_action(0.0f)).info.get("action_penalty_weight"), 0.03);
  EXPECT_EQ(reach.total_steps(), 51);
}

TEST(Ur5Reach, ReachingTheTargetToolDownSucceedsAndEndsTheEpisode) {
  Ur5Reach env;
  env.plant(home(), Eigen::Vector3d(0.6, 0.0, 0.2));
  const Eigen::Vector3d at_flange = env.arm().flange_position();
  ASSERT_LT(env.orientation_error(), 0.3);
  env.plant(home(), at_flange);
  const Step success = env.step(constant_action(0.0f));
  EXPECT_TRUE(success.terminated);
  EXPECT_EQ(*success.info.get("is_success"), 1.0);
  EXPECT_EQ(*success.info.get("collision"), 0.0);
  EXPECT_LT(*success.info.get("distance"), 1e-9);
  EXPECT_GT(success.reward, 300.0);  // the bonus and the terms near the target

  // At the target with the tool tilted by 0.5 rad: not a success, the episode goes on.
  Joints tilted = home();
  tilted[4] += 0.5;
  env.plant(tilted, Eigen::Vector3d::Zero());
  env.plant(tilted, env.arm().flange_position());
  ASSERT_GT(env.orientation_error(), 0.3);
  const Step not_yet = env.step(constant_action(0.0f));
  EXPECT_FALSE(not_yet.terminated);
  EXPECT_EQ(*not_yet.info.get("is_success"), 0.0);
}

TEST(Ur5Reach, AStillArmIsCutOffByTheTimeLimitAfterAThousandSteps) {
  auto env = make("UR5/Reach-v0");
  env->reset(2);
  Step step;
  int steps = 0;
  do {
    step = env->step(constant_action(0.0f));
    ++steps;
  } while (!step.terminated && !step.truncated);
  EXPECT_EQ(steps, 1000);
  EXPECT_TRUE(step.truncated);
  EXPECT_FALSE(step.terminated);
}

TEST(Ur5Reach, EveryStartIsFreeAndEveryTargetHiddenBehindTheBox) {
  // The scene's promise: from each episode's start the straight path of the flange to the
  // target runs through the box. Sampling rejects targets it does not hide, but the region is
  // laid out so that from the home pose every target outside the margin is hidden anyway.
  Ur5Reach env;
  env.plant(home(), Eigen::Vector3d(0.6, 0.0, 0.2));
  const Eigen::Vector3d home_flange = env.arm().flange_position();
  const TargetRegion& region = env.params().targets;
  const Eigen::Vector3d centre = env.arm().obstacle_centre();
  const Eigen::Vector3d half = env.arm().obstacle_half_extents();
  for (uint64_t seed = 0; seed < 300; ++seed) {
    env.reset(seed);
    ASSERT_EQ(env.arm().contacts(), 0) << seed;
    ASSERT_TRUE(segment_hits_box(env.arm().flange_position(), env.target(), centre, half)) << seed;
  }
  Rng rng(5);
  int hidden = 0, kept = 0;
  for (int i = 0; i < 5000; ++i) {
    Eigen::Vector3d target;
    for (int axis = 0; axis < 3; ++axis)
      target[axis] = rng.uniform(region.low[axis], region.high[axis]);
    if (distance_to_box(target, centre, half) <= region.obstacle_margin) continue;
    ++kept;
    hidden += segment_hits_box(home_flange, target, centre, half);
  }
  EXPECT_EQ(hidden, kept);
}

TEST(Ur5Reach, TheSameSeedGivesTheSameEpisode) {
  Ur5Reach a, b;
  Rng actions(3);
  EXPECT_EQ(a.reset(11), b.reset(11));
  for (int i = 0; i < 50; ++i) {
    const Action action = a.action_space().sample(actions);
    const Step sa = a.step(action), sb = b.step(action);
    ASSERT_EQ(sa.observation, sb.observation) << i;
    ASSERT_EQ(sa.reward, sb.reward) << i;
  }
  EXPECT_NE(a.reset(12), b.reset(13));
}

TEST(Ur5Reach, BadParamsAndModelFilesAreErrorsNamingThem) {
  EXPECT_NE(error_message([] {
              make("UR5/Reach-v0", Config::parse("{model_file: /no/such/ur5.xml}"));
            }).find("/no/such/ur5.xml"),
            std::string::npos);
  EXPECT_NE(error_message([] {
              make("UR5/Reach-v0", Config::parse("{action_space: infinite}", "exp.yaml"));
            }).find("action_space"),
            std::string::npos);
  EXPECT_NE(error_message([] {
              make("UR5/Reach-v0", Config::parse("{home: [0, 0, 0]}", "exp.yaml"));
            }).find("home"),
            std::string::npos);
  EXPECT_NE(error_message([] {
              make("UR5/Reach-v0", Config::parse("{max_delta: -1}", "exp.yaml"));
            }).find("max_delta"),
            std::string::npos);
  EXPECT_NE(error_message([] {
              make("UR5/Reach-v0", Config::parse("{obstacle_size: [1, 1, 1]}"));
            }).find("obstacle_size"),
            std::string::npos);
}

TEST(Ur5Reach, TheSceneAddsTheTargetToTheArm) {
  Ur5Reach env;
  env.reset(1);
  Scene scene;
  ASSERT_TRUE(env.describe_scene(scene));
  EXPECT_EQ(scene.cylinders.size(), 8u);
  EXPECT_EQ(scene.boxes.size(), 1u);
  ASSERT_EQ(scene.spheres.size(), 1u);
  EXPECT_EQ(scene.spheres[0].role, "target");
  EXPECT_EQ(scene.spheres[0].centre, env.target());
  EXPECT_EQ(scene.spheres[0].radius, 0.05);
}

}  // namespace
}  // namespace tendril::envs::ur5
