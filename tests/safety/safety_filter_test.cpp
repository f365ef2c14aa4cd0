#include "tendril/safety/safety_filter.hpp"

#include <gtest/gtest.h>

#include "scripted_critic.hpp"
#include "tendril/core/error.hpp"

namespace tendril::safety {
namespace {

using testing::ScriptedCritic;

TEST(SafetyFilter, PassesTheTaskActionAboveTheThresholdAndOverridesAtOrBelow) {
  const ScriptedCritic critic;
  SafetyFilter filter([](const Observation&) { return Action::Constant(1, 0.5f); }, critic, 1.0);
  // Q = 2 − 0.5 = 1.5 > 1: the task action.
  EXPECT_FLOAT_EQ(filter.act(Observation::Constant(1, 2.0f))[0], 0.5f);
  EXPECT_FALSE(filter.last_intervened());
  // Q = 1.5 − 0.5 = 1 ≤ 1: the safety action (eq. 6.5 intervenes at equality).
  EXPECT_FLOAT_EQ(filter.act(Observation::Constant(1, 1.5f))[0], -1.0f);
  EXPECT_TRUE(filter.last_intervened());
  EXPECT_FLOAT_EQ(filter.act(Observation::Constant(1, 0.0f))[0], -1.0f);
  EXPECT_EQ(filter.decisions(), 3);
  EXPECT_EQ(filter.interventions(), 2);
  EXPECT_NEAR(filter.intervention_rate(), 2.0 / 3.0, 1e-15);
  // A larger ε₂ is more conservative: the first state is now filtered too.
  filter.set_threshold(1.6);
  EXPECT_FLOAT_EQ(filter.act(Observation::Constant(1, 2.0f))[0], -1.0f);
  filter.reset_counts();
  EXPECT_EQ(filter.decisions(), 0);
}

TEST(SafetyFilter, RandomActorStaysInItsSpace) {
  Rng rng(5);
  const TaskActor box = random_actor(Space::box(1, -2.0f, 2.0f), rng);
  const TaskActor discrete = random_actor(Space::discrete(4), rng);
  for (int i = 0; i < 100; ++i) {
    const float a = box(Observation::Zero(1))[0];
    EXPECT_GE(a, -2.0f);
    EXPECT_LT(a, 2.0f);
    const float k = discrete(Observation::Zero(1))[0];
    EXPECT_TRUE(k == 0.0f || k == 1.0f || k == 2.0f || k == 3.0f);
  }
  const ScriptedCritic critic;
  EXPECT_THROW(SafetyFilter(TaskActor(), critic, 0.0), Error);
}

}  // namespace
}  // namespace tendril::safety
