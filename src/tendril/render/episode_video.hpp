#pragma once

#include <filesystem>
#include <string>

#include "tendril/core/episode.hpp"
#include "tendril/render/scene_rasterizer.hpp"

namespace tendril::render {

struct VideoOptions {
  RasterOptions raster;  // size (even) and anti-aliasing of the frames
  // Frames per second of the video; 0: the recording's own rate (one video frame per step)
  // up to `max_fps`, past which steps are skipped so that the video keeps the episode's time.
  double fps = 0.0;
  double max_fps = 30.0;
  double speed = 1.0;  // episode seconds per video second
  bool trails = true;  // the paths of the first rod's tip and of each target up to now
  std::string ffmpeg = "ffmpeg";
};

// A video of a recorded episode (docs/episode_format.md), every frame from one fixed view of
// the whole episode (frame_scenes), encoded by ffmpeg (VideoWriter: .mp4, .webm or .gif; an
// existing file is never replaced). Returns the number of video frames. Raises Error naming the
// file when the episode has no scene to draw.
int write_episode_video(const Episode& episode, const std::filesystem::path& file,
                        const VideoOptions& options = {});

}  // namespace tendril::render
