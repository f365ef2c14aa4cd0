// Episode statistics of the last 100 episodes, including the success rate of environments that
// report "is_success" (SB3's rollout/success_rate) and the curriculum level of environments under
// a curriculum, and their round trip through a checkpoint.
#include "tendril/rl/episode_tracker.hpp"

#include <gtest/gtest.h>

#include "support/scratch_directory.hpp"
#include "tendril/core/archive.hpp"
#include "tendril/envs/wrappers/curriculum.hpp"
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

TEST(EpisodeTracker, CurriculumLevelIsTheMeanOverTheLastHundredEpisodes) {
  EpisodeTracker tracker;
  tracker.record(finished_episode(1.0, -1.0));
  EXPECT_FALSE(tracker.curriculum_level().has_value());  // no curriculum
  auto at_level = [](double level) {
    envs::VecStep step = finished_episode(1.0, -1.0);
    step.infos[0].set(envs::Curriculum::kLevelKey, level);
    return step;
  };
  for (int i = 0; i < 100; ++i) tracker.record(at_level(0.0));
  for (int i = 0; i < 40; ++i) tracker.record(at_level(1.0));
  for (int i = 0; i < 10; ++i) tracker.record(at_level(2.0));
  // The window: 50 episodes at level 0, 40 at 1, 10 at 2.
  ASSERT_TRUE(tracker.curriculum_level().has_value());
  EXPECT_DOUBLE_EQ(*tracker.curriculum_level(), 0.6);
  Progress progress;
  tracker.report(progress);
  EXPECT_EQ(progress.curriculum_level, 0.6);
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

TEST_F(EpisodeTrackerCheckpoint, SuccessesAndLevelsSurviveACheckpointAndOldCheckpointsLoadWithoutThem) {
  EpisodeTracker tracker;
  for (int i = 0; i < 4; ++i) {
    envs::VecStep step = finished_episode(i, i % 2);
    step.infos[0].set(envs::Curriculum::kLevelKey, i < 2 ? 0.0 : 1.0);
    tracker.record(step);
  }
  ArchiveWriter writer("checkpoint");
  tracker.save(writer);
  writer.commit(directory_ / "tracker.pt");
  EpisodeTracker restored;
  const ArchiveReader reader(directory_ / "tracker.pt", "checkpoint");
  restored.prepare_load(reader)();
  EXPECT_EQ(restored.success_rate(), 0.5);
  EXPECT_EQ(restored.curriculum_level(), 0.5);
  EXPECT_EQ(restored.recent_returns(), tracker.recent_returns());

  ArchiveWriter old("checkpoint");
  old.put("episodes", int64_t{2});
  old.put_doubles("recent_returns", std::vector<double>{1.0, 2.0});
  old.put_doubles("recent_lengths", std::vector<double>{5.0, 6.0});
  old.commit(directory_ / "old.pt");
  const ArchiveReader old_reader(directory_ / "old.pt", "checkpoint");
  restored.prepare_load(old_reader)();
  EXPECT_FALSE(restored.success_rate().has_value());
  EXPECT_FALSE(restored.curriculum_level().has_value());
  EXPECT_EQ(restored.episodes(), 2);
}

}  // namespace
}  // namespace tendril::rl
