#include "tendril/render/video_writer.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iterator>
#include <vector>

#include "tendril/core/error.hpp"

extern char** environ;

namespace tendril::render {

namespace fs = std::filesystem;

namespace {

// ffmpeg's output options for a container: H.264 in yuv420p for .mp4 (what browsers and
// players take), VP9 for .webm, a palette for .gif.
std::vector<std::string> codec_options(const std::string& extension, const std::string& file) {
  if (extension == ".mp4" || extension == ".mov" || extension == ".mkv") {
    return {"-c:v", "libx264",  "-preset", "veryfast",  "-crf",
            "20",   "-pix_fmt", "yuv420p", "-movflags", "+faststart"};
  }
  if (extension == ".webm")
    return {"-c:v", "libvpx-vp9", "-b:v",    "0",         "-crf",
            "34",   "-pix_fmt",   "yuv420p", "-deadline", "realtime"};
  if (extension == ".gif") {
    return {"-vf", "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse"};
  }
  throw Error("a video is .mp4, .mkv, .mov, .webm or .gif, not '" + extension + "'", file);
}

// Writes all of `bytes` to `fd`; false when the reader has gone (EPIPE). SIGPIPE is held back for
// the call, so a dead ffmpeg becomes an error here instead of ending the process.
bool write_all(int fd, const uint8_t* bytes, std::size_t size) {
  sigset_t pipe_signal, previous;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_signal, &previous);
  bool ok = true;
  while (size > 0) {
    const ssize_t written = ::write(fd, bytes, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      ok = false;
      break;
    }
    bytes += written;
    size -= static_cast<std::size_t>(written);
  }
  if (!ok) {  // take the pending SIGPIPE (if this write raised one) before unblocking
    const timespec zero{0, 0};
    while (sigtimedwait(&pipe_signal, nullptr, &zero) == SIGPIPE) {
    }
  }
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  return ok;
}

}  // namespace

VideoWriter::VideoWriter(const fs::path& file, int width, int height, double fps,
                         std::string ffmpeg)
    : file_(file), width_(width), height_(height) {
  const std::string where = file.string();
  require(width > 0 && height > 0 && width % 2 == 0 && height % 2 == 0,
          "video frames must have an even, positive width and height, not " +
              std::to_string(width) + "x" + std::to_string(height),
          where);
  require(fps >= 1.0 && fps <= 240.0, "frames per second must lie in 1..240", where);
  if (fs::exists(file)) throw Error("exists already; not overwriting it", where);
  const std::vector<std::string> codec = codec_options(file.extension().string(), where);
  const std::string stem = file.stem().string() + ".partial-" + std::to_string(::getpid());
  partial_ = file.parent_path() / (stem + file.extension().string());
  log_ = file.parent_path() / (stem + ".log");
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.6g", fps);
  std::vector<std::string> words = {ffmpeg,
                                    "-hide_banner",
                                    "-loglevel",
                                    "error",
                                    "-y",
                                    "-f",
                                    "rawvideo",
                                    "-pix_fmt",
                                    "rgb24",
                                    "-s",
                                    std::to_string(width) + "x" + std::to_string(height),
                                    "-r",
                                    rate,
                                    "-i",
                                    "pipe:0"};
  words.insert(words.end(), codec.begin(), codec.end());
  words.push_back(partial_.string());

  int ends[2];
  require(::pipe2(ends, O_CLOEXEC) == 0, std::string("cannot make a pipe: ") + std::strerror(errno),
          where);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, ends[0], 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const int spawned =
      ::posix_spawnp(&process_, ffmpeg.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(ends[0]);
  if (spawned != 0) {
    ::close(ends[1]);
    process_ = -1;
    std::error_code ignored;
    fs::remove(log_, ignored);
    throw Error("cannot run " + ffmpeg + ": " + std::strerror(spawned) +
                    " (scripts/setup installs Debian's ffmpeg)",
                where);
  }
  pipe_ = ends[1];
}

VideoWriter::~VideoWriter() { abandon(); }

std::string VideoWriter::ffmpeg_message() const {
  std::ifstream in(log_);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text.empty() ? "no message" : text;
}

void VideoWriter::write(const Image& frame) {
  require(pipe_ >= 0, "the video is finished", file_.string());
  require(frame.width == width_ && frame.height == height_,
          "a frame of " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
              " in a video of " + std::to_string(width_) + "x" + std::to_string(height_),
          file_.string());
  if (!write_all(pipe_, frame.rgb.data(), frame.rgb.size())) {
    const std::string message = "ffmpeg stopped reading frames: ";
    ::close(pipe_);
    pipe_ = -1;
    int status = 0;
    ::waitpid(process_, &status, 0);
    process_ = -1;
    const std::string reason = ffmpeg_message();
    abandon();
    throw Error(message + reason, file_.string());
  }
  ++frames_;
}

int VideoWriter::finish() {
  const std::string where = file_.string();
  require(pipe_ >= 0, "the video is finished", where);
  ::close(pipe_);
  pipe_ = -1;
  int status = 0;
  while (::waitpid(process_, &status, 0) < 0 && errno == EINTR) {
  }
  process_ = -1;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || frames_ == 0) {
    const std::string reason = frames_ == 0 ? "no frames" : ffmpeg_message();
    abandon();
    throw Error("ffmpeg could not encode the video: " + reason, where);
  }
  // The last step must not replace a file that appeared meanwhile: a hard link fails if it does.
  if (::link(partial_.c_str(), file_.c_str()) != 0) {
    const std::string reason = errno == EEXIST
                                   ? "exists already; not overwriting it"
                                   : std::string("cannot name it: ") + std::strerror(errno);
    abandon();
    throw Error(reason, where);
  }
  std::error_code ignored;
  fs::remove(partial_, ignored);
  fs::remove(log_, ignored);
  return frames_;
}

void VideoWriter::abandon() {
  if (pipe_ >= 0) {
    ::close(pipe_);
    pipe_ = -1;
  }
  if (process_ > 0) {
    int status = 0;
    ::waitpid(process_, &status, 0);
    process_ = -1;
  }
  std::error_code ignored;
  if (!partial_.empty()) fs::remove(partial_, ignored);
  if (!log_.empty()) fs::remove(log_, ignored);
}

}  // namespace tendril::render
