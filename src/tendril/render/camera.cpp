#include "tendril/render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::render {

namespace {

// The balls (centre, radius) a scene's drawing lies in: each primitive's points with its
// radius, and for each rod the sphere its tip can reach about its base (its length).
using Balls = std::vector<std::pair<Eigen::Vector3d, double>>;

void add_scene(const Scene& scene, bool with_reach, Balls& balls) {
  const auto add = [&](const Eigen::Vector3d& p, double radius) {
    if (p.allFinite() && std::isfinite(radius)) balls.emplace_back(p, std::max(radius, 0.0));
  };
  for (const Scene::Rod& rod : scene.rods) {
    const Eigen::Matrix3Xd& c = rod.centreline;
    if (c.cols() == 0) continue;
    double length = 0.0;
    for (Eigen::Index k = 1; k < c.cols(); ++k) length += (c.col(k) - c.col(k - 1)).norm();
    const double radius = rod.radii.size() > 0 ? rod.radii.maxCoeff() : 0.0;
    for (Eigen::Index k = 0; k < c.cols(); ++k) add(c.col(k), radius);
    if (with_reach) add(c.col(0), length + radius);
  }
  for (const Scene::Sphere& s : scene.spheres) add(s.centre, s.radius);
  for (const Scene::Cylinder& c : scene.cylinders) {
    add(c.start, c.radius);
    add(c.end, c.radius);
  }
  for (const Scene::Box& b : scene.boxes) add(b.centre, b.half_extents.norm());
  for (const Scene::Lattice& l : scene.lattices) {
    for (Eigen::Index k = 0; k < l.nodes.cols(); ++k) add(l.nodes.col(k), 0.0);
  }
  for (const Scene::Path& p : scene.paths) {
    for (Eigen::Index k = 0; k < p.points.cols(); ++k) add(p.points.col(k), 0.0);
  }
}

}  // namespace

Projection::Projection(const Camera& camera, int width, int height)
    : eye_(camera.eye),
      orthographic_(camera.orthographic),
      centre_x_(0.5 * width),
      centre_y_(0.5 * height) {
  const Eigen::Vector3d view = camera.target - camera.eye;
  require(view.norm() > 0.0, "the camera's eye and target coincide", "render::Camera");
  forward_ = view.normalized();
  right_ = forward_.cross(camera.up);
  if (right_.norm() < 1e-9) right_ = forward_.unitOrthogonal();  // looking along `up`
  right_.normalize();
  up_ = right_.cross(forward_);
  if (orthographic_) {
    require(camera.height > 0.0, "an orthographic view needs a positive height", "render::Camera");
    focal_ = height / camera.height;
  } else {
    require(camera.fov_degrees > 0.0 && camera.fov_degrees < 179.0,
            "the field of view must lie in (0°, 179°)", "render::Camera");
    focal_ = 0.5 * height / std::tan(0.5 * camera.fov_degrees * std::numbers::pi / 180.0);
  }
  near_ = 1e-3 * view.norm();
}

ViewPoint Projection::project(const Eigen::Vector3d& lab) const {
  const Eigen::Vector3d v = lab - eye_;
  const double x = v.dot(right_), y = v.dot(up_), z = v.dot(forward_);
  ViewPoint point;
  point.depth = z;
  point.pixels_per_metre = orthographic_ ? focal_ : focal_ / std::max(z, near_);
  point.pixel = {centre_x_ + point.pixels_per_metre * x, centre_y_ - point.pixels_per_metre * y};
  return point;
}

Eigen::Vector3d Projection::to_view(const Eigen::Vector3d& direction) const {
  return {direction.dot(right_), direction.dot(up_), direction.dot(forward_)};
}

void Projection::ray(const Eigen::Vector2d& pixel, Eigen::Vector3d& origin,
                     Eigen::Vector3d& direction) const {
  const double x = (pixel.x() - centre_x_) / focal_, y = (centre_y_ - pixel.y()) / focal_;
  if (orthographic_) {
    origin = {x, y, 0.0};
    direction = {0.0, 0.0, 1.0};
  } else {
    origin = Eigen::Vector3d::Zero();
    direction = {x, y, 1.0};
  }
}

Eigen::Vector3d detect_up(const Scene& scene) {
  if (scene.rods.empty() || scene.rods.front().centreline.cols() < 2)
    return Eigen::Vector3d::UnitZ();
  const Eigen::Matrix3Xd& c = scene.rods.front().centreline;
  const Eigen::Vector3d span = (c.col(c.cols() - 1) - c.col(0)).cwiseAbs();
  return span.y() > span.z() && span.y() >= span.x() ? Eigen::Vector3d::UnitY()
                                                     : Eigen::Vector3d::UnitZ();
}

double grid_spacing(double length) {
  const double raw = std::max(length, 1e-6) / 8.0;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double factor : {1.0, 2.0, 5.0}) {
    if (factor * power >= raw) return factor * power;
  }
  return 10.0 * power;
}

View frame_scenes(const std::vector<const Scene*>& scenes, std::optional<Eigen::Vector3d> up,
                  double fov_degrees) {
  Balls balls, drawn;
  for (const Scene* scene : scenes) {
    add_scene(*scene, true, balls);
    add_scene(*scene, false, drawn);
  }
  if (balls.empty()) balls.emplace_back(Eigen::Vector3d::Zero(), 1.0);
  View view;
  Camera& camera = view.camera;
  camera.up = up ? up->normalized()
                 : (scenes.empty() ? Eigen::Vector3d::UnitZ() : detect_up(*scenes.front()));
  camera.fov_degrees = fov_degrees;
  // A sphere around every ball: centred in their bounding box, as large as the farthest.
  Eigen::Vector3d low = balls.front().first, high = low;
  for (const auto& [centre, radius] : balls) {
    low = low.cwiseMin((centre.array() - radius).matrix());
    high = high.cwiseMax((centre.array() + radius).matrix());
  }
  camera.target = 0.5 * (low + high);
  double radius = 0.05;
  for (const auto& [centre, r] : balls)
    radius = std::max(radius, (centre - camera.target).norm() + r);
  // A three-quarter view from above (the dashboard's default camera) in which that sphere fills
  // the view's height, with a margin of a tenth.
  const Eigen::Vector3d direction =
      camera.up.z() > 0.5 ? Eigen::Vector3d(1.0, -1.4, 0.7) : Eigen::Vector3d(1.0, 0.7, 1.4);
  const double distance = 1.1 * radius / std::sin(0.5 * fov_degrees * std::numbers::pi / 180.0);
  camera.eye = camera.target + distance * direction.normalized();
  camera.height = 2.2 * radius;

  // The floor: at the lab's zero height, or under the lowest point drawn.
  Floor& floor = view.floor;
  floor.up = camera.up;
  double lowest = 0.0;
  for (const auto& [centre, r] : drawn) lowest = std::min(lowest, centre.dot(floor.up) - r);
  floor.centre = camera.target - (camera.target.dot(floor.up) - lowest) * floor.up;
  floor.spacing = grid_spacing(2.0 * radius);
  floor.half_extent = std::ceil(1.2 * radius / floor.spacing) * floor.spacing;
  return view;
}

}  // namespace tendril::render
