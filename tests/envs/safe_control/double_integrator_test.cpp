#include "tendril/envs/safe_control/double_integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "tendril/core/error.hpp"

namespace tendril::envs::safe_control {
namespace {

TEST(DoubleIntegrator, OneStepIsTheExactZeroOrderHold) {
  DoubleIntegrator env;
  env.reset(0);
  env.set_state(0.5, -1.0, 10);
  const Step step = env.step(Action::Constant(1, 2.0f));
  // x' = 0.5 − 1·0.05 + ½·2·0.0025 = 0.4525, ẋ' = −1 + 0.1 = −0.9.
  EXPECT_NEAR(env.position(), 0.4525, 1e-15);
  EXPECT_NEAR(env.velocity(), -0.9, 1e-15);
  EXPECT_NEAR(step.reward, -std::abs(0.4525 - 1.8), 1e-15);
  EXPECT_FLOAT_EQ(step.observation[2], 11.0f / 200.0f);
  // d = min(2 − 0.4525, 3 − 0.9) = 1.5475.
  EXPECT_NEAR(*step.info.get("safety_margin"), 1.5475, 1e-12);
  EXPECT_EQ(*step.info.get("unsafe"), 0.0);
  EXPECT_FALSE(step.terminated);
}

TEST(DoubleIntegrator, MarginIsTheSmallerConstraintAndZeroCountsUnsafe) {
  const DoubleIntegrator::Params p;
  EXPECT_DOUBLE_EQ(DoubleIntegrator::safety_margin(p, 1.5, 0.0), 0.5);
  EXPECT_NEAR(DoubleIntegrator::safety_margin(p, 0.0, -2.8), 0.2, 1e-12);  // 3 − 2.8 rounds
  EXPECT_DOUBLE_EQ(DoubleIntegrator::safety_margin(p, -2.5, 0.0), -0.5);
  EXPECT_DOUBLE_EQ(DoubleIntegrator::max_safety_margin(p), 2.0);

  DoubleIntegrator env;
  env.reset(1);
  env.set_state(2.0 - 0.05 * 1.0, 1.0);  // one step at a = 0 lands on x = 2 exactly
  const Step step = env.step(Action::Constant(1, 0.0f));
  EXPECT_NEAR(*step.info.get("safety_margin"), 0.0, 1e-12);
  EXPECT_EQ(*step.info.get("cost"), 1.0);
  EXPECT_FALSE(step.terminated);  // unsafe is not the end: only the absolute bounds are
}

TEST(DoubleIntegrator, AnalyticSetIsTheBrakingParabola) {
  const DoubleIntegrator::Params p;
  // x ≤ 2 − ẋ²/4 for ẋ ≥ 0: at ẋ = 2 the boundary is x = 1.
  EXPECT_TRUE(DoubleIntegrator::in_analytic_safe_set(p, 0.99, 2.0));
  EXPECT_FALSE(DoubleIntegrator::in_analytic_safe_set(p, 1.01, 2.0));
  EXPECT_TRUE(DoubleIntegrator::in_analytic_safe_set(p, -0.99, -2.0));
  EXPECT_FALSE(DoubleIntegrator::in_analytic_safe_set(p, -1.01, -2.0));
  // Moving away from the near wall is always fine inside the box.
  EXPECT_TRUE(DoubleIntegrator::in_analytic_safe_set(p, 1.9, -2.0));
  EXPECT_FALSE(DoubleIntegrator::in_analytic_safe_set(p, 0.0, 3.0));

  // Full braking from just inside stays safe for the whole horizon; from just outside it
  // enters the unsafe set: the set is exactly viable under the exact discretisation.
  for (const double velocity : {0.5, 1.5, 2.5}) {
    const double boundary = 2.0 - velocity * velocity / 4.0;
    for (const double offset : {-0.02, 0.02}) {
      DoubleIntegrator env;
      env.reset(0);
      env.set_state(boundary + offset, velocity);
      bool entered_unsafe = false;
      for (int t = 0; t < 100; ++t) {
        const double a = env.velocity() > 0.0 ? -2.0 : 0.0;
        const Step step = env.step(Action::Constant(1, static_cast<float>(a)));
        if (*step.info.get("unsafe") > 0.0) entered_unsafe = true;
        if (env.velocity() <= 0.0) env.set_state(env.position(), 0.0);
      }
      EXPECT_EQ(entered_unsafe, offset > 0.0) << "v = " << velocity << ", offset " << offset;
    }
  }
}

TEST(DoubleIntegrator, DiscreteActionsAreEvenlySpaced) {
  DoubleIntegrator::Params p;
  p.discrete_actions = 5;
  DoubleIntegrator env(p);
  EXPECT_TRUE(env.action_space().is_discrete());
  EXPECT_DOUBLE_EQ(env.acceleration(Action::Constant(1, 0.0f)), -2.0);
  EXPECT_DOUBLE_EQ(env.acceleration(Action::Constant(1, 3.0f)), 1.0);
  EXPECT_THROW(env.acceleration(Action::Constant(1, 5.0f)), Error);
}

TEST(DoubleIntegrator, TerminatesBeyondAbsoluteBoundsAndTruncatesAtHorizon) {
  DoubleIntegrator::Params p;
  p.horizon = 3;
  DoubleIntegrator env(p);
  env.reset(2);
  env.set_state(0.0, 0.0);
  Step step;
  for (int t = 0; t < 3; ++t) step = env.step(Action::Constant(1, 0.0f));
  EXPECT_TRUE(step.truncated);
  EXPECT_FALSE(step.terminated);
  env.set_state(3.99, 4.9);
  step = env.step(Action::Constant(1, 2.0f));
  EXPECT_TRUE(step.terminated);
}

TEST(DoubleIntegrator, StartsInTheSafeBoxAndRejectsBadParams) {
  DoubleIntegrator env;
  for (uint64_t seed = 0; seed < 50; ++seed) {
    const Observation o = env.reset(seed);
    EXPECT_LE(std::abs(o[0]), 2.0f);
    EXPECT_LE(std::abs(o[1]), 3.0f);
    EXPECT_EQ(o[2], 0.0f);
  }
  EXPECT_THROW(DoubleIntegrator::create(Config::parse("dt: -1")), Error);
  EXPECT_THROW(DoubleIntegrator::create(Config::parse("horizn: 10")), Error);
  EXPECT_THROW(DoubleIntegrator::create(Config::parse("absolute_position_limit: 1.5")), Error);
}

// The reward-penalty baseline: the same step, with the penalty only where x' is unsafe.
TEST(DoubleIntegrator, UnsafePenaltyIsSubtractedOnlyInTheUnsafeSet) {
  DoubleIntegrator::Params penalized;
  penalized.unsafe_penalty = 10.0;
  DoubleIntegrator plain, with_penalty(penalized);
  for (DoubleIntegrator* env : {&plain, &with_penalty}) env->reset(0);
  for (auto [x, v] : {std::pair{0.5, 0.0}, std::pair{1.99, 2.0}}) {
    plain.set_state(x, v);
    with_penalty.set_state(x, v);
    const Step a = plain.step(Action::Constant(1, 0.0f));
    const Step b = with_penalty.step(Action::Constant(1, 0.0f));
    EXPECT_DOUBLE_EQ(a.info.get("unsafe").value(), x > 1.0 ? 1.0 : 0.0);
    EXPECT_DOUBLE_EQ(b.reward, a.reward - 10.0 * a.info.get("unsafe").value());
  }
}

}  // namespace
}  // namespace tendril::envs::safe_control
