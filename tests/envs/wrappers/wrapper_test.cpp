#include "tendril/envs/wrappers/wrapper.hpp"

#include <gtest/gtest.h>

#include "tendril/envs/classic_control/pendulum.hpp"
#include "tendril/envs/wrappers/normalize_observation.hpp"
#include "tendril/envs/wrappers/normalize_reward.hpp"
#include "tendril/envs/wrappers/time_limit.hpp"

namespace tendril::envs {
namespace {

TEST(Wrapper, FindWrapperWalksTheChainFromOutsideIn) {
  auto normalize = std::make_unique<NormalizeObservation>(
      std::make_unique<TimeLimit>(std::make_unique<Pendulum>(), 200));
  NormalizeObservation* expected = normalize.get();
  NormalizeReward env(std::move(normalize));
  EXPECT_EQ(find_wrapper<NormalizeObservation>(env), expected);
  EXPECT_EQ(find_wrapper<NormalizeReward>(env), &env);
  EXPECT_NE(find_wrapper<TimeLimit>(env), nullptr);
  EXPECT_NE(find_wrapper<Pendulum>(env), nullptr);
  Pendulum bare;
  EXPECT_EQ(find_wrapper<TimeLimit>(bare), nullptr);
}

TEST(Wrapper, PassesSpacesThrough) {
  TimeLimit env(std::make_unique<Pendulum>(), 10);
  EXPECT_EQ(env.observation_space().describe(), "Box(3, [-8, 8])");
  EXPECT_EQ(&env.action_space(), &env.inner().action_space());
}

}  // namespace
}  // namespace tendril::envs
