#include "tendril/envs/wrappers/episode_recorder.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "envs/scripted_env.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/episode_reader.hpp"

namespace tendril::envs {
namespace {

namespace fs = std::filesystem;

// The scripted environment with a scene: a sphere whose height is the number of steps taken.
class DrawnEnv : public testing::ScriptedEnv {
 public:
  explicit DrawnEnv(Options options) : ScriptedEnv(options) {}
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override {
    steps_ = 0;
    return ScriptedEnv::reset(seed);
  }
  Step step(const Action& action) override {
    ++steps_;
    return ScriptedEnv::step(action);
  }
  bool describe_scene(Scene& scene) const override {
    scene.time = 0.5 * steps_;
    scene.spheres.push_back({"target", Eigen::Vector3d(0.0, 0.0, steps_), 0.1});
    return true;
  }

 private:
  int steps_ = 0;
};

class EpisodeRecorderTest : public tendril::testing::ScratchDirectoryTest {
 protected:
  EpisodeRecorderTest() : ScratchDirectoryTest("episode_recorder") {}
  RecordingOptions options() const {
    return {directory_ / "episodes", "episode", {{"env", "Drawn"}}};
  }
};

TEST_F(EpisodeRecorderTest, WritesEachEpisodeWithItsScenesActionsAndRewards) {
  EpisodeRecorder env(std::make_unique<DrawnEnv>(DrawnEnv::Options{2.5, 3}), options());
  env.reset(7);
  const std::vector<Action> actions = {Eigen::Vector2f(0.5f, 0.25f), Eigen::Vector2f(-1.0f, 1.0f),
                                       Eigen::Vector2f(2.0f, 0.0f)};
  for (const Action& action : actions) env.step(action);
  ASSERT_EQ(env.episodes().size(), 1u);
  EXPECT_EQ(env.episodes()[0].file, directory_ / "episodes" / "episode_0000.tep");
  EXPECT_EQ(env.episodes()[0].summary.episode_return, 7.5);
  EXPECT_TRUE(env.episodes()[0].summary.terminated);

  const Episode episode = read_episode(env.episodes()[0].file);
  EXPECT_EQ(episode.meta("env"), "Drawn");
  EXPECT_EQ(episode.meta("reset_seed"), "7");
  ASSERT_EQ(episode.frames.size(), 4u);  // the state after reset and one per step
  EXPECT_EQ(episode.frames[0].action.size(), 0);
  for (int k = 0; k < 4; ++k) {
    const EpisodeFrame& frame = episode.frames[k];
    EXPECT_EQ(frame.step, k);
    EXPECT_EQ(frame.scene.time, 0.5 * k);
    ASSERT_EQ(frame.scene.spheres.size(), 1u);
    EXPECT_EQ(frame.scene.spheres[0].centre.z(), k);
    if (k == 0) continue;
    EXPECT_EQ(frame.action, actions[k - 1]);
    EXPECT_EQ(frame.reward, 2.5);
  }
  EXPECT_TRUE(episode.frames[3].terminated);
  ASSERT_EQ(episode.frames[3].info.size(), 1u);
  EXPECT_EQ(episode.frames[3].info[0].first, "is_success");
  EXPECT_EQ(episode.frames[3].info[0].second, 1.0);
}

TEST_F(EpisodeRecorderTest, TakesTheFirstFreeNumbersAndOverwritesNothing) {
  fs::create_directories(directory_ / "episodes");
  std::ofstream(directory_ / "episodes" / "episode_0000.tep") << "kept";
  EpisodeRecorder env(std::make_unique<DrawnEnv>(DrawnEnv::Options{1.0, 2}), options());
  for (int e = 0; e < 2; ++e) {
    env.reset();
    env.step(Eigen::Vector2f::Zero());
    env.step(Eigen::Vector2f::Zero());
  }
  ASSERT_EQ(env.episodes().size(), 2u);
  EXPECT_EQ(env.episodes()[0].file.filename(), "episode_0001.tep");
  EXPECT_EQ(env.episodes()[1].file.filename(), "episode_0002.tep");
  std::ifstream kept(directory_ / "episodes" / "episode_0000.tep");
  std::string text;
  kept >> text;
  EXPECT_EQ(text, "kept");
}

TEST_F(EpisodeRecorderTest, AnEpisodeCutOffByAResetStaysIncomplete) {
  EpisodeRecorder env(std::make_unique<DrawnEnv>(DrawnEnv::Options{1.0, 5}), options());
  env.reset();
  env.step(Eigen::Vector2f::Zero());
  env.reset();
  const PartialEpisode cut = read_partial_episode(directory_ / "episodes" / "episode_0000.tep");
  EXPECT_TRUE(cut.truncated);
  EXPECT_EQ(cut.episode.frames.size(), 2u);
  EXPECT_TRUE(env.episodes().empty());
}

TEST_F(EpisodeRecorderTest, RecordEpisodesRunsAPolicyOnAnEnvironmentItDoesNotOwn) {
  DrawnEnv env(DrawnEnv::Options{-1.0, 4});
  int calls = 0;
  const auto act = [&](const Observation& observation) {
    ++calls;
    return Action(Eigen::Vector2f(observation(0), 0.5f));  // the step count, as the observation
  };
  const std::vector<RecordedEpisode> episodes = record_episodes(env, act, 2, 11, options());
  EXPECT_EQ(calls, 8);
  ASSERT_EQ(episodes.size(), 2u);
  for (const RecordedEpisode& recorded : episodes) {
    EXPECT_EQ(recorded.summary.episode_return, -4.0);
    const Episode episode = read_episode(recorded.file);
    ASSERT_EQ(episode.frames.size(), 5u);
    for (int k = 1; k < 5; ++k) EXPECT_EQ(episode.frames[k].action(0), k - 1);
  }
  EXPECT_EQ(read_episode(episodes[0].file).meta("reset_seed"), "11");
  EXPECT_EQ(read_episode(episodes[1].file).meta("reset_seed"), "");  // later resets unseeded
}

}  // namespace
}  // namespace tendril::envs
