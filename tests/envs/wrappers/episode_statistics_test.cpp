#include "tendril/envs/wrappers/episode_statistics.hpp"

#include <gtest/gtest.h>

#include "../scripted_env.hpp"
#include "tendril/envs/wrappers/time_limit.hpp"

namespace tendril::envs {
namespace {

using testing::ScriptedEnv;

const Action kAction = Eigen::Vector2f(0.0f, 0.5f);

TEST(EpisodeStatistics, ReportsReturnLengthAndSuccessAtTheEnd) {
  EpisodeStatistics env(std::make_unique<ScriptedEnv>(ScriptedEnv::Options{0.25, 4}));
  env.reset(0);
  for (int t = 1; t <= 3; ++t) {
    const Step step = env.step(kAction);
    EXPECT_FALSE(step.info.has("episode_return")) << t;
    EXPECT_FALSE(step.info.has("episode_length")) << t;
  }
  const Step last = env.step(kAction);
  ASSERT_TRUE(last.terminated);
  EXPECT_EQ(last.info.get("episode_return"), 1.0);
  EXPECT_EQ(last.info.get("episode_length"), 4.0);
  EXPECT_EQ(last.info.get("is_success"), 1.0);  // from the inner environment
  EXPECT_EQ(env.episode_length(), 0);
}

TEST(EpisodeStatistics, CountsTruncatedEpisodesAndRestartsOnReset) {
  EpisodeStatistics env(std::make_unique<TimeLimit>(std::make_unique<ScriptedEnv>(), 3));
  env.reset(0);
  env.step(kAction);
  env.reset(1);  // an unfinished episode is discarded
  env.step(kAction);
  env.step(kAction);
  const Step last = env.step(kAction);
  ASSERT_TRUE(last.truncated);
  EXPECT_EQ(last.info.get("episode_return"), 3.0);
  EXPECT_EQ(last.info.get("episode_length"), 3.0);
  EXPECT_FALSE(last.info.has("is_success"));
}

}  // namespace
}  // namespace tendril::envs
