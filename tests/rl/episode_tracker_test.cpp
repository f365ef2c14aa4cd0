// Episode statistics of the last 100 episodes, including the success rate of environments that
// report "is_success" (SB3's rollout/success_rate), and their round trip through a checkpoint.
#include "tendril/rl/episode_tracker.hpp"

#include <gtest/gtest.h>

#include "support/scratch_directory.hpp"
#include "tendril/core/archive.hpp"
#include "tendril/envs/wrappers/episode_statistics.hpp"

namespace tendril::rl {
namespace {

// One env that finishes an episode on this step, reporting `success` unless it is negative.
envs::VecStep finished_episode(double episode_return, double success) {
  envs::VecStep step;
  step.terminated = {1};
  step.truncated = {0};
  step.infos.resize(1);
  step.infos[0].set(envs::EpisodeStatistics::kReturnKey, episode_return);
  step.infos[0].set(envs::EpisodeStatistics::kLengthKey, 10.0);
  if (success >= 0.0) step.infos[0].set("is_success", success);
  return step;
}

TEST(EpisodeTracker, SuccessRateIsTheFractionOfTheLastHundredEpisodesThatSucceeded) {
  EpisodeTracker tracker;
  tracker.record(finished_episode(1.0, -1.0));
  EXPECT_FALSE(tracker.success_rate().has_value());  // the env reports no successes
  for (int i = 0; i < 100; ++i) tracker.record(finished_episode(1.0, 0.0));
  for (int i = 0; i < 25; ++i) tracker.record(finished_episode(1.0, 1.0));
  // The window holds the last 75 failures and the 25 successes.
  ASSERT_TRUE(tracker.success_rate().has_value());
  EXPECT_DOUBLE_EQ(*tracker.success_rate(), 0.25);
  Progress progress;
  tracker.report(progress);
  EXPECT_EQ(progress.success_rate, 0.25);
  EXPECT_EQ(progress.episodes, 126);
}

TEST(EpisodeTracker, AnEpisodeStillRunningIsNotCounted) {
  EpisodeTracker tracker;
  envs::VecStep running = finished_episode(1.0, 1.0);
  running.terminated = {0};
  tracker.record(running);
  EXPECT_FALSE(tracker.success_rate().has_value());
  EXPECT_EQ(tracker.episodes(), 0);
}

class EpisodeTrackerCheckpoint : public testing::ScratchDirectoryTest {
 protected:
  EpisodeTrackerCheckpoint() : ScratchDirectoryTest("episode_tracker") {}
};

TEST_F(EpisodeTrackerCheckpoint, SuccessesSurviveACheckpointAndOldCheckpointsLoadWithoutThem) {
  EpisodeTracker tracker;
  for (int i = 0; i < 4; ++i) tracker.record(finished_episode(i, i % 2));
  ArchiveWriter writer("checkpoint");
  tracker.save(writer);
  writer.commit(directory_ / "tracker.pt");
  EpisodeTracker restored;
  const ArchiveReader reader(directory_ / "tracker.pt", "checkpoint");
  restored.prepare_load(reader)();
  EXPECT_EQ(restored.success_rate(), 0.5);
  EXPECT_EQ(restored.recent_returns(), tracker.recent_returns());

  ArchiveWriter old("checkpoint");
  old.put("episodes", int64_t{2});
  old.put_doubles("recent_returns", std::vector<double>{1.0, 2.0});
  old.put_doubles("recent_lengths", std::vector<double>{5.0, 6.0});
  old.commit(directory_ / "old.pt");
  const ArchiveReader old_reader(directory_ / "old.pt", "checkpoint");
  restored.prepare_load(old_reader)();
  EXPECT_FALSE(restored.success_rate().has_value());
  EXPECT_EQ(restored.episodes(), 2);
}

}  // namespace
}  // namespace tendril::rl
