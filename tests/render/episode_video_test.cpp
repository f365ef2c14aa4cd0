// Episode videos: encoded by ffmpeg, read back by ffprobe (codec, size, frame count, duration);
// nothing is overwritten and bad requests are refused by name.
#include "tendril/render/episode_video.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/render/video_writer.hpp"

namespace tendril::render {
namespace {

namespace fs = std::filesystem;

class EpisodeVideo : public testing::ScratchDirectoryTest {
 protected:
  EpisodeVideo() : ScratchDirectoryTest("episode_video_test") {}
};

std::string run(const std::string& command) {
  std::string output;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return "cannot run";
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  ::pclose(pipe);
  return output;
}

// An arm bending over 2 s at 100 steps per second (201 frames), with a target moving in a circle.
Episode bending_arm() {
  Episode episode;
  episode.metadata = {{"env", "test"}};
  for (int step = 0; step <= 200; ++step) {
    EpisodeFrame frame;
    frame.step = step;
    frame.scene.time = 0.01 * step;
    Scene::Rod rod;
    rod.role = "arm";
    rod.centreline.resize(3, 21);
    const double curvature = 1.5 * step / 200.0;
    for (int k = 0; k <= 20; ++k) {
      const double s = 0.05 * k;
      rod.centreline.col(k) = curvature > 1e-9
                                  ? Eigen::Vector3d((1.0 - std::cos(curvature * s)) / curvature,
                                                    0.0, std::sin(curvature * s) / curvature)
                                  : Eigen::Vector3d(0.0, 0.0, s);
    }
    rod.radii = Eigen::VectorXd::Constant(1, 0.03);
    frame.scene.rods.push_back(rod);
    const double angle = 0.02 * step;
    frame.scene.spheres.push_back(
        {"target", {0.5 * std::cos(angle), 0.5 * std::sin(angle), 0.6}, 0.04});
    episode.frames.push_back(std::move(frame));
  }
  return episode;
}

// ffprobe's answer for one stream entry.
std::string probe(const fs::path& file, const std::string& entry) {
  std::string out =
      run(std::string(TENDRIL_FFPROBE) +
          " -v error -count_frames -select_streams v:0 -show_entries stream=" + entry +
          " -of default=noprint_wrappers=1:nokey=1 " + file.string());
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

// In real time (speed 1), 2 s at 100 steps per second, capped at 30 fps: 61 frames (0 s, 1/30 s,
// …, 2 s) of 320 × 240 in H.264.
TEST_F(EpisodeVideo, Mp4IsReadableWithTheEpisodesTiming) {
  const fs::path file = directory_ / "arm.mp4";
  VideoOptions options;
  options.raster.width = 320;
  options.raster.height = 240;
  options.speed = 1.0;
  options.ffmpeg = TENDRIL_FFMPEG;
  EXPECT_EQ(write_episode_video(bending_arm(), file, options), 61);
  ASSERT_TRUE(fs::exists(file));
  EXPECT_EQ(probe(file, "codec_name"), "h264");
  EXPECT_EQ(probe(file, "width"), "320");
  EXPECT_EQ(probe(file, "height"), "240");
  EXPECT_EQ(probe(file, "nb_read_frames"), "61");
  EXPECT_EQ(probe(file, "avg_frame_rate"), "30/1");
  for (const auto& entry : fs::directory_iterator(directory_)) {  // no temporary files left
    EXPECT_EQ(entry.path().filename(), "arm.mp4");
  }
}

// At half speed and a fixed 10 fps: 4 s of video, 41 frames; as a GIF too.
TEST_F(EpisodeVideo, SpeedAndFrameRateChooseTheFrames) {
  VideoOptions options;
  options.raster.width = 160;
  options.raster.height = 120;
  options.raster.supersample = 1;
  options.fps = 10.0;
  options.speed = 0.5;
  options.ffmpeg = TENDRIL_FFMPEG;
  EXPECT_EQ(write_episode_video(bending_arm(), directory_ / "slow.gif", options), 41);
  EXPECT_EQ(probe(directory_ / "slow.gif", "nb_read_frames"), "41");
}

// By default every step is a frame: 201 frames at 30 fps (the recording's 100 Hz is faster than
// 30, so the video plays in slow motion).
TEST_F(EpisodeVideo, DefaultShowsEveryStep) {
  VideoOptions options;
  options.raster.width = 160;
  options.raster.height = 120;
  options.raster.supersample = 1;
  options.ffmpeg = TENDRIL_FFMPEG;
  EXPECT_EQ(write_episode_video(bending_arm(), directory_ / "steps.mp4", options), 201);
  EXPECT_EQ(probe(directory_ / "steps.mp4", "nb_read_frames"), "201");
  EXPECT_EQ(probe(directory_ / "steps.mp4", "avg_frame_rate"), "30/1");
}

TEST_F(EpisodeVideo, NeverOverwritesAndRefusesBadRequests) {
  VideoOptions options;
  options.raster.width = 160;
  options.raster.height = 120;
  options.ffmpeg = TENDRIL_FFMPEG;
  std::ofstream(directory_ / "kept.mp4") << "kept";
  EXPECT_NE(testing::error_message([&] {
              write_episode_video(bending_arm(), directory_ / "kept.mp4", options);
            }).find("exists already"),
            std::string::npos);
  EXPECT_EQ(fs::file_size(directory_ / "kept.mp4"), 4u);
  EXPECT_NE(testing::error_message([&] {
              write_episode_video(bending_arm(), directory_ / "arm.avi", options);
            }).find(".mp4"),
            std::string::npos);
  Episode empty_scenes = bending_arm();
  for (EpisodeFrame& frame : empty_scenes.frames) frame.scene = Scene();
  EXPECT_NE(testing::error_message([&] {
              write_episode_video(empty_scenes, directory_ / "none.mp4", options);
            }).find("no scene"),
            std::string::npos);
  options.raster.width = 161;
  EXPECT_NE(testing::error_message([&] {
              write_episode_video(bending_arm(), directory_ / "odd.mp4", options);
            }).find("even"),
            std::string::npos);
  options.raster.width = 160;
  options.ffmpeg = "/nonexistent/ffmpeg";
  EXPECT_NE(testing::error_message([&] {
              write_episode_video(bending_arm(), directory_ / "no_ffmpeg.mp4", options);
            }).find("cannot run"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(directory_ / "no_ffmpeg.mp4"));
}

}  // namespace
}  // namespace tendril::render
