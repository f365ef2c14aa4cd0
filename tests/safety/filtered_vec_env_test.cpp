#include "tendril/safety/filtered_vec_env.hpp"

#include <gtest/gtest.h>

#include "scripted_critic.hpp"
#include "tendril/core/error.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::safety {
namespace {

// Q_s(x, u) = x₀ − u₀ on the double integrator's observation [x, ẋ, t/T].
using testing::ScriptedCritic;

std::unique_ptr<envs::VecEnv> two_double_integrators() {
  rl::VecEnvOptions options;
  options.id = "Safety/DoubleIntegrator-v0";
  options.params = Config::parse("start_position: 1.0\nstart_velocity: 0.0");
  options.n_envs = 2;
  return rl::make_vec_env(options);
}

TEST(FilteredVecEnv, ExecutesTheProposalAboveTheThresholdAndTheSafeActionAtOrBelow) {
  const ScriptedCritic critic;
  FilteredVecEnv env(
      two_double_integrators(), critic,
      [&critic](const Observation& x) { return critic.safe_action(x); }, 0.0);
  const envs::BatchMatrix start = env.reset(11);
  // Propose u = x₀ − 0.5 to env 0 (Q = 0.5 > 0: passed) and u = x₀ to env 1 (Q = 0: filtered).
  envs::BatchMatrix proposals(2, 1);
  proposals << start(0, 0) - 0.5f, start(1, 0);
  const envs::VecStep& step = env.step(proposals);
  EXPECT_FLOAT_EQ(env.executed_actions()(0, 0), proposals(0, 0));
  EXPECT_FLOAT_EQ(env.executed_actions()(1, 0), -1.0f);
  EXPECT_EQ(env.intervened(), (std::vector<uint8_t>{0, 1}));
  EXPECT_EQ(env.decisions(), 2);
  EXPECT_EQ(env.interventions(), 1);
  // The environments moved with the executed actions: ẋ' = ẋ + a dt from rest.
  EXPECT_NEAR(step.observations(1, 1), -1.0f * 0.05f, 1e-6);
  EXPECT_NEAR(step.observations(0, 1), proposals(0, 0) * 0.05f, 1e-6);
}

TEST(FilteredVecEnv, RefusesAStepBeforeAReset) {
  const ScriptedCritic critic;
  FilteredVecEnv env(
      two_double_integrators(), critic,
      [&critic](const Observation& x) { return critic.safe_action(x); }, 0.0);
  EXPECT_THROW(env.step(envs::BatchMatrix::Zero(2, 1)), Error);
}

}  // namespace
}  // namespace tendril::safety
