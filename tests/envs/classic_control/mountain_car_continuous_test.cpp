#include "tendril/envs/classic_control/mountain_car_continuous.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::envs {
namespace {

TEST(MountainCarContinuous, OneStepMatchesGymnasiumEquations) {
  MountainCarContinuous env;
  env.reset(0);
  const double x = -0.5, v = 0.01, a = 0.6;
  env.set_state(x, v);
  const Step step = env.step(Action::Constant(1, static_cast<float>(a)));
  const double action = static_cast<float>(a);  // the env sees the float32 action
  const double new_v = v + action * 0.0015 - 0.0025 * std::cos(3.0 * x);
  const double new_x = x + new_v;
  // Independently evaluated: v' = 0.010723156995830742, x' = -0.48927684300416924.
  EXPECT_NEAR(new_v, 0.010723156995830742, 1e-9);
  EXPECT_EQ(env.velocity(), static_cast<float>(new_v));  // Gymnasium keeps the state in float32
  EXPECT_EQ(env.position(), static_cast<float>(new_x));
  EXPECT_EQ(step.observation,
            Eigen::Vector2f(static_cast<float>(new_x), static_cast<float>(new_v)));
  EXPECT_NEAR(step.reward, -0.1 * action * action, 1e-15);
  EXPECT_FALSE(step.terminated);
}

TEST(MountainCarContinuous, RewardPenalizesTheUnclippedAction) {
  MountainCarContinuous env;
  env.reset(0);
  env.set_state(-0.5, 0.0);
  const Step step = env.step(Action::Constant(1, 2.0f));
  EXPECT_NEAR(step.reward, -0.4, 1e-12);  // −0.1 · 2², though the force is clipped to 1
  EXPECT_EQ(env.velocity(), static_cast<float>(0.0015 - 0.0025 * std::cos(-1.5)));
}

TEST(MountainCarContinuous, ReachingTheGoalTerminatesWithTheBonus) {
  MountainCarContinuous env;
  env.reset(0);
  env.set_state(0.44, 0.02);
  const Step step = env.step(Action::Constant(1, 0.5f));
  const double new_v = 0.02 + 0.5 * 0.0015 - 0.0025 * std::cos(3.0 * 0.44);
  EXPECT_GE(0.44 + new_v, 0.45);
  EXPECT_TRUE(step.terminated);
  EXPECT_FALSE(step.truncated);
  EXPECT_NEAR(step.reward, 100.0 - 0.1 * 0.25, 1e-12);
}

TEST(MountainCarContinuous, GoalVelocityParameterDelaysTermination) {
  const auto env = MountainCarContinuous::create(Config::parse("goal_velocity: 0.05"));
  auto& car = dynamic_cast<MountainCarContinuous&>(*env);
  car.reset(0);
  car.set_state(0.44, 0.02);
  EXPECT_FALSE(car.step(Action::Constant(1, 0.5f)).terminated);  // v' ≈ 0.0201 < 0.05
}

TEST(MountainCarContinuous, LeftWallStopsTheCarAndSpeedIsCapped) {
  MountainCarContinuous env;
  env.reset(0);
  env.set_state(-1.19, -0.05);
  env.step(Action::Constant(1, -1.0f));
  EXPECT_EQ(env.position(), static_cast<float>(-1.2));
  EXPECT_EQ(env.velocity(), 0.0);
  env.set_state(-0.6, 0.0699);  // 0.0699 + 0.0015 − 0.0025 cos(−1.8) > 0.07
  env.step(Action::Constant(1, 1.0f));
  EXPECT_EQ(env.velocity(), static_cast<float>(0.07));
}

TEST(MountainCarContinuous, ResetDistributionAndSpaces) {
  MountainCarContinuous env;
  for (uint64_t seed = 0; seed < 200; ++seed) {
    const Observation obs = env.reset(seed);
    ASSERT_GE(obs[0], -0.6f);
    ASSERT_LE(obs[0], -0.4f);
    ASSERT_EQ(obs[1], 0.0f);
  }
  EXPECT_FLOAT_EQ(env.observation_space().low()[0], -1.2f);
  EXPECT_FLOAT_EQ(env.observation_space().high()[1], 0.07f);
  EXPECT_EQ(env.action_space().describe(), "Box(1, [-1, 1])");
  EXPECT_THROW(env.step(Action::Constant(1, INFINITY)), Error);
}

}  // namespace
}  // namespace tendril::envs
