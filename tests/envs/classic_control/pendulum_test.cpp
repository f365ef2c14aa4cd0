#include "tendril/envs/classic_control/pendulum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::envs {
namespace {

// Gymnasium's Pendulum-v1 step, written out from its published equations for one state.
TEST(Pendulum, OneStepMatchesGymnasiumEquations) {
  Pendulum env;
  env.reset(0);
  const double theta = 0.5, theta_dot = -1.2, u = 1.5, g = 10.0, m = 1.0, l = 1.0, dt = 0.05;
  env.set_state(theta, theta_dot);
  const Step step = env.step(Action::Constant(1, static_cast<float>(u)));

  const double new_theta_dot =
      theta_dot + (3.0 * g / (2.0 * l) * std::sin(theta) + 3.0 / (m * l * l) * u) * dt;
  const double new_theta = theta + new_theta_dot * dt;
  const double reward = -(theta * theta + 0.1 * theta_dot * theta_dot + 0.001 * u * u);
  // The same numbers evaluated independently: -0.6154308460468477, 0.46922845769765764, -0.39625.
  EXPECT_NEAR(new_theta_dot, -0.6154308460468477, 1e-15);
  EXPECT_NEAR(env.theta_dot(), new_theta_dot, 1e-12);
  EXPECT_NEAR(env.theta(), new_theta, 1e-12);
  EXPECT_NEAR(step.reward, reward, 1e-12);
  EXPECT_NEAR(step.reward, -0.39625, 1e-12);
  ASSERT_EQ(step.observation.size(), 3);
  EXPECT_FLOAT_EQ(step.observation[0], static_cast<float>(std::cos(new_theta)));
  EXPECT_FLOAT_EQ(step.observation[1], static_cast<float>(std::sin(new_theta)));
  EXPECT_FLOAT_EQ(step.observation[2], static_cast<float>(new_theta_dot));
  EXPECT_FALSE(step.terminated);
  EXPECT_FALSE(step.truncated);
}

TEST(Pendulum, RewardUsesTheNormalizedAngle) {
  Pendulum env;
  env.reset(0);
  env.set_state(5.0, 0.0);
  const Step step = env.step(Action::Zero(1));
  const double normalized = 5.0 - 2.0 * std::numbers::pi;  // 5 rad is −1.283 rad from upright
  EXPECT_NEAR(step.reward, -(normalized * normalized), 1e-12);
  EXPECT_NEAR(step.reward, -1.646564532561569, 1e-12);
  EXPECT_NEAR(Pendulum::normalize_angle(-4.0), 2.0 * std::numbers::pi - 4.0, 1e-12);
  EXPECT_NEAR(Pendulum::normalize_angle(std::numbers::pi), -std::numbers::pi, 1e-12);
}

TEST(Pendulum, TorqueSaturatesAndSpeedIsCapped) {
  Pendulum env;
  env.reset(0);
  env.set_state(0.0, 7.9);
  const Step step = env.step(Action::Constant(1, 5.0f));
  // u is saturated to 2 N·m before it enters dynamics and reward; θdot is capped at 8 rad/s.
  EXPECT_DOUBLE_EQ(env.theta_dot(), 8.0);
  EXPECT_DOUBLE_EQ(env.theta(), 8.0 * 0.05);
  EXPECT_NEAR(step.reward, -(0.1 * 7.9 * 7.9 + 0.001 * 2.0 * 2.0), 1e-12);
}

TEST(Pendulum, GravityIsAParameter) {
  const auto env = Pendulum::create(Config::parse("g: 9.81"));
  auto& pendulum = dynamic_cast<Pendulum&>(*env);
  pendulum.reset(0);
  pendulum.set_state(0.5, -1.2);
  pendulum.step(Action::Constant(1, 1.5f));
  EXPECT_NEAR(pendulum.theta_dot(), -1.2 + (1.5 * 9.81 * std::sin(0.5) + 3.0 * 1.5) * 0.05, 1e-12);
}

TEST(Pendulum, SpacesAndResetDistribution) {
  Pendulum env;
  EXPECT_EQ(env.observation_space().describe(), "Box(3, [-8, 8])");
  EXPECT_EQ(env.action_space().low()[0], -2.0f);
  EXPECT_EQ(env.action_space().high()[0], 2.0f);
  double min_theta = 10, max_theta = -10;
  for (uint64_t seed = 0; seed < 500; ++seed) {
    const Observation obs = env.reset(seed);
    ASSERT_GE(env.theta(), -std::numbers::pi);
    ASSERT_LT(env.theta(), std::numbers::pi);
    ASSERT_GE(env.theta_dot(), -1.0);
    ASSERT_LT(env.theta_dot(), 1.0);
    ASSERT_FLOAT_EQ(obs[0], static_cast<float>(std::cos(env.theta())));
    min_theta = std::min(min_theta, env.theta());
    max_theta = std::max(max_theta, env.theta());
  }
  EXPECT_LT(min_theta, -3.0);  // the whole circle is covered
  EXPECT_GT(max_theta, 3.0);
}

TEST(Pendulum, SameSeedSameEpisode) {
  Pendulum a, b;
  EXPECT_EQ(a.reset(7), b.reset(7));
  EXPECT_NE(a.reset(7), a.reset(8));
  a.reset(7);
  for (int t = 0; t < 50; ++t) {
    const Action action = Action::Constant(1, std::sin(0.3f * t));
    ASSERT_EQ(a.step(action).observation, b.step(action).observation);
  }
}

TEST(Pendulum, RejectsWrongSizeAndNonFiniteActions) {
  Pendulum env;
  env.reset(0);
  EXPECT_THROW(env.step(Action::Zero(2)), Error);
  EXPECT_THROW(env.step(Action::Constant(1, std::nanf(""))), Error);
}

}  // namespace
}  // namespace tendril::envs
