#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>

#include "tendril/render/image.hpp"

namespace tendril::render {

// A video file written frame by frame by an ffmpeg process (Debian's `ffmpeg`; scripts/setup
// installs it) reading raw RGB frames from a pipe. The container and codec follow the file's
// extension: .mp4 (H.264, yuv420p: plays everywhere), .webm (VP9) or .gif. The video goes to a
// temporary file beside `file` and takes its name only when `finish` succeeds: an existing file
// is never replaced and a failed encoding leaves nothing under the name. Raises Error naming
// the file (and ffmpeg's own message) when ffmpeg is missing or fails.
class VideoWriter {
 public:
  // `width` and `height` must be even (yuv420p); `fps` frames per second, 1 to 240.
  VideoWriter(const std::filesystem::path& file, int width, int height, double fps,
              std::string ffmpeg = "ffmpeg");
  ~VideoWriter();  // abandons an unfinished video (its temporary file is removed)
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  void write(const Image& frame);
  // Closes the stream, waits for ffmpeg and names the file; returns the frames written.
  int finish();

  int frames() const { return frames_; }

 private:
  void abandon();
  std::string ffmpeg_message() const;

  std::filesystem::path file_, partial_, log_;
  int width_, height_;
  int frames_ = 0;
  int pipe_ = -1;
  pid_t process_ = -1;
};

}  // namespace tendril::render
