#include <gtest/gtest.h>

#include "elastica_test_support.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/episode_reader.hpp"
#include "tendril/envs/wrappers/episode_recorder.hpp"

namespace tendril::envs::elastica {
namespace {

class ElasticaRecordingTest : public tendril::testing::ScratchDirectoryTest {
 protected:
  ElasticaRecordingTest() : ScratchDirectoryTest("elastica_recording") {}
};

// A recorded case-3 episode replays the arm, target and the obstacles as the environment
// described them at every step, through float32.
TEST_F(ElasticaRecordingTest, RecordsWhatTheEnvironmentDescribesEachStep) {
  auto made = testing::make_case("Elastica/StructuredObstacles-v0", "{max_episode_steps: 12}");
  std::vector<Scene> described;
  const auto act = [&](const Observation&) {
    described.emplace_back();
    made.env->describe_scene(described.back());
    return Action(Action::Constant(made.env->action_space().size(), 0.6f));
  };
  const auto episodes =
      record_episodes(*made.env, act, 1, 3, {directory_, "case3", {{"env", "case 3"}}});
  Scene last;
  made.env->describe_scene(last);
  described.push_back(last);

  ASSERT_EQ(episodes.size(), 1u);
  const Episode episode = read_episode(episodes[0].file);
  ASSERT_EQ(episode.frames.size(), 13u);
  EXPECT_TRUE(episode.frames.back().truncated);
  for (size_t k = 0; k < episode.frames.size(); ++k) {
    const Scene& read = episode.frames[k].scene;
    const Scene& expected = described[k];
    EXPECT_EQ(read.time, expected.time);
    ASSERT_EQ(read.rods.size(), 1u);
    EXPECT_EQ(Eigen::MatrixXd(read.rods[0].centreline),
              expected.rods[0].centreline.cast<float>().cast<double>());
    EXPECT_EQ(Eigen::MatrixXd(read.spheres[0].centre),
              expected.spheres[0].centre.cast<float>().cast<double>());
    ASSERT_EQ(read.cylinders.size(), expected.cylinders.size());
    EXPECT_GT(read.cylinders.size(), 0u);
    for (size_t c = 0; c < read.cylinders.size(); ++c) {
      EXPECT_EQ(Eigen::MatrixXd(read.cylinders[c].end),
                expected.cylinders[c].end.cast<float>().cast<double>());
    }
  }
}

}  // namespace
}  // namespace tendril::envs::elastica
