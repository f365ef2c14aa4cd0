// The software rasterizer: silhouettes of spheres and tubes against their closed-form areas,
// depth order, translucency, and byte-for-byte determinism.
#include "tendril/render/scene_rasterizer.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace tendril::render {
namespace {

constexpr double kPi = std::numbers::pi;

// Looking down the z axis at the origin, orthographic, `metres` tall; no floor.
View top_view(double metres) {
  View view;
  view.camera.eye = {0.0, 0.0, 5.0};
  view.camera.target = Eigen::Vector3d::Zero();
  view.camera.up = Eigen::Vector3d::UnitY();
  view.camera.orthographic = true;
  view.camera.height = metres;
  view.floor.visible = false;
  return view;
}

// Pixels that are not the background.
int covered(const Image& image, const Colour& background) {
  int count = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.pixel(x, y);
      count += p[0] != background[0] || p[1] != background[1] || p[2] != background[2];
    }
  }
  return count;
}

Scene::Sphere sphere(const std::string& role, Eigen::Vector3d centre, double radius) {
  return {role, centre, radius};
}

// A sphere of radius 0.5 m seen from above at 100 px/m is a disc of radius 50 px: π·50² =
// 7,854 px; anti-aliased edges count as covered, so allow the ring of one pixel around it
// (2π·50 ≈ 314 px): within 4 %.
TEST(SceneRasterizer, SphereCoversItsDisc) {
  SceneRasterizer rasterizer({.width = 200, .height = 200, .supersample = 2});
  Scene scene;
  scene.spheres.push_back(sphere("target", Eigen::Vector3d::Zero(), 0.5));
  Image image;
  rasterizer.draw(scene, top_view(2.0), image);
  const double expected = kPi * 50.0 * 50.0;
  EXPECT_NEAR(covered(image, rasterizer.options().background), expected, 0.04 * expected);
  // Red at its centre (the target's role colour, lit), background in the corners.
  const uint8_t* centre = image.pixel(100, 100);
  EXPECT_GT(centre[0], 2 * centre[1]);
  EXPECT_GT(centre[0], 2 * centre[2]);
  EXPECT_EQ(image.pixel(2, 2)[0], rasterizer.options().background[0]);
}

// A straight rod of length 1 m and radius 0.1 m from above: a capsule, 2rL + πr² = 0.2314 m²
// = 2,314 px at 100 px/m (within 6 %: its outline is 2.6 m = 260 px long).
TEST(SceneRasterizer, RodCoversItsCapsule) {
  SceneRasterizer rasterizer({.width = 200, .height = 200, .supersample = 2});
  Scene scene;
  Scene::Rod rod;
  rod.role = "arm";
  rod.centreline.resize(3, 11);
  for (int k = 0; k <= 10; ++k) rod.centreline.col(k) = Eigen::Vector3d(-0.5 + 0.1 * k, 0.0, 0.0);
  rod.radii = Eigen::VectorXd::Constant(1, 0.1);
  scene.rods.push_back(rod);
  Image image;
  rasterizer.draw(scene, top_view(2.0), image);
  const double expected = (2.0 * 0.1 * 1.0 + kPi * 0.01) * 100.0 * 100.0;
  EXPECT_NEAR(covered(image, rasterizer.options().background), expected, 0.06 * expected);
}

// The nearer of two overlapping spheres is seen, whatever their order in the scene.
TEST(SceneRasterizer, NearerSurfaceHidesFartherOne) {
  SceneRasterizer rasterizer({.width = 120, .height = 120, .supersample = 1});
  for (const bool target_first : {true, false}) {
    Scene scene;
    const auto near = sphere("target", {0.0, 0.0, 1.0}, 0.3);  // red, nearer the eye at z = 5
    const auto far = sphere("path", {0.0, 0.0, 0.0}, 0.6);     // blue, larger
    scene.spheres = target_first ? std::vector{near, far} : std::vector{far, near};
    Image image;
    rasterizer.draw(scene, top_view(2.0), image);
    const uint8_t* centre = image.pixel(60, 60);
    EXPECT_GT(centre[0], centre[2]) << "target first: " << target_first;
    const uint8_t* rim = image.pixel(60 + 25, 60);  // 0.42 m out: only the blue sphere
    EXPECT_GT(rim[2], rim[0]) << "target first: " << target_first;
  }
}

// An obstacle in front of a target is translucent: the target tints the obstacle's pixels.
TEST(SceneRasterizer, TargetShowsThroughAnObstacle) {
  SceneRasterizer rasterizer({.width = 120, .height = 120, .supersample = 1});
  Scene obstacle_only;
  obstacle_only.cylinders.push_back({"obstacle", {-1.0, 0.0, 1.0}, {1.0, 0.0, 1.0}, 0.4, false});
  Scene both = obstacle_only;
  both.spheres.push_back(sphere("target", Eigen::Vector3d::Zero(), 0.2));
  Image alone, with_target;
  rasterizer.draw(obstacle_only, top_view(2.0), alone);
  rasterizer.draw(both, top_view(2.0), with_target);
  const uint8_t* a = alone.pixel(60, 60);
  const uint8_t* b = with_target.pixel(60, 60);
  EXPECT_GT(b[0] - b[2], a[0] - a[2] + 40);  // redder where the target lies behind
}

// The same scene and view give the same bytes; a moved arm gives others.
TEST(SceneRasterizer, IsDeterministic) {
  Scene scene;
  Scene::Rod rod;
  rod.role = "arm";
  rod.centreline.resize(3, 21);
  for (int k = 0; k <= 20; ++k) {
    const double s = 0.05 * k;
    rod.centreline.col(k) = Eigen::Vector3d(0.3 * s * s, 0.1 * s, s);
  }
  rod.radii = Eigen::VectorXd::LinSpaced(20, 0.03, 0.01);
  scene.rods.push_back(rod);
  scene.spheres.push_back(sphere("target", {0.4, 0.2, 0.7}, 0.04));
  scene.boxes.push_back({"obstacle",
                         {0.2, -0.3, 0.3},
                         {0.1, 0.1, 0.2},
                         Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()))});
  const View view = frame_scenes({&scene});
  Image first, second, third;
  SceneRasterizer(RasterOptions{}).draw(scene, view, first);
  SceneRasterizer(RasterOptions{}).draw(scene, view, second);
  EXPECT_EQ(first.rgb, second.rgb);
  EXPECT_GT(covered(first, RasterOptions{}.background), 0.05 * 640 * 480);  // arm, box, floor
  scene.rods.front().centreline.row(0).array() += 0.1;
  SceneRasterizer(RasterOptions{}).draw(scene, view, third);
  EXPECT_NE(first.rgb, third.rgb);
}

TEST(Camera, FramingSeesTheArmsReach) {
  // A vertical rod of 1 m at the origin: the view must hold the sphere of its reach.
  Scene scene;
  Scene::Rod rod;
  rod.role = "arm";
  rod.centreline.resize(3, 2);
  rod.centreline << 0, 0, 0, 0, 0, 1;
  rod.radii = Eigen::VectorXd::Constant(1, 0.01);
  scene.rods.push_back(rod);
  const View view = frame_scenes({&scene});
  EXPECT_EQ(view.camera.up, Eigen::Vector3d::UnitZ());
  const Projection projection(view.camera, 640, 480);
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(0, 1, 0),
        Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -1)}) {
    const ViewPoint v = projection.project(p);
    EXPECT_GT(v.depth, 0.0);
    EXPECT_GE(v.pixel.x(), 0.0);
    EXPECT_LE(v.pixel.x(), 640.0);
    EXPECT_GE(v.pixel.y(), 0.0);
    EXPECT_LE(v.pixel.y(), 480.0);
  }
  // The floor under everything drawn (the base's rounded end), with round spacing.
  EXPECT_NEAR(view.floor.centre.z(), -0.01, 1e-9);
  EXPECT_DOUBLE_EQ(grid_spacing(2.0), 0.5);
  EXPECT_DOUBLE_EQ(grid_spacing(0.8), 0.1);
  EXPECT_DOUBLE_EQ(grid_spacing(16.0), 2.0);
}

TEST(Camera, ArmsAlongYAreDrawnYUp) {
  Scene scene;
  Scene::Rod rod;
  rod.centreline.resize(3, 2);
  rod.centreline.col(0) = Eigen::Vector3d(0, 0, 0);
  rod.centreline.col(1) = Eigen::Vector3d(0.1, 1.0, 0.0);
  scene.rods.push_back(rod);
  EXPECT_EQ(detect_up(scene), Eigen::Vector3d::UnitY());
}

}  // namespace
}  // namespace tendril::render
