#include "tendril/envs/identity/identity.hpp"

#include <gtest/gtest.h>

#include <set>

#include "tendril/core/error.hpp"

namespace tendril::envs {
namespace {

int64_t hot_index(const Observation& obs) {
  Eigen::Index index = 0;
  obs.maxCoeff(&index);
  return index;
}

TEST(Identity, ObservationIsOneHotOfTheState) {
  Identity env(Identity::Params{5});
  EXPECT_EQ(env.observation_space().describe(), "Box(5, [0, 1])");
  EXPECT_EQ(env.action_space().n(), 5);
  const Observation obs = env.reset(1);
  EXPECT_EQ(obs.sum(), 1.0f);
  EXPECT_EQ(hot_index(obs), env.state());
}

TEST(Identity, RewardsRepeatingTheShownStateAndRedrawsIt) {
  Identity env(Identity::Params{4});
  Observation obs = env.reset(3);
  std::set<int64_t> states;
  for (int t = 0; t < 200; ++t) {
    const int64_t shown = hot_index(obs);
    states.insert(shown);
    const bool repeat = t % 2 == 0;
    const int64_t action = repeat ? shown : (shown + 1) % 4;
    const Step step = env.step(Action::Constant(1, static_cast<float>(action)));
    ASSERT_EQ(step.reward, repeat ? 1.0 : 0.0) << t;
    ASSERT_FALSE(step.terminated || step.truncated);
    obs = step.observation;
    ASSERT_EQ(hot_index(obs), env.state());
  }
  EXPECT_EQ(states.size(), 4u);  // every state comes up
}

TEST(Identity, SameSeedSameStates) {
  Identity a, b;
  EXPECT_EQ(a.reset(11), b.reset(11));
  for (int t = 0; t < 20; ++t) {
    ASSERT_EQ(a.step(Action::Zero(1)).observation, b.step(Action::Zero(1)).observation);
  }
}

TEST(Identity, RejectsInvalidActionsAndSizes) {
  Identity env(Identity::Params{3});
  env.reset(0);
  EXPECT_THROW(env.step(Action::Constant(1, 3.0f)), Error);
  EXPECT_THROW(env.step(Action::Constant(1, -1.0f)), Error);
  EXPECT_THROW(Identity(Identity::Params{0}), Error);
}

}  // namespace
}  // namespace tendril::envs
