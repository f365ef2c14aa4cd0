#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "tendril/core/scene.hpp"

namespace tendril::render {

// Where a picture of a scene is taken from (lab frame, metres): a pinhole camera at `eye`
// looking at `target` with `up` upwards on the image, with a vertical field of view in degrees,
// or an orthographic view `height` metres tall.
struct Camera {
  Eigen::Vector3d eye{2.0, -2.8, 1.4};
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  double fov_degrees = 40.0;
  bool orthographic = false;
  double height = 1.0;  // orthographic only: the view's height in metres
};

// A point in the camera's frame: x right, y up on the image, z the distance along the view
// direction (metres).
struct ViewPoint {
  Eigen::Vector2d pixel;          // image coordinates, x right, y down, (0, 0) the top-left corner
  double depth = 0.0;             // along the view direction; ≤ 0 behind the camera
  double pixels_per_metre = 0.0;  // of a length across the view at this depth
};

// A camera's projection onto an image of `width` × `height` pixels.
class Projection {
 public:
  Projection(const Camera& camera, int width, int height);

  ViewPoint project(const Eigen::Vector3d& lab) const;
  // The view direction's component of a lab point (depth), without projecting.
  double depth(const Eigen::Vector3d& lab) const { return (lab - eye_).dot(forward_); }
  // A lab-frame direction in the camera's frame (x right, y up, z forward).
  Eigen::Vector3d to_view(const Eigen::Vector3d& direction) const;
  // A lab-frame point in the camera's frame (the eye at the origin).
  Eigen::Vector3d to_view_point(const Eigen::Vector3d& lab) const { return to_view(lab - eye_); }
  // The ray through an image point, in the camera's frame: origin + s · direction, s ≥ 0, with
  // direction's z component 1 (so s is the depth gained).
  void ray(const Eigen::Vector2d& pixel, Eigen::Vector3d& origin, Eigen::Vector3d& direction) const;
  double near() const { return near_; }

 private:
  Eigen::Vector3d eye_, right_, up_, forward_;
  double focal_ = 1.0;  // pixels per unit of (lateral / depth); orthographic: per metre
  bool orthographic_ = false;
  double centre_x_ = 0.0, centre_y_ = 0.0;
  double near_ = 1e-3;
};

// The lab axis drawn upwards: the one the first rod runs along from base to tip when that is y
// (PyElastica's arms grow along y), else z.
Eigen::Vector3d detect_up(const Scene& scene);

// The floor drawn under a scene as a grid of lines: a square of `half_extent` about `centre`
// (a point of the floor), perpendicular to `up`, with lines `spacing` apart; an axis triad at the
// lab origin when it lies on the floor's square.
struct Floor {
  bool visible = true;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  double spacing = 0.1;
  double half_extent = 1.0;
};

struct View {
  Camera camera;
  Floor floor;
};

// A view of the whole of each scene in `scenes` — and the sphere each rod's tip can reach about
// its base (a rod's length) — from a three-quarter view above with `up` upwards (detect_up of
// the first scene when not given), over a floor at the lab's zero height or below everything
// drawn: one fixed view for a whole episode.
View frame_scenes(const std::vector<const Scene*>& scenes,
                  std::optional<Eigen::Vector3d> up = std::nullopt, double fov_degrees = 40.0);

// A round grid spacing near `length` / 8: 1, 2 or 5 times a power of ten.
double grid_spacing(double length);

}  // namespace tendril::render
