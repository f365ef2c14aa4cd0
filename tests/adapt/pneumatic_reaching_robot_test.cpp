// The pneumatic arm's task as BOAC and GPRCA see it: the same arm as PneumaticArm/Reach-v0 under
// the same actions, and GPRCA's model fed the measured tips.
#include "tendril/adapt/pneumatic_reaching_robot.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"
#include "tendril/envs/pneumatic/linear_arm_model.hpp"

namespace tendril::adapt {
namespace {

const char* kTwin = "observe_command: true\nrobot: {stochastic: false}\n";

TEST(PneumaticReachingRobot, StepsAsTheTaskDoesAndObservesAsThePolicyWould) {
  const auto env = envs::pneumatic::ReachEnv::create_on_robot(Config::parse(kTwin));
  const auto robot = PneumaticReachingRobot::on_robot(Config::parse(kTwin));
  auto& task = dynamic_cast<envs::pneumatic::ReachEnv&>(*env);
  EXPECT_EQ(robot->state_names().front(), "tip_m1_x_mm");
  EXPECT_EQ(robot->state_names().back(), "tip_m3_z_mm");
  EXPECT_EQ(robot->goal(), Eigen::Vector3d(-30.0, -120.0, -620.0));
  env->reset(0);
  const Eigen::VectorXd rest = robot->reset(0);
  EXPECT_EQ(rest, task.tips());
  EXPECT_EQ(robot->command(), Eigen::VectorXd::Constant(9, -1.0));
  Rng rng(1);
  Eigen::VectorXd state = rest;
  for (int t = 0; t < 8; ++t) {
    Action delta(9);
    for (int k = 0; k < 9; ++k) delta[k] = static_cast<float>(rng.uniform(-0.2, 0.2));
    const Step step = env->step(delta);
    state = robot->step(robot->command_after(delta));
    EXPECT_EQ(state, task.tips()) << t;
    EXPECT_EQ(robot->observation_of(state), step.observation) << t;
    EXPECT_EQ(robot->status().goal_distance, *step.info.get("goal_distance_mm"));
    EXPECT_EQ(robot->task_point(state), task.tips().tail<3>());
  }
  // A delta beyond the rate limit leaves the command as it is, as the task does.
  Action too_far = Action::Zero(9);
  too_far[0] = 0.3f;
  EXPECT_EQ(robot->command_after(too_far), robot->command());
  EXPECT_THROW(robot->step(Eigen::VectorXd::Zero(4)), Error);
}

TEST(PneumaticHistoryModel, PredictsFromTheMeasuredTipsAndFollowsThem) {
  // Without a `model` the learned-reach parameters give LinearArmModel, the torch-free stand-in.
  PneumaticHistoryModel model(Config::parse("{}"));
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
}

}  // namespace
}  // namespace tendril::adapt
