#include "tendril/envs/classic_control/cart_pole.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::envs {
namespace {

// Gymnasium's CartPole-v1 Euler step written out for one state and both actions.
Eigen::Vector4d expected_step(const Eigen::Vector4d& s, double force) {
  const double gravity = 9.8, cart_mass = 1.0, pole_mass = 0.1, half_length = 0.5, tau = 0.02;
  const double total = cart_mass + pole_mass;
  const double c = std::cos(s[2]), sn = std::sin(s[2]);
  const double temp = (force + pole_mass * half_length * s[3] * s[3] * sn) / total;
  const double theta_acc =
      (gravity * sn - c * temp) / (half_length * (4.0 / 3.0 - pole_mass * c * c / total));
  const double x_acc = temp - pole_mass * half_length * theta_acc * c / total;
  return {s[0] + tau * s[1], s[1] + tau * x_acc, s[2] + tau * s[3], s[3] + tau * theta_acc};
}

TEST(CartPole, OneStepMatchesGymnasiumEquations) {
  const Eigen::Vector4d start(0.1, -0.2, 0.05, 0.3);
  for (const int action : {0, 1}) {
    CartPole env;
    env.reset(0);
    env.set_state(start);
    const Step step = env.step(Action::Constant(1, static_cast<float>(action)));
    const Eigen::Vector4d expected = expected_step(start, action == 1 ? 10.0 : -10.0);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(env.state()[i], expected[i], 1e-14) << i;
    EXPECT_EQ(step.observation, expected.cast<float>());
    EXPECT_EQ(step.reward, 1.0);
    EXPECT_FALSE(step.terminated);
  }
  // Independently evaluated: pushing right, xdot' = -0.005625065781779709, θdot' =
  // 0.02349585151852651.
  CartPole env;
  env.reset(0);
  env.set_state(start);
  env.step(Action::Constant(1, 1.0f));
  EXPECT_NEAR(env.state()[1], -0.005625065781779709, 1e-15);
  EXPECT_NEAR(env.state()[3], 0.02349585151852651, 1e-15);
}

TEST(CartPole, TerminatesPastThePositionLimitAndRewardsTheFallOnce) {
  CartPole env;
  env.reset(0);
  env.set_state(Eigen::Vector4d(2.399, 1.0, 0.0, 0.0));
  const Step fall = env.step(Action::Constant(1, 1.0f));  // x' = 2.399 + 0.02 > 2.4
  EXPECT_TRUE(fall.terminated);
  EXPECT_FALSE(fall.truncated);
  EXPECT_EQ(fall.reward, 1.0);
  const Step after = env.step(Action::Constant(1, 1.0f));
  EXPECT_TRUE(after.terminated);
  EXPECT_EQ(after.reward, 0.0);  // Gymnasium: steps after termination earn nothing
  env.reset(1);
  EXPECT_EQ(env.step(Action::Constant(1, 0.0f)).reward, 1.0);
}

TEST(CartPole, TerminatesPastTwelveDegrees) {
  const double limit = 12.0 * 2.0 * std::numbers::pi / 360.0;
  CartPole env;
  env.reset(0);
  env.set_state(Eigen::Vector4d(0.0, 0.0, limit - 1e-4, 0.0));
  EXPECT_FALSE(env.step(Action::Constant(1, 1.0f)).terminated);  // θdot was 0: θ unchanged
  env.set_state(Eigen::Vector4d(0.0, 0.0, -limit + 1e-4, -0.01));
  EXPECT_TRUE(env.step(Action::Constant(1, 0.0f)).terminated);  // θ' = θ − 0.0002 < −12°
}

TEST(CartPole, SpacesAndResetDistribution) {
  CartPole env;
  EXPECT_TRUE(env.action_space().is_discrete());
  EXPECT_EQ(env.action_space().n(), 2);
  EXPECT_FLOAT_EQ(env.observation_space().high()[0], 4.8f);
  EXPECT_FLOAT_EQ(env.observation_space().high()[2],
                  static_cast<float>(24.0 * std::numbers::pi / 180.0));
  for (uint64_t seed = 0; seed < 200; ++seed) {
    const Observation obs = env.reset(seed);
    ASSERT_TRUE((obs.array().abs() < 0.05f).all()) << obs.transpose();
  }
  CartPole a, b;
  EXPECT_EQ(a.reset(3), b.reset(3));
}

TEST(CartPole, RejectsActionsOutsideDiscreteTwo) {
  CartPole env;
  env.reset(0);
  EXPECT_THROW(env.step(Action::Constant(1, 2.0f)), Error);
  EXPECT_THROW(env.step(Action::Constant(1, 0.5f)), Error);
  EXPECT_THROW(env.step(Action::Zero(2)), Error);
}

}  // namespace
}  // namespace tendril::envs
