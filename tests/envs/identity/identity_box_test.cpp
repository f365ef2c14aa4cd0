#include "tendril/envs/identity/identity_box.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"

namespace tendril::envs {
namespace {

TEST(IdentityBox, RewardsActionsWithinEpsOfTheShownState) {
  IdentityBox env;
  Observation obs = env.reset(5);
  for (int t = 0; t < 100; ++t) {
    const float state = obs[0];
    ASSERT_EQ(state, env.state());
    ASSERT_GE(state, -1.0f);
    ASSERT_LT(state, 1.0f);
    // Cycle through: exact, just inside, just outside the ±0.05 interval.
    const float offsets[] = {0.0f, 0.049f, 0.051f, -0.049f, -0.051f};
    const float offset = offsets[t % 5];
    const Step step = env.step(Action::Constant(1, state + offset));
    ASSERT_EQ(step.reward, std::abs(offset) <= 0.05f ? 1.0 : 0.0) << t << " " << offset;
    ASSERT_FALSE(step.terminated || step.truncated);
    obs = step.observation;
  }
}

TEST(IdentityBox, EpsIsAParameter) {
  const auto env = IdentityBox::create(Config::parse("eps: 0.5"));
  const Observation obs = env->reset(2);
  EXPECT_EQ(env->step(Action::Constant(1, obs[0] + 0.4f)).reward, 1.0);
  EXPECT_THROW(IdentityBox(IdentityBox::Params{0.0}), Error);
}

}  // namespace
}  // namespace tendril::envs
