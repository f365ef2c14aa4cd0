#include "tendril/safety/constraint.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"
#include "tendril/envs/classic_control/pendulum.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::safety {
namespace {

TEST(Constraint, DoubleIntegratorFromTheRegisteredEnvironment) {
  auto env = envs::make("Safety/DoubleIntegrator-v0", Config::parse("horizon: 100"));
  const auto constraint = constraint_of(*env);
  EXPECT_DOUBLE_EQ(constraint->max_margin(), 2.0);
  EXPECT_EQ(constraint->horizon(), 100);
  EXPECT_NEAR(constraint->margin(Eigen::Vector3f(1.5f, 0.5f, 0.25f)), 0.5, 1e-6);
  EXPECT_EQ(constraint->time_step(Eigen::Vector3f(1.5f, 0.5f, 0.25f)), 25);
  EXPECT_TRUE(constraint->unsafe(Eigen::Vector3f(0.0f, 3.5f, 0.0f)));
  Rng rng(3);
  for (int i = 0; i < 100; ++i) {
    const Observation o = constraint->sample_unsafe(rng);
    EXPECT_TRUE(constraint->unsafe(o));
    EXPECT_LE(std::abs(o[0]), 4.0f);
    EXPECT_LE(std::abs(o[1]), 5.0f);
  }
}

TEST(Constraint, DubinsCarAndEnvironmentsWithoutOne) {
  auto env = envs::make("Safety/DubinsCar-v0");
  const auto constraint = constraint_of(*env);
  Observation o(5);
  o << 0.3f, 0.4f, 1.0f, 0.0f, 0.5f;
  EXPECT_NEAR(constraint->margin(o), -0.5, 1e-6);
  EXPECT_EQ(constraint->time_step(o), 100);
  envs::Pendulum pendulum;
  EXPECT_THROW(constraint_of(pendulum), Error);
}

// With the margin observed, unsafe samples carry their own margin, and the positions drawn are
// those of the plain car's stream (the extra entry draws nothing).
TEST(Constraint, DubinsCarUnsafeSamplesCarryTheObservedMargin) {
  auto plain = constraint_of(*envs::make("Safety/DubinsCar-v0"));
  auto with =
      constraint_of(*envs::make("Safety/DubinsCar-v0", Config::parse("observe_margin: true")));
  Rng a(5), b(5);
  for (int i = 0; i < 100; ++i) {
    const Observation o = with->sample_unsafe(a), p = plain->sample_unsafe(b);
    ASSERT_EQ(o.size(), 6);
    EXPECT_EQ(o.head(5), p);
    EXPECT_LE(o[5], 0.0f);
    EXPECT_NEAR(o[5], with->margin(o), 1e-6);
  }
}

}  // namespace
}  // namespace tendril::safety
