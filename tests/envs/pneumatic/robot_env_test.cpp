#include "tendril/envs/pneumatic/robot_env.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "support/error_message.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::envs::pneumatic {
namespace {

using testing::error_message;

std::unique_ptr<Env> robot(const std::string& yaml) {
  return make(RobotEnv::kId, Config::parse(yaml, "robot.yaml"));
}

TEST(RobotEnv, SpacesAreTheHardwaresPressuresAndTipPositions) {
  const auto env = robot("stochastic: false\n");
  EXPECT_EQ(env->action_space().describe(), "Box(9, [0, 1.5])");
  EXPECT_EQ(env->observation_space().size(), 9);
  EXPECT_EQ(robot("observe_pressures: true\n")->observation_space().size(), 18);
}

// The arm hangs from the base plane along −z: at rest the module tips are on the axis, one
// module length apart (598 mm / 3, a little more for gravity's stretch), in mm.
TEST(RobotEnv, ObservesTheModuleTipsInMillimetresZDown) {
  const auto env = robot("stochastic: false\n");
  const Observation rest = env->reset(0);
  for (int m = 0; m < 3; ++m) {
    EXPECT_NEAR(rest[3 * m], 0.0, 1e-9);
    EXPECT_NEAR(rest[3 * m + 1], 0.0, 1e-9);
    EXPECT_NEAR(rest[3 * m + 2], -199.33 * (m + 1), 1.0) << m;
  }
  // Chamber 1 of module 1 (index 0) at +x bends the arm toward −x; the pressures observed
  // are what the regulators hold, under the 1.5 bar ceiling whatever is commanded.
  const auto sensing = robot("stochastic: false\nobserve_pressures: true\n");
  sensing->reset(0);
  Action action = Action::Zero(9);
  action[0] = 4.0f;
  Step step;
  for (int t = 0; t < 20; ++t) step = sensing->step(action);
  EXPECT_LT(step.observation[6], -20.0f);
  EXPECT_GT(step.observation[9], 1.45f);
  EXPECT_LE(step.observation[9], 1.5f);
  EXPECT_EQ(step.observation.tail(8).maxCoeff(), 0.0f);
  EXPECT_NEAR(*step.info.get("time_s"), 2.0, 1e-9);
}

TEST(RobotEnv, TheTwinIsReproducibleWithASeedAndStochasticWithout) {
  auto run = [](Env& env, uint64_t seed) {
    std::vector<Observation> observations{env.reset(seed)};
    Action action = Action::Constant(9, 0.6f);
    action[4] = 1.4f;
    for (int t = 0; t < 10; ++t) observations.push_back(env.step(action).observation);
    return observations;
  };
  const auto a = robot("{}"), b = robot("{}");
  const auto first = run(*a, 3);
  EXPECT_EQ(run(*b, 3), first);
  EXPECT_NE(run(*b, 4), first);
  const auto plain_a = robot("stochastic: false\n"), plain_b = robot("stochastic: false\n");
  EXPECT_EQ(run(*plain_a, 3), run(*plain_b, 4));
  // magnitude_scale multiplies every magnitude: at 0 the effects are on but do nothing.
  const auto scaled_to_zero = robot("magnitude_scale: 0\n");
  EXPECT_EQ(run(*scaled_to_zero, 5), run(*plain_a, 3));
  const auto doubled = robot("magnitude_scale: 2\n");
  EXPECT_NE(run(*doubled, 3), first);
}

TEST(RobotEnv, BadParametersAndActionsAreNamed) {
  EXPECT_NE(error_message([] { robot("scenario: S7\n"); }).find("robot.yaml: scenario"),
            std::string::npos);
  EXPECT_NE(error_message([] { robot("sensor_latency_s: 0.015\n"); }).find("sample period"),
            std::string::npos);
  EXPECT_NE(error_message([] { robot("control_period_s: 0.105\n"); }).find("control_period_s"),
            std::string::npos);
  EXPECT_NE(error_message([] { robot("drift: {step: 3}\n"); }).find("drift.step"),
            std::string::npos);
  EXPECT_NE(error_message([] { robot("twin: {ceiling_bar: 5}\n"); }).find("ceiling_bar"),
            std::string::npos);
  EXPECT_NE(error_message([] { robot("damaged_chamber: 3\n"); }).find("damaged_chamber"),
            std::string::npos);
  for (const char* fraction : {"1", "-0.1", ".nan"}) {
    EXPECT_NE(error_message([&] { robot(std::string("damaged_fraction: ") + fraction + "\n"); })
                  .find("damaged_fraction"),
              std::string::npos)
        << fraction;
  }
  EXPECT_NO_THROW(robot("stochastic: false\nscenario: S1\ndamaged_fraction: 0.5\n"));
  const auto env = robot("{}");
  env->reset(0);
  Action action = Action::Zero(9);
  action[3] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(env->step(action), Error);
  EXPECT_THROW(env->step(Action::Zero(8)), Error);
}

TEST(RobotEnv, DescribesTheArmItsMarkersAndPressures) {
  const auto env = robot("{}");
  env->reset(1);
  Scene scene;
  ASSERT_TRUE(env->describe_scene(scene));
  ASSERT_EQ(scene.rods.size(), 1u);
  EXPECT_EQ(scene.rods[0].centreline.cols(), 19);
  EXPECT_NEAR(scene.rods[0].centreline(2, 18), -0.599, 0.02);
  EXPECT_EQ(scene.spheres.size(), 3u);
  EXPECT_EQ(scene.values.size(), 9u);
}

}  // namespace
}  // namespace tendril::envs::pneumatic
