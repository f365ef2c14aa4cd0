#include "tendril/safety/search_space.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::safety {
namespace {

// A state placed in the environment is the state its next step starts from, and the space's
// observation of it is the environment's own at t = 0.
TEST(SearchSpace, DoubleIntegratorPlacesAndObservesInSafeBoundUnits) {
  auto env = envs::make("Safety/DoubleIntegrator-v0");
  const auto space = search_space_of(*env);
  ASSERT_EQ(space->dimension(), 2);
  EXPECT_EQ(space->names()[1], "velocity");
  const Eigen::Vector2d s(0.5, -0.2);  // x = 1 m, ẋ = −0.6 m/s
  const Observation x = space->observation(s);
  EXPECT_FLOAT_EQ(x[0], 1.0f);
  EXPECT_FLOAT_EQ(x[1], -0.6f);
  EXPECT_FLOAT_EQ(x[2], 0.0f);
  env->reset(0);
  space->place(*env, s);
  const Step step = env->step(Action::Constant(1, 0.0f));  // coast: x' = x + ẋ dt
  EXPECT_NEAR(step.observation[0], 1.0 - 0.6 * 0.05, 1e-6);
  EXPECT_NEAR(step.observation[2], 1.0 / 200.0, 1e-7);
  // The viability kernel: braking at 2 m/s² from ẋ = 2.4 m/s takes 1.44 m.
  EXPECT_TRUE(*space->analytically_safe(Eigen::Vector2d(0.25, 0.8)));  // 0.5 + 1.44 < 2
  EXPECT_FALSE(*space->analytically_safe(Eigen::Vector2d(0.5, 0.8)));  // 1 + 1.44 > 2
}

TEST(SearchSpace, DubinsCarPlacesPositionAndHeading) {
  auto env = envs::make("Safety/DubinsCar-v0");
  const auto space = search_space_of(*env);
  ASSERT_EQ(space->dimension(), 3);
  EXPECT_FALSE(space->analytically_safe(Eigen::Vector3d::Zero()).has_value());
  const Eigen::Vector3d s(0.75, -0.5, 0.5);  // (1.5 m, −1 m), heading π/2
  const Observation x = space->observation(s);
  EXPECT_FLOAT_EQ(x[0], 1.5f);
  EXPECT_FLOAT_EQ(x[1], -1.0f);
  EXPECT_NEAR(x[2], 0.0f, 1e-7);
  EXPECT_FLOAT_EQ(x[3], 1.0f);
  env->reset(0);
  space->place(*env, s);
  // Straight ahead (ω = 0, the middle action of the Box is 0): up by v dt.
  const Step step = env->step(Action::Constant(1, 0.0f));
  EXPECT_NEAR(step.observation[0], 1.5, 1e-6);
  EXPECT_NEAR(step.observation[1], -1.0 + 1.2 * 0.05, 1e-6);
  Rng rng(1);
  for (int k = 0; k < 100; ++k) EXPECT_LE(space->sample(rng).cwiseAbs().maxCoeff(), 1.0);
  // With observe_margin the searched states carry their margin: 0.5 m to the wall at (1.5, −1).
  auto observed = envs::make("Safety/DubinsCar-v0", Config::parse("observe_margin: true"));
  const Observation y = search_space_of(*observed)->observation(s);
  ASSERT_EQ(y.size(), 6);
  EXPECT_EQ(y.head(5), x);
  EXPECT_NEAR(y[5], 0.5, 1e-6);
}

// The limb's safety task (on the torch-free stand-in model): (θx, θy, θ̇x, θ̇y) over the 30° radius.
TEST(SearchSpace, LearnedLimbPlacesAngleAndRateInRadiusUnits) {
  auto env = envs::make("SmaLimb/LearnedSafety-v0");
  const auto space = search_space_of(*env);
  ASSERT_EQ(space->dimension(), 4);
  EXPECT_EQ(space->names()[0], "theta_x");
  EXPECT_FALSE(space->analytically_safe(Eigen::Vector4d::Zero()).has_value());
  const Eigen::Vector4d s(0.5, -0.25, 0.1, 0.0);  // (15°, −7.5°), θ̇x = 3 °/s
  const Observation x = space->observation(s);
  ASSERT_EQ(x.size(), 5);
  EXPECT_FLOAT_EQ(x[0], 15.0f);
  EXPECT_FLOAT_EQ(x[1], -7.5f);
  EXPECT_FLOAT_EQ(x[2], 3.0f);
  EXPECT_FLOAT_EQ(x[4], 0.0f);
  env->reset(0);
  space->place(*env, s);
  const Step step = env->step(Action::Constant(1, 0.0f));
  EXPECT_LT(std::abs(step.observation[0] - 15.0f), 5.0f);  // one step on from the placed state
  EXPECT_LT(std::abs(step.observation[1] + 7.5f), 5.0f);
}

TEST(SearchSpace, RefusesAnEnvironmentWithoutOne) {
  auto env = envs::make("Pendulum-v1");
  EXPECT_THROW(search_space_of(*env), Error);
}

}  // namespace
}  // namespace tendril::safety
