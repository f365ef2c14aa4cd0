#include "tendril/envs/wrappers/time_limit.hpp"

#include <gtest/gtest.h>

#include "../scripted_env.hpp"
#include "tendril/core/error.hpp"

namespace tendril::envs {
namespace {

using testing::ScriptedEnv;

const Action kAction = Eigen::Vector2f(0.0f, 0.5f);

TEST(TimeLimit, TruncatesAtTheLimitOnly) {
  TimeLimit env(std::make_unique<ScriptedEnv>(), 3);
  env.reset(0);
  EXPECT_FALSE(env.step(kAction).truncated);
  EXPECT_FALSE(env.step(kAction).truncated);
  const Step last = env.step(kAction);
  EXPECT_TRUE(last.truncated);
  EXPECT_FALSE(last.terminated);
  EXPECT_EQ(env.elapsed_steps(), 3);
  env.reset();
  EXPECT_EQ(env.elapsed_steps(), 0);
  EXPECT_FALSE(env.step(kAction).truncated);
}

TEST(TimeLimit, TerminationOnTheLastStepIsNotAlsoTruncation) {
  TimeLimit env(std::make_unique<ScriptedEnv>(ScriptedEnv::Options{1.0, 2}), 2);
  env.reset(0);
  env.step(kAction);
  const Step last = env.step(kAction);
  EXPECT_TRUE(last.terminated);
  EXPECT_FALSE(last.truncated);
}

TEST(TimeLimit, TerminationBeforeTheLimitPassesThrough) {
  TimeLimit env(std::make_unique<ScriptedEnv>(ScriptedEnv::Options{1.0, 1}), 5);
  env.reset(0);
  const Step step = env.step(kAction);
  EXPECT_TRUE(step.terminated);
  EXPECT_FALSE(step.truncated);
}

TEST(TimeLimit, RejectsBadLimitsAndStepBeforeReset) {
  EXPECT_THROW(TimeLimit(std::make_unique<ScriptedEnv>(), 0), Error);
  EXPECT_THROW(TimeLimit(nullptr, 5), Error);
  TimeLimit env(std::make_unique<ScriptedEnv>(), 5);
  EXPECT_THROW(env.step(kAction), Error);
}

}  // namespace
}  // namespace tendril::envs
