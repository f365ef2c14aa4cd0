// Writes the recorded episodes the browser and plotting tests draw: a scene with every kind of
// Scene primitive in motion (all_primitives.tep), and beside it the values a reader must find
// in it (all_primitives.csv, float32 values printed exactly).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "tendril/core/episode_reader.hpp"
#include "tendril/core/episode_writer.hpp"

namespace {

using tendril::Scene;

Scene scene_at(int k) {
  const double t = 0.02 * k, pi = std::numbers::pi;
  Scene scene;
  scene.time = t;
  // An arm along z bending in x, its radius tapering from 2 cm to 1 cm.
  Eigen::Matrix3Xd arm(3, 21);
  for (int i = 0; i <= 20; ++i) {
    const double s = i / 20.0, angle = 0.8 * std::sin(2 * pi * 0.5 * t) * s;
    arm.col(i) = Eigen::Vector3d(0.5 * s * std::sin(angle), 0.1 * s * s, 0.5 * s * std::cos(angle));
  }
  scene.rods.push_back({"arm", arm, Eigen::VectorXd::LinSpaced(20, 0.02, 0.01)});
  const Eigen::Vector3d target(0.25 * std::cos(pi * t), 0.25 * std::sin(pi * t), 0.4);
  scene.spheres.push_back({"target", target, 0.03});
  scene.cylinders.push_back({"obstacle", {-0.3, -0.2, 0.0}, {-0.3, -0.2, 0.35}, 0.04, true});
  scene.cylinders.push_back({"obstacle", {0.3, -0.3, 0.2}, {0.3, 0.3, 0.2}, 0.015, false});
  scene.boxes.push_back(
      {"obstacle",
       {-0.25, 0.3, 0.15},
       {0.08, 0.05, 0.03},
       Eigen::Quaterniond(Eigen::AngleAxisd(t, Eigen::Vector3d(1, 1, 0).normalized()))});
  scene.planes.push_back({"ground", Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()});
  // A breathing cube of masses and springs.
  Eigen::Matrix3Xd nodes(3, 8);
  const double half = 0.06 * (1.0 + 0.2 * std::sin(2 * pi * t));
  for (int n = 0; n < 8; ++n) {
    nodes.col(n) = Eigen::Vector3d(0.35, 0.3, 0.5) +
                   half * Eigen::Vector3d(n & 1 ? 1 : -1, n & 2 ? 1 : -1, n & 4 ? 1 : -1);
  }
  std::vector<std::array<int, 2>> springs;
  for (int a = 0; a < 8; ++a) {
    for (int bit : {1, 2, 4}) {
      if ((a & bit) == 0) springs.push_back({a, a | bit});
    }
  }
  springs.push_back({0, 7});
  scene.lattices.push_back({"lattice", nodes, springs});
  Eigen::Matrix3Xd reference(3, 41);
  for (int i = 0; i <= 40; ++i) {
    reference.col(i) =
        Eigen::Vector3d(0.25 * std::cos(pi * i / 20.0), 0.25 * std::sin(pi * i / 20.0), 0.4);
  }
  scene.paths.push_back({"reference", reference});
  scene.values.emplace_back("distance", (arm.col(20) - target).norm());
  return scene;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <directory>\n", argv[0]);
    return 2;
  }
  const std::filesystem::path directory = argv[1];
  std::filesystem::create_directories(directory);
  const std::filesystem::path file = directory / "all_primitives.tep";
  {
    tendril::EpisodeWriter writer(file, {{"env", "every Scene primitive"}}, 2);
    for (int k = 0; k <= 150; ++k) {
      tendril::EpisodeFrame frame;
      frame.step = k;
      frame.scene = scene_at(k);
      if (k > 0) {
        frame.reward = -frame.scene.values[0].second;
        frame.action = tendril::Action(2);
        frame.action << static_cast<float>(std::sin(0.1 * k)), 0.5f;
        frame.info = {{"distance", frame.scene.values[0].second}};
      }
      frame.truncated = k == 150;
      writer.write(frame);
    }
    writer.finish();
  }
  // What the reader finds, for readers in other languages to compare against.
  const tendril::Episode episode = tendril::read_episode(file);
  FILE* out = std::fopen((directory / "all_primitives.csv").c_str(), "w");
  std::fprintf(out, "step,time,reward,tip_x,tip_y,tip_z,box_w,lattice_x0,distance\n");
  for (const tendril::EpisodeFrame& frame : episode.frames) {
    const Scene& s = frame.scene;
    std::fprintf(out, "%lld,%.17g,%.17g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n",
                 static_cast<long long>(frame.step), s.time, frame.reward,
                 s.rods[0].centreline(0, 20), s.rods[0].centreline(1, 20),
                 s.rods[0].centreline(2, 20), s.boxes[0].orientation.w(), s.lattices[0].nodes(0, 0),
                 s.values[0].second);
  }
  std::fclose(out);
  std::printf("%s: %zu frames\n", file.c_str(), episode.frames.size());
  return 0;
}
