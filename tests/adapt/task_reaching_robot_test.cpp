// A reaching task as BOAC and GPRCA see it, through its envs::ReachCommandTask: the pneumatic
// arm's task steps as PneumaticArm/Reach-v0 does under the same actions, its learned-model task
// gives GPRCA's model fed the measured tips, and environments without the capability are refused.
#include "tendril/adapt/task_reaching_robot.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"
#include "tendril/envs/pneumatic/linear_arm_model.hpp"
#include "tendril/envs/pneumatic/reach_env.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/wrappers/time_limit.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::adapt {
namespace {

using envs::pneumatic::ReachEnv;

const char* kTwin = "observe_command: true\nrobot: {stochastic: false}\n";

TEST(TaskReachingRobot, StepsAsTheTaskDoesAndObservesAsThePolicyWould) {
  const auto env = ReachEnv::create_on_robot(Config::parse(kTwin));
  // Found through a wrapper, as the registry's environments come.
  TaskReachingRobot robot(
      std::make_unique<envs::TimeLimit>(ReachEnv::create_on_robot(Config::parse(kTwin)), 150));
  auto& task = *envs::find_wrapper<ReachEnv>(*env);
  EXPECT_EQ(robot.state_dim(), 9);
  EXPECT_EQ(robot.command_dim(), 9);
  EXPECT_EQ(robot.state_names().front(), "tip_m1_x_mm");
  EXPECT_EQ(robot.state_names().back(), "tip_m3_z_mm");
  EXPECT_EQ(robot.goal(), Eigen::Vector3d(-30.0, -120.0, -620.0));
  EXPECT_EQ(robot.success_distance(), task.task().success_distance);
  env->reset(0);
  const Eigen::VectorXd rest = robot.reset(0);
  EXPECT_EQ(rest, task.tips());
  EXPECT_EQ(robot.command(), Eigen::VectorXd::Constant(9, -1.0));
  EXPECT_EQ(robot.status().goal_distance, (task.tips().tail<3>() - robot.goal()).norm());
  EXPECT_EQ(robot.status().reward, 0.0);
  Rng rng(1);
  Eigen::VectorXd state = rest;
  for (int t = 0; t < 8; ++t) {
    Action delta(9);
    for (int k = 0; k < 9; ++k) delta[k] = static_cast<float>(rng.uniform(-0.2, 0.2));
    const Step step = env->step(delta);
    state = robot.step(robot.command_after(delta));
    EXPECT_EQ(state, task.tips()) << t;
    EXPECT_EQ(robot.command(), Eigen::VectorXd(task.command())) << t;
    EXPECT_EQ(robot.observation_of(state), step.observation) << t;
    EXPECT_EQ(robot.status().goal_distance, *step.info.get("goal_distance_mm"));
    EXPECT_EQ(robot.status().reward, step.reward);
    EXPECT_EQ(robot.task_point(state), task.tips().tail<3>());
  }
  // A delta beyond the rate limit leaves the command as it is, as the task does.
  Action too_far = Action::Zero(9);
  too_far[0] = 0.3f;
  EXPECT_EQ(robot.command_after(too_far), robot.command());
  EXPECT_THROW(robot.step(Eigen::VectorXd::Zero(4)), Error);
}

TEST(TaskHistoryModel, PredictsFromTheMeasuredTipsAndFollowsThem) {
  // Without a `model` the learned-reach parameters give LinearArmModel, the torch-free stand-in.
  TaskHistoryModel model(ReachEnv::create_on_model(Config::parse("{}")));
  envs::pneumatic::TipVector measured = envs::pneumatic::LinearArmModel::rest();
  measured[8] -= 10.0;
  model.reset(measured);
  const Eigen::VectorXd command = Eigen::VectorXd::Constant(9, 0.0);  // 0.75 bar each
  const Eigen::VectorXd first = model.predict(command);
  EXPECT_EQ(model.predict(command), first);
  model.follow(first);
  const Eigen::VectorXd second = model.predict(command);
  // Three equal pressures extend: module 3's tip keeps going down toward the steady state.
  EXPECT_LT(first[8], measured[8]);
  EXPECT_LT(second[8], first[8]);
  EXPECT_NEAR(first[0], measured[0], 1e-3);
  EXPECT_THROW(model.predict(Eigen::VectorXd::Zero(4)), Error);
}

// The task on the robot has no learned model to feed; a task that is no ReachCommandTask is
// refused by name.
TEST(TaskReachingRobot, RefusesEnvironmentsWithoutTheCapability) {
  EXPECT_THROW(TaskHistoryModel(ReachEnv::create_on_robot(Config::parse(kTwin))), Error);
  try {
    TaskReachingRobot robot(envs::make("Pendulum-v1"));
    FAIL() << "a pendulum was taken for a reaching task";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("envs::ReachCommandTask"), std::string::npos) << e.what();
  }
  EXPECT_THROW(TaskHistoryModel(envs::make("Pendulum-v1")), Error);
}

}  // namespace
}  // namespace tendril::adapt
