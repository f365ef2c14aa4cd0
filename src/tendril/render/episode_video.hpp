#pragma once

#include <filesystem>
#include <string>

#include "tendril/core/episode.hpp"
#include "tendril/render/scene_rasterizer.hpp"

namespace tendril::render {

struct VideoOptions {
  RasterOptions raster;  // size (even) and anti-aliasing of the frames
  // Episode seconds per video second. 0: one video frame per step, at the recording's own rate
  // up to `max_fps` — real time for environments that step at most `max_fps` times a second,
  // slow motion for faster ones (the Elastica arms step every 1.4 ms: a 200-step episode is
  // 0.28 s, which real time would show in 9 frames). Otherwise frames are picked by time.
  double speed = 0.0;
  double fps = 0.0;  // frames per second of the video; 0: the rate described above
  double max_fps = 30.0;
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
