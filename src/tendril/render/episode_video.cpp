#include "tendril/render/episode_video.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/render/video_writer.hpp"

namespace tendril::render {

namespace {

bool draws_something(const Scene& s) {
  return !s.rods.empty() || !s.spheres.empty() || !s.cylinders.empty() || !s.boxes.empty() ||
         !s.planes.empty() || !s.lattices.empty() || !s.paths.empty();
}

// The median time between consecutive frames (s); 0 when the recording has no clock.
double step_seconds(const Episode& episode) {
  std::vector<double> steps;
  for (std::size_t k = 1; k < episode.frames.size(); ++k) {
    const double dt = episode.frames[k].scene.time - episode.frames[k - 1].scene.time;
    if (dt > 0.0 && std::isfinite(dt)) steps.push_back(dt);
  }
  if (steps.empty()) return 0.0;
  std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
  return steps[steps.size() / 2];
}

// Adds to `scene` the paths, up to frame `upto`, of the first rod's tip and of each sphere whose
// role is a target or a goal.
void add_trails(const Episode& episode, std::size_t upto, Scene& scene) {
  const Scene& first = episode.frames.front().scene;
  if (!first.rods.empty()) {
    Scene::Path tip{first.rods.front().role, Eigen::Matrix3Xd(3, 0)};
    std::vector<Eigen::Vector3d> points;
    for (std::size_t k = 0; k <= upto; ++k) {
      const auto& rods = episode.frames[k].scene.rods;
      if (!rods.empty() && rods.front().centreline.cols() > 0) {
        points.push_back(rods.front().centreline.col(rods.front().centreline.cols() - 1));
      }
    }
    tip.points.resize(3, static_cast<Eigen::Index>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i)
      tip.points.col(static_cast<Eigen::Index>(i)) = points[i];
    scene.paths.push_back(std::move(tip));
  }
  for (std::size_t s = 0; s < first.spheres.size(); ++s) {
    const std::string& role = first.spheres[s].role;
    if (role != "target" && role != "goal") continue;
    std::vector<Eigen::Vector3d> points;
    for (std::size_t k = 0; k <= upto; ++k) {
      const auto& spheres = episode.frames[k].scene.spheres;
      if (s < spheres.size()) points.push_back(spheres[s].centre);
    }
    Scene::Path path{role, Eigen::Matrix3Xd(3, static_cast<Eigen::Index>(points.size()))};
    for (std::size_t i = 0; i < points.size(); ++i)
      path.points.col(static_cast<Eigen::Index>(i)) = points[i];
    scene.paths.push_back(std::move(path));
  }
}

}  // namespace

int write_episode_video(const Episode& episode, const std::filesystem::path& file,
                        const VideoOptions& options) {
  const std::string where = file.string();
  require(!episode.frames.empty(), "the episode has no frames", where);
  require(std::any_of(episode.frames.begin(), episode.frames.end(),
                      [](const EpisodeFrame& f) { return draws_something(f.scene); }),
          "the episode's environment describes no scene to draw (" +
              episode.meta("env", "unknown environment") + ")",
          where);
  require(options.speed >= 0.0, "speed must be positive (or 0: one frame per step)", where);
  std::vector<const Scene*> scenes;
  for (const EpisodeFrame& frame : episode.frames) scenes.push_back(&frame.scene);
  const View view = frame_scenes(scenes);

  // Which recorded frame each video frame shows.
  const double dt = step_seconds(episode);
  const double start = episode.frames.front().scene.time;
  std::vector<std::size_t> shown;
  double fps = options.fps;
  if (options.speed <= 0.0 || dt <= 0.0) {  // one video frame per step
    if (fps <= 0.0) fps = dt > 0.0 ? std::min(1.0 / dt, options.max_fps) : options.max_fps;
    for (std::size_t k = 0; k < episode.frames.size(); ++k) shown.push_back(k);
  } else {  // frames picked by the episode's clock
    if (fps <= 0.0) fps = std::min(options.speed / dt, options.max_fps);
    const double duration = (episode.frames.back().scene.time - start) / options.speed;
    const auto count = static_cast<std::size_t>(std::floor(duration * fps + 1e-9)) + 1;
    std::size_t k = 0;
    for (std::size_t j = 0; j < count; ++j) {
      const double time = start + options.speed * static_cast<double>(j) / fps;
      while (k + 1 < episode.frames.size() && episode.frames[k + 1].scene.time <= time + 1e-9) ++k;
      shown.push_back(k);
    }
  }
  fps = std::clamp(fps, 1.0, 240.0);

  SceneRasterizer rasterizer(options.raster);
  VideoWriter video(file, options.raster.width, options.raster.height, fps, options.ffmpeg);
  Image image;
  for (const std::size_t k : shown) {
    if (options.trails) {
      Scene scene = episode.frames[k].scene;
      add_trails(episode, k, scene);
      rasterizer.draw(scene, view, image);
    } else {
      rasterizer.draw(episode.frames[k].scene, view, image);
    }
    video.write(image);
  }
  return video.finish();
}

}  // namespace tendril::render
