// TendonArm/Reach-v0 and TendonArm/LearnedReach-v0: goals the plant itself reaches, the
// observation and reward of the task, determinism, and the learned variant's required model.
#include "tendril/envs/tendon_arm/reach_env.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "support/error_message.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/tendon_arm/arm_spec.hpp"
#include "tendril/envs/tendon_arm/constant_curvature_model.hpp"
#include "tendril/envs/tendon_arm/robot_env.hpp"

namespace tendril::envs::tendon_arm {
namespace {

using testing::error_message;

std::unique_ptr<ReachEnv> make_reach(const std::string& id) {
  const Config params =
      Config::parse(id == ReachEnv::kModelId ? "model: constant_curvature\n" : "");
  std::unique_ptr<Env> env = id == ReachEnv::kModelId ? ReachEnv::create_on_model(params)
                                                      : ReachEnv::create_on_robot(params);
  return std::unique_ptr<ReachEnv>(static_cast<ReachEnv*>(env.release()));
}

class OnEveryPlant : public ::testing::TestWithParam<std::string> {};

// Holding the goal's tensions from the rest for goal_settle_steps (15) is how the goal was made,
// so it lands on the goal exactly (both plants are deterministic): every goal is reachable.
TEST_P(OnEveryPlant, TheGoalTensionsReachTheGoalExactly) {
  const auto env = make_reach(GetParam());
  for (uint64_t seed : {0u, 1u, 2u}) {
    const Observation start = env->reset(seed);
    const Eigen::Vector3d goal = env->goal();
    const double away = (goal - env->tip()).norm();
    EXPECT_GT(away, 0.01) << "seed " << seed;
    EXPECT_EQ(env->goal_tensions().minCoeff(), 0.0) << "one tendon slack";
    // The observation: tip / L, (goal − tip) / L, tensions / 6 N (0 at rest).
    EXPECT_NEAR(start[2], env->tip().z() / 0.30, 1e-6);
    EXPECT_NEAR(Eigen::Vector3d(start.segment<3>(3).cast<double>()).norm() * 0.30, away, 1e-6);
    EXPECT_EQ(start.tail<3>(), Eigen::Vector3f::Zero());
    const Action action = env->goal_tensions().cast<float>();
    Step step;
    for (int k = 0; k < 15; ++k) step = env->step(action);
    EXPECT_LT((env->tip() - goal).norm(), 1e-6) << "seed " << seed;
    EXPECT_GT(step.reward, -1e-5);
    EXPECT_EQ(step.info.get("is_success"), 1.0);
    EXPECT_NEAR(step.observation[6], action[0] / 6.0, 1e-6);
  }
}

TEST_P(OnEveryPlant, RewardIsMinusTheDistanceInArmLengthsAndSeedsRepeatGoals) {
  const auto env = make_reach(GetParam());
  const auto other = make_reach(GetParam());
  env->reset(5);
  other->reset(6);
  EXPECT_GT((env->goal() - other->goal()).norm(), 1e-3) << "seeds draw different goals";
  other->reset(5);
  EXPECT_EQ(env->goal(), other->goal());
  Action action(3);
  action << 1.0f, 0.5f, 2.0f;
  const Step a = env->step(action), b = other->step(action);
  EXPECT_EQ(a.observation, b.observation);
  const double distance = (env->goal() - env->tip()).norm();
  EXPECT_DOUBLE_EQ(a.info.get("distance").value(), distance);
  EXPECT_DOUBLE_EQ(a.reward, -distance / 0.30);
  EXPECT_EQ(a.info.get("is_success"), distance <= 0.01 ? 1.0 : 0.0);
  EXPECT_EQ(env->action_space().high(), Eigen::VectorXf::Constant(3, 6.0f));
  EXPECT_EQ(env->observation_space().size(), 9);
}

INSTANTIATE_TEST_SUITE_P(TendonArm, OnEveryPlant,
                         ::testing::Values(ReachEnv::kRobotId, ReachEnv::kModelId));

TEST(TendonArmLearnedReach, WithoutAModelItNamesTheMissingKey) {
  const std::string message = error_message([] { make(ReachEnv::kModelId); });
  EXPECT_NE(message.find("TendonArm/LearnedReach-v0 needs `model:`"), std::string::npos) << message;
  EXPECT_NE(message.find("model"), std::string::npos);
  // Another name is opened as a model file, through the loader this program lacks.
  EXPECT_NE(error_message([] { make(ReachEnv::kModelId, Config::parse("model: linear\n")); }),
            "no error");
  EXPECT_NE(error_message([] {
              make(ReachEnv::kModelId,
                   Config::parse("model: constant_curvature\nrest_m: [0, 0]\n"));
            }).find("rest_m"),
            std::string::npos);
}

// The stand-in's steady tip is the constant-curvature arc (Webster & Jones 2010): one tendon at
// T bends the L-long arm by θ = T r L / (E I) towards it; the tip sits L (1 − cos θ)/θ sideways
// and L sin θ / θ below the base.
TEST(TendonArmLearnedReach, TheStandInIsTheConstantCurvatureArc) {
  const ArmSpec spec;
  const Eigen::Vector3d rest(0.0, 0.0, -spec.length);
  const ConstantCurvatureModel model(spec, rest);
  Eigen::VectorXd tensions = Eigen::VectorXd::Zero(3);
  tensions[0] = 3.0;
  const double theta = 3.0 * spec.tendon_offset * spec.length / spec.bending_stiffness();
  const Eigen::Vector3d tip = model.steady_tip(tensions);
  EXPECT_NEAR(tip.x(), spec.length * (1.0 - std::cos(theta)) / theta, 1e-12);
  EXPECT_NEAR(tip.y(), 0.0, 1e-12);
  EXPECT_NEAR(tip.z(), -spec.length * std::sin(theta) / theta, 1e-12);
  EXPECT_EQ(model.steady_tip(Eigen::VectorXd::Zero(3)), rest);
}

}  // namespace
}  // namespace tendril::envs::tendon_arm
