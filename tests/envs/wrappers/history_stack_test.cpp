#include "tendril/envs/wrappers/history_stack.hpp"

#include <gtest/gtest.h>

#include "../scripted_env.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/classic_control/pendulum.hpp"

namespace tendril::envs {
namespace {

using testing::ScriptedEnv;

const Action kAction = Eigen::Vector2f(0.0f, 0.5f);

TEST(HistoryStack, StacksTheLastObservationsOldestFirst) {
  HistoryStack env(std::make_unique<ScriptedEnv>(), 3);
  EXPECT_EQ(env.observation_space().size(), 9);
  // ScriptedEnv observes [steps, resets, seed].
  Eigen::VectorXf expected(9);
  expected << 0, 1, 2, 0, 1, 2, 0, 1, 2;
  EXPECT_EQ(env.reset(2), expected);  // padded with the first observation
  env.step(kAction);
  const Observation second = env.step(kAction).observation;
  expected << 0, 1, 2, 1, 1, 2, 2, 1, 2;
  EXPECT_EQ(second, expected);
  expected << 1, 1, 2, 2, 1, 2, 3, 1, 2;
  EXPECT_EQ(env.step(kAction).observation, expected);
  expected << 0, 2, 2, 0, 2, 2, 0, 2, 2;
  EXPECT_EQ(env.reset(), expected);  // a reset clears the history
}

TEST(HistoryStack, RepeatsTheInnerBounds) {
  HistoryStack env(std::make_unique<Pendulum>(), 2);
  Eigen::VectorXf high(6);
  high << 1, 1, 8, 1, 1, 8;
  EXPECT_EQ(env.observation_space().high(), high);
  EXPECT_EQ(env.observation_space().low(), -high);
  EXPECT_THROW(HistoryStack(std::make_unique<Pendulum>(), 0), Error);
  HistoryStack fresh(std::make_unique<Pendulum>(), 2);
  EXPECT_THROW(fresh.step(Action::Zero(1)), Error);
}

}  // namespace
}  // namespace tendril::envs
