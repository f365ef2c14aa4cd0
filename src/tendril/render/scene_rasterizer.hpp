#pragma once

#include <Eigen/Core>
#include <vector>

#include "tendril/core/scene.hpp"
#include "tendril/render/camera.hpp"
#include "tendril/render/image.hpp"
#include "tendril/render/role_colours.hpp"

namespace tendril::render {

struct RasterOptions {
  int width = 640, height = 480;
  // Samples per pixel along each axis (anti-aliasing by averaging supersample² samples).
  int supersample = 2;
  Colour background{244, 245, 247};
};

// A software rasterizer of Scene primitives (core/scene.hpp) into an RGB image, for pictures
// and videos of environments without a GPU or a display: rods as tubes of their own radii
// (capsules per segment, so joints are round), spheres, cylinders (capped or not), boxes,
// planes and the floor as grids of lines, lattices as nodes and springs, paths as lines;
// coloured by role (role_colour), lit by a head light from the upper left, depth-tested, with
// obstacles and walls translucent so that what is behind them shows. Deterministic: the same
// scene and view give the same bytes. Tubes and spheres a few pixels wide and more are
// ray-traced exactly (each sample's ray against the capsule), so a rod's segments join into one
// smooth tube; thinner ones are drawn as their projected silhouettes.
//
// Keeps its sample buffers between calls: one rasterizer draws one picture at a time.
class SceneRasterizer {
 public:
  explicit SceneRasterizer(RasterOptions options = {});

  const RasterOptions& options() const { return options_; }
  // Draws `scene` as `view` sees it into `image` (sized to the options).
  void draw(const Scene& scene, const View& view, Image& image);

 private:
  void clear();
  void floor_grid(const Floor& floor);
  void capsule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius_a, double radius_b,
               const Colour& colour, bool capped, float opacity);
  void line(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Colour& colour,
            double width_pixels);
  void triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                const Colour& colour, float opacity);
  void box(const Scene::Box& box, float opacity);
  void plane(const Scene::Plane& plane, const Floor& floor);
  void put(int x, int y, float depth, const Colour& colour, float opacity);
  void downsample(Image& image) const;

  RasterOptions options_;
  int width_ = 0, height_ = 0;  // of the sample buffers
  std::vector<uint8_t> colour_;
  std::vector<float> depth_;
  const Projection* projection_ = nullptr;  // during draw()
};

}  // namespace tendril::render
