#include "tendril/render/scene_rasterizer.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "tendril/core/error.hpp"

namespace tendril::render {

namespace {

constexpr float kFar = std::numeric_limits<float>::infinity();
constexpr float kTranslucent = 0.55f;  // obstacles and walls
const Colour kGridMinor{213, 217, 222}, kGridMajor{170, 176, 184};
const Colour kAxisColours[3] = {{214, 64, 50}, {58, 160, 72}, {40, 110, 200}};

bool translucent(const std::string& role) { return role == "obstacle" || role == "wall"; }

// A head light from the upper left (view frame: x right, y up, z away from the eye): ambient,
// Lambert and a small Blinn-Phong highlight.
Colour shade(const Colour& base, const Eigen::Vector3d& normal) {
  static const Eigen::Vector3d light = Eigen::Vector3d(-0.45, 0.6, -0.66).normalized();
  static const Eigen::Vector3d half = (light + Eigen::Vector3d(0.0, 0.0, -1.0)).normalized();
  const double diffuse = std::max(0.0, normal.dot(light));
  const double highlight = 0.22 * std::pow(std::max(0.0, normal.dot(half)), 32.0);
  const double intensity = 0.42 + 0.58 * diffuse;
  Colour out;
  for (int c = 0; c < 3; ++c) {
    out[c] = static_cast<uint8_t>(
        std::clamp(std::lround(base[c] * intensity + 255.0 * highlight), 0L, 255L));
  }
  return out;
}

// Two lab axes spanning the plane perpendicular to `up` (the other two lab axes when `up` is
// one of them).
void plane_axes(const Eigen::Vector3d& up, Eigen::Vector3d& first, Eigen::Vector3d& second) {
  Eigen::Index largest;
  up.cwiseAbs().maxCoeff(&largest);
  if (std::abs(up[largest]) > 1.0 - 1e-9) {
    first = Eigen::Vector3d::Unit((largest + 1) % 3);
    second = Eigen::Vector3d::Unit((largest + 2) % 3);
    if (largest == 1) std::swap(first, second);  // y up: x and z
  } else {
    first = up.unitOrthogonal();
    second = up.cross(first).normalized();
  }
}

// The columns of image row `y` (pixel centre y + 0.5) that may lie within `reach` pixels of the
// segment from a to b: a superset of the row's part of the capsule around the segment, so that a
// long, thin shape is scanned along its length instead of over its bounding box.
bool row_span(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double reach, int y, int width,
              int& x0, int& x1) {
  const double centre = y + 0.5;
  double t0 = 0.0, t1 = 1.0;
  const double dy = b.y() - a.y();
  if (std::abs(dy) < 1e-12) {
    if (std::abs(centre - a.y()) > reach) return false;
  } else {
    t0 = (centre - reach - a.y()) / dy;
    t1 = (centre + reach - a.y()) / dy;
    if (t0 > t1) std::swap(t0, t1);
    t0 = std::max(t0, 0.0);
    t1 = std::min(t1, 1.0);
    if (t0 > t1) return false;
  }
  const double xa = a.x() + t0 * (b.x() - a.x()), xb = a.x() + t1 * (b.x() - a.x());
  x0 = std::max(0, static_cast<int>(std::floor(std::min(xa, xb) - reach)));
  x1 = std::min(width - 1, static_cast<int>(std::ceil(std::max(xa, xb) + reach)));
  return x0 <= x1;
}

// Where a ray (origin + s · direction, camera frame) first meets a capsule of radius r around
// the segment a–b (round ends when `capped`, flat ends otherwise): its s and the outward normal.
bool hit_capsule(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                 const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r, bool capped,
                 double& nearest, Eigen::Vector3d& normal) {
  nearest = std::numeric_limits<double>::infinity();
  const auto take = [&](double s, const Eigen::Vector3d& n) {
    if (s > 0.0 && s < nearest) {
      nearest = s;
      normal = n;
    }
  };
  const auto sphere = [&](const Eigen::Vector3d& centre) {
    const Eigen::Vector3d m = origin - centre;
    const double aa = direction.squaredNorm(), bb = m.dot(direction), cc = m.squaredNorm() - r * r;
    const double disc = bb * bb - aa * cc;
    if (disc < 0.0) return;
    const double s = (-bb - std::sqrt(disc)) / aa;
    take(s, (origin + s * direction - centre) / r);
  };
  const Eigen::Vector3d axis = b - a;
  const double length = axis.norm();
  if (length < 1e-12) {
    sphere(a);
    return std::isfinite(nearest);
  }
  const Eigen::Vector3d u = axis / length;
  const Eigen::Vector3d w = origin - a;
  const Eigen::Vector3d dp = direction - direction.dot(u) * u, wp = w - w.dot(u) * u;
  const double qa = dp.squaredNorm(), qb = 2.0 * wp.dot(dp), qc = wp.squaredNorm() - r * r;
  if (qa > 1e-14) {
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc >= 0.0) {
      const double s = (-qb - std::sqrt(disc)) / (2.0 * qa);
      const Eigen::Vector3d point = origin + s * direction;
      const double t = (point - a).dot(u);
      if (t >= 0.0 && t <= length) take(s, (point - a - t * u) / r);
    }
  }
  if (capped) {
    sphere(a);
    sphere(b);
  } else {
    for (const auto& [centre, n] : {std::pair{a, Eigen::Vector3d(-u)}, std::pair{b, u}}) {
      const double facing = direction.dot(n);
      if (std::abs(facing) < 1e-14) continue;
      const double s = (centre - origin).dot(n) / facing;
      if ((origin + s * direction - centre).squaredNorm() <= r * r) take(s, n);
    }
  }
  return std::isfinite(nearest);
}

}  // namespace

SceneRasterizer::SceneRasterizer(RasterOptions options) : options_(options) {
  require(options_.width > 0 && options_.height > 0 && options_.width <= 8192 &&
              options_.height <= 8192,
          "image size must be 1 to 8192 pixels each way", "render::SceneRasterizer");
  require(options_.supersample >= 1 && options_.supersample <= 4, "supersample must be 1 to 4",
          "render::SceneRasterizer");
  width_ = options_.width * options_.supersample;
  height_ = options_.height * options_.supersample;
  colour_.resize(static_cast<std::size_t>(width_) * height_ * 3);
  depth_.resize(static_cast<std::size_t>(width_) * height_);
}

void SceneRasterizer::clear() {
  for (std::size_t i = 0; i < depth_.size(); ++i) {
    colour_[3 * i] = options_.background[0];
    colour_[3 * i + 1] = options_.background[1];
    colour_[3 * i + 2] = options_.background[2];
  }
  std::fill(depth_.begin(), depth_.end(), kFar);
}

void SceneRasterizer::put(int x, int y, float depth, const Colour& colour, float opacity) {
  const std::size_t i = static_cast<std::size_t>(y) * width_ + x;
  if (!(depth < depth_[i])) return;
  uint8_t* out = colour_.data() + 3 * i;
  if (opacity >= 1.0f) {
    out[0] = colour[0];
    out[1] = colour[1];
    out[2] = colour[2];
    depth_[i] = depth;
    return;
  }
  for (int c = 0; c < 3; ++c) {
    out[c] = static_cast<uint8_t>(std::lround((1.0f - opacity) * out[c] + opacity * colour[c]));
  }
}

// A tube from a to b whose radius goes linearly from radius_a to radius_b, with round ends when
// `capped`: per sample, the closest point of the projected axis, the silhouette's half-width
// there, and a normal and depth as for a cylinder seen straight on.
void SceneRasterizer::capsule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius_a,
                              double radius_b, const Colour& colour, bool capped, float opacity) {
  const Projection& projection = *projection_;
  Eigen::Vector3d start = a, end = b;
  const double near = projection.near();
  double depth_a = projection.depth(a), depth_b = projection.depth(b);
  if (depth_a < near && depth_b < near) return;
  if (depth_a < near || depth_b < near) {  // cut at the near plane
    const double t = (near - depth_a) / (depth_b - depth_a);
    const Eigen::Vector3d cut = a + t * (b - a);
    const double radius_cut = radius_a + t * (radius_b - radius_a);
    if (depth_a < near) {
      start = cut;
      radius_a = radius_cut;
    } else {
      end = cut;
      radius_b = radius_cut;
    }
  }
  const ViewPoint pa = projection.project(start), pb = projection.project(end);
  const double minimum = 0.5 * options_.supersample;  // thin rods stay visible
  const double ra = std::max(radius_a * pa.pixels_per_metre, minimum);
  const double rb = std::max(radius_b * pb.pixels_per_metre, minimum);
  const double extent = std::max(ra, rb) + 1.0;
  const int y0 =
      std::max(0, static_cast<int>(std::floor(std::min(pa.pixel.y(), pb.pixel.y()) - extent)));
  const int y1 = std::min(
      height_ - 1, static_cast<int>(std::ceil(std::max(pa.pixel.y(), pb.pixel.y()) + extent)));
  const Eigen::Vector2d axis = pb.pixel - pa.pixel;
  const double length2 = axis.squaredNorm();
  // Tubes a few pixels wide and more are ray-traced exactly (every sample's ray against the
  // capsule in the camera's frame), so that consecutive segments join into one smooth tube;
  // thinner ones, and tapered ones, are drawn as their projected silhouettes.
  if (radius_a == radius_b && std::min(ra, rb) >= 1.5) {
    const Eigen::Vector3d va = projection.to_view_point(start), vb = projection.to_view_point(end);
    Eigen::Vector3d origin, direction, normal;
    for (int y = y0; y <= y1; ++y) {
      int x0 = 0, x1 = -1;
      if (!row_span(pa.pixel, pb.pixel, 1.2 * extent + 1.0, y, width_, x0, x1)) continue;
      for (int x = x0; x <= x1; ++x) {
        projection.ray({x + 0.5, y + 0.5}, origin, direction);
        double s = 0.0;
        if (!hit_capsule(origin, direction, va, vb, radius_a, capped, s, normal)) continue;
        if (normal.z() > 0.0) normal = -normal;  // a flat end seen from behind
        put(x, y, static_cast<float>(origin.z() + s * direction.z()), shade(colour, normal),
            opacity);
      }
    }
    return;
  }
  for (int y = y0; y <= y1; ++y) {
    int x0 = 0, x1 = -1;
    if (!row_span(pa.pixel, pb.pixel, extent, y, width_, x0, x1)) continue;
    for (int x = x0; x <= x1; ++x) {
      const Eigen::Vector2d p(x + 0.5, y + 0.5);
      double t = length2 > 1e-12 ? (p - pa.pixel).dot(axis) / length2 : 0.0;
      if (!capped && (t < 0.0 || t > 1.0)) continue;
      t = std::clamp(t, 0.0, 1.0);
      const Eigen::Vector2d offset = p - (pa.pixel + t * axis);
      const double r = ra + t * (rb - ra);
      const double distance2 = offset.squaredNorm();
      if (distance2 > r * r) continue;
      const double h = std::sqrt(std::max(0.0, 1.0 - distance2 / (r * r)));
      const double radius = radius_a + t * (radius_b - radius_a);
      const double depth = pa.depth + t * (pb.depth - pa.depth) - radius * h;
      const Eigen::Vector3d normal(offset.x() / r, -offset.y() / r, -h);
      put(x, y, static_cast<float>(depth), shade(colour, normal), opacity);
    }
  }
}

void SceneRasterizer::line(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Colour& colour,
                           double width_pixels) {
  const Projection& projection = *projection_;
  Eigen::Vector3d start = a, end = b;
  const double near = projection.near();
  const double depth_a = projection.depth(a), depth_b = projection.depth(b);
  if (depth_a < near && depth_b < near) return;
  if (depth_a < near) start = a + (near - depth_a) / (depth_b - depth_a) * (b - a);
  if (depth_b < near) end = a + (near - depth_a) / (depth_b - depth_a) * (b - a);
  const ViewPoint pa = projection.project(start), pb = projection.project(end);
  const double r = 0.5 * width_pixels * options_.supersample;
  const int y0 =
      std::max(0, static_cast<int>(std::floor(std::min(pa.pixel.y(), pb.pixel.y()) - r - 1)));
  const int y1 = std::min(
      height_ - 1, static_cast<int>(std::ceil(std::max(pa.pixel.y(), pb.pixel.y()) + r + 1)));
  const Eigen::Vector2d axis = pb.pixel - pa.pixel;
  const double length2 = axis.squaredNorm();
  for (int y = y0; y <= y1; ++y) {
    int x0 = 0, x1 = -1;
    if (!row_span(pa.pixel, pb.pixel, r + 1.0, y, width_, x0, x1)) continue;
    for (int x = x0; x <= x1; ++x) {
      const Eigen::Vector2d p(x + 0.5, y + 0.5);
      const double t =
          length2 > 1e-12 ? std::clamp((p - pa.pixel).dot(axis) / length2, 0.0, 1.0) : 0.0;
      if ((p - (pa.pixel + t * axis)).squaredNorm() > r * r) continue;
      put(x, y, static_cast<float>(pa.depth + t * (pb.depth - pa.depth)), colour, 1.0f);
    }
  }
}

void SceneRasterizer::triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c, const Colour& colour, float opacity) {
  const Projection& projection = *projection_;
  const double near = projection.near();
  if (projection.depth(a) < near || projection.depth(b) < near || projection.depth(c) < near) {
    return;
  }
  const ViewPoint p[3] = {projection.project(a), projection.project(b), projection.project(c)};
  Eigen::Vector3d normal = projection.to_view((b - a).cross(c - a));
  if (normal.norm() == 0.0) return;
  normal.normalize();
  if (normal.z() > 0.0) normal = -normal;  // the side facing the eye
  const Colour lit = shade(colour, normal);
  const auto edge = [](const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                       const Eigen::Vector2d& q) {
    return (to.x() - from.x()) * (q.y() - from.y()) - (to.y() - from.y()) * (q.x() - from.x());
  };
  const double area = edge(p[0].pixel, p[1].pixel, p[2].pixel);
  if (std::abs(area) < 1e-12) return;
  const int x0 = std::max(
      0, static_cast<int>(std::floor(std::min({p[0].pixel.x(), p[1].pixel.x(), p[2].pixel.x()}))));
  const int x1 = std::min(
      width_ - 1,
      static_cast<int>(std::ceil(std::max({p[0].pixel.x(), p[1].pixel.x(), p[2].pixel.x()}))));
  const int y0 = std::max(
      0, static_cast<int>(std::floor(std::min({p[0].pixel.y(), p[1].pixel.y(), p[2].pixel.y()}))));
  const int y1 = std::min(
      height_ - 1,
      static_cast<int>(std::ceil(std::max({p[0].pixel.y(), p[1].pixel.y(), p[2].pixel.y()}))));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const Eigen::Vector2d q(x + 0.5, y + 0.5);
      const double w0 = edge(p[1].pixel, p[2].pixel, q) / area;
      const double w1 = edge(p[2].pixel, p[0].pixel, q) / area;
      const double w2 = 1.0 - w0 - w1;
      if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) continue;
      const double depth = w0 * p[0].depth + w1 * p[1].depth + w2 * p[2].depth;
      put(x, y, static_cast<float>(depth), lit, opacity);
    }
  }
}

void SceneRasterizer::box(const Scene::Box& box, float opacity) {
  const Eigen::Matrix3d rotation = box.orientation.normalized().toRotationMatrix();
  Eigen::Vector3d corner[8];
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d sign(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0);
    corner[i] = box.centre + rotation * sign.cwiseProduct(box.half_extents);
  }
  static const int faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                  {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  const Colour colour = role_colour(box.role);
  for (const auto& f : faces) {
    triangle(corner[f[0]], corner[f[1]], corner[f[2]], colour, opacity);
    triangle(corner[f[0]], corner[f[2]], corner[f[3]], colour, opacity);
  }
}

// A plane as a grid of its role's colour over the floor's extent, about the point of the plane
// nearest the floor's centre.
void SceneRasterizer::plane(const Scene::Plane& plane, const Floor& floor) {
  if (plane.normal.norm() == 0.0) return;
  const Eigen::Vector3d normal = plane.normal.normalized();
  const Eigen::Vector3d centre = floor.centre - (floor.centre - plane.point).dot(normal) * normal;
  Eigen::Vector3d u, v;
  plane_axes(normal, u, v);
  const int lines = 10;
  const double half = floor.half_extent, step = 2.0 * half / lines;
  const Colour colour = role_colour(plane.role);
  for (int k = 0; k <= lines; ++k) {
    const double offset = -half + k * step;
    line(centre + offset * u - half * v, centre + offset * u + half * v, colour, 1.0);
    line(centre + offset * v - half * u, centre + offset * v + half * u, colour, 1.0);
  }
}

void SceneRasterizer::floor_grid(const Floor& floor) {
  Eigen::Vector3d u, v;
  plane_axes(floor.up, u, v);
  const double spacing = floor.spacing, half = floor.half_extent;
  // Lines through multiples of the spacing in lab coordinates, so one passes through the origin.
  const double cu = std::round(floor.centre.dot(u) / spacing) * spacing;
  const double cv = std::round(floor.centre.dot(v) / spacing) * spacing;
  const Eigen::Vector3d origin = floor.centre - floor.centre.dot(u) * u - floor.centre.dot(v) * v;
  const int count = static_cast<int>(std::lround(half / spacing));
  for (int pass = 0; pass < 2; ++pass) {  // minor lines first, the major ones over them
    for (int k = -count; k <= count; ++k) {
      const bool major = std::lround(cu / spacing + k) % 5 == 0;
      const bool major_v = std::lround(cv / spacing + k) % 5 == 0;
      if ((pass == 1) == major) {
        const Eigen::Vector3d at = origin + (cu + k * spacing) * u + cv * v;
        line(at - half * v, at + half * v, major ? kGridMajor : kGridMinor, 1.0);
      }
      if ((pass == 1) == major_v) {
        const Eigen::Vector3d at = origin + cu * u + (cv + k * spacing) * v;
        line(at - half * u, at + half * u, major_v ? kGridMajor : kGridMinor, 1.0);
      }
    }
  }
  // The lab frame's axes at its origin (x red, y green, z blue), two grid spacings long.
  const Eigen::Vector3d lab_origin = Eigen::Vector3d::Zero();
  const Eigen::Vector3d in_plane =
      lab_origin - floor.centre - (lab_origin - floor.centre).dot(floor.up) * floor.up;
  if (std::abs(in_plane.dot(u)) <= half && std::abs(in_plane.dot(v)) <= half) {
    for (int axis = 0; axis < 3; ++axis) {
      line(lab_origin, lab_origin + 2.0 * spacing * Eigen::Vector3d::Unit(axis), kAxisColours[axis],
           2.5);
    }
  }
}

void SceneRasterizer::draw(const Scene& scene, const View& view, Image& image) {
  const Projection projection(view.camera, width_, height_);
  projection_ = &projection;
  clear();
  if (view.floor.visible) floor_grid(view.floor);
  for (const Scene::Plane& p : scene.planes) plane(p, view.floor);
  for (const Scene::Path& path : scene.paths) {
    const Colour colour = role_colour(path.role);
    for (Eigen::Index k = 1; k < path.points.cols(); ++k) {
      line(path.points.col(k - 1), path.points.col(k), colour, 1.5);
    }
  }
  for (const Scene::Rod& rod : scene.rods) {
    const Colour colour = role_colour(rod.role);
    const Eigen::Matrix3Xd& c = rod.centreline;
    for (Eigen::Index k = 0; k + 1 < c.cols(); ++k) {
      const double radius =
          rod.radii.size() == 0 ? 0.0 : rod.radii[std::min<Eigen::Index>(k, rod.radii.size() - 1)];
      capsule(c.col(k), c.col(k + 1), radius, radius, colour, true, 1.0f);
    }
  }
  for (const Scene::Sphere& s : scene.spheres) {
    capsule(s.centre, s.centre, s.radius, s.radius, role_colour(s.role), true,
            translucent(s.role) ? kTranslucent : 1.0f);
  }
  for (const Scene::Lattice& lattice : scene.lattices) {
    const Colour colour = role_colour(lattice.role);
    const double node_radius = 0.08 * view.floor.spacing;
    for (const auto& [i, j] : lattice.springs) {
      if (i >= 0 && j >= 0 && i < lattice.nodes.cols() && j < lattice.nodes.cols()) {
        line(lattice.nodes.col(i), lattice.nodes.col(j), colour, 1.0);
      }
    }
    for (Eigen::Index k = 0; k < lattice.nodes.cols(); ++k) {
      capsule(lattice.nodes.col(k), lattice.nodes.col(k), node_radius, node_radius, colour, true,
              1.0f);
    }
  }
  // Opaque solids, then the translucent ones over everything they do not hide.
  for (const bool see_through : {false, true}) {
    const float opacity = see_through ? kTranslucent : 1.0f;
    for (const Scene::Cylinder& c : scene.cylinders) {
      if (translucent(c.role) != see_through) continue;
      capsule(c.start, c.end, c.radius, c.radius, role_colour(c.role), c.capped, opacity);
    }
    for (const Scene::Box& b : scene.boxes) {
      if (translucent(b.role) == see_through) box(b, opacity);
    }
  }
  projection_ = nullptr;
  downsample(image);
}

void SceneRasterizer::downsample(Image& image) const {
  const int s = options_.supersample;
  image.resize(options_.width, options_.height);
  const int samples = s * s;
  for (int y = 0; y < options_.height; ++y) {
    for (int x = 0; x < options_.width; ++x) {
      int sum[3] = {0, 0, 0};
      for (int dy = 0; dy < s; ++dy) {
        const uint8_t* row =
            colour_.data() + 3 * (static_cast<std::size_t>(y * s + dy) * width_ + x * s);
        for (int dx = 0; dx < s; ++dx) {
          sum[0] += row[3 * dx];
          sum[1] += row[3 * dx + 1];
          sum[2] += row[3 * dx + 2];
        }
      }
      uint8_t* out = image.rgb.data() + 3 * (static_cast<std::size_t>(y) * options_.width + x);
      for (int c = 0; c < 3; ++c) out[c] = static_cast<uint8_t>((sum[c] + samples / 2) / samples);
    }
  }
}

}  // namespace tendril::render
