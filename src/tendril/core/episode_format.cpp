#include "tendril/core/episode_format.hpp"

#include <bit>
#include <cstring>

#include "tendril/core/error.hpp"

namespace tendril::episode_format {

static_assert(std::endian::native == std::endian::little,
              "episode files are little-endian; this writer copies scalars as they are in memory");

namespace {

void put_points(const Eigen::Matrix3Xd& points, std::vector<float>& out) {
  for (Eigen::Index c = 0; c < points.cols(); ++c) {
    for (int r = 0; r < 3; ++r) out.push_back(static_cast<float>(points(r, c)));
  }
}

void put_vector(const Eigen::Vector3d& v, std::vector<float>& out) {
  for (int r = 0; r < 3; ++r) out.push_back(static_cast<float>(v(r)));
}

// Reads float32s in order from one primitive's data.
class Floats {
 public:
  explicit Floats(const std::vector<float>& data) : data_(data) {}
  double next() { return static_cast<double>(data_[index_++]); }
  Eigen::Vector3d vector() {
    const double x = next(), y = next(), z = next();
    return {x, y, z};
  }
  Eigen::Matrix3Xd points(uint32_t count) {
    Eigen::Matrix3Xd points(3, count);
    for (uint32_t c = 0; c < count; ++c) points.col(c) = vector();
    return points;
  }

 private:
  const std::vector<float>& data_;
  std::size_t index_ = 0;
};

}  // namespace

std::size_t Primitive::float_count() const {
  switch (kind) {
    case Kind::kRod:
      return 3 * std::size_t{points} + radii;
    case Kind::kSphere:
      return 4;  // centre, radius
    case Kind::kCylinder:
      return 7;  // start, end, radius
    case Kind::kBox:
      return 10;  // centre, half extents, orientation quaternion (w, x, y, z)
    case Kind::kPlane:
      return 6;  // point, normal
    case Kind::kLattice:
    case Kind::kPath:
      return 3 * std::size_t{points};
  }
  return 0;
}

Layout layout_of(const Scene& scene, std::vector<std::string> info_names, uint32_t action_size) {
  Layout layout;
  layout.action_size = action_size;
  layout.info_names = std::move(info_names);
  for (const auto& value : scene.values) layout.value_names.push_back(value.first);
  auto& primitives = layout.primitives;
  for (const Scene::Rod& rod : scene.rods) {
    primitives.push_back({Kind::kRod,
                          rod.role,
                          static_cast<uint32_t>(rod.centreline.cols()),
                          static_cast<uint32_t>(rod.radii.size()),
                          false,
                          {}});
  }
  for (const Scene::Sphere& sphere : scene.spheres) {
    primitives.push_back({.kind = Kind::kSphere, .role = sphere.role});
  }
  for (const Scene::Cylinder& cylinder : scene.cylinders) {
    primitives.push_back(
        {.kind = Kind::kCylinder, .role = cylinder.role, .capped = cylinder.capped});
  }
  for (const Scene::Box& box : scene.boxes) primitives.push_back({Kind::kBox, box.role});
  for (const Scene::Plane& plane : scene.planes) primitives.push_back({Kind::kPlane, plane.role});
  for (const Scene::Lattice& lattice : scene.lattices) {
    Primitive primitive{Kind::kLattice, lattice.role, static_cast<uint32_t>(lattice.nodes.cols())};
    for (const auto& spring : lattice.springs) {
      primitive.springs.emplace_back(static_cast<uint32_t>(spring[0]),
                                     static_cast<uint32_t>(spring[1]));
    }
    primitives.push_back(std::move(primitive));
  }
  for (const Scene::Path& path : scene.paths) {
    primitives.push_back({Kind::kPath, path.role, static_cast<uint32_t>(path.points.cols())});
  }
  return layout;
}

std::vector<std::vector<float>> primitive_data(const Scene& scene) {
  std::vector<std::vector<float>> data;
  for (const Scene::Rod& rod : scene.rods) {
    auto& out = data.emplace_back();
    put_points(rod.centreline, out);
    for (Eigen::Index i = 0; i < rod.radii.size(); ++i)
      out.push_back(static_cast<float>(rod.radii(i)));
  }
  for (const Scene::Sphere& sphere : scene.spheres) {
    auto& out = data.emplace_back();
    put_vector(sphere.centre, out);
    out.push_back(static_cast<float>(sphere.radius));
  }
  for (const Scene::Cylinder& cylinder : scene.cylinders) {
    auto& out = data.emplace_back();
    put_vector(cylinder.start, out);
    put_vector(cylinder.end, out);
    out.push_back(static_cast<float>(cylinder.radius));
  }
  for (const Scene::Box& box : scene.boxes) {
    auto& out = data.emplace_back();
    put_vector(box.centre, out);
    put_vector(box.half_extents, out);
    const Eigen::Quaterniond& q = box.orientation;
    for (double component : {q.w(), q.x(), q.y(), q.z()})
      out.push_back(static_cast<float>(component));
  }
  for (const Scene::Plane& plane : scene.planes) {
    auto& out = data.emplace_back();
    put_vector(plane.point, out);
    put_vector(plane.normal, out);
  }
  for (const Scene::Lattice& lattice : scene.lattices)
    put_points(lattice.nodes, data.emplace_back());
  for (const Scene::Path& path : scene.paths) put_points(path.points, data.emplace_back());
  return data;
}

void fill_scene(const Layout& layout, const std::vector<std::vector<float>>& data, Scene& scene) {
  for (std::size_t i = 0; i < layout.primitives.size(); ++i) {
    const Primitive& p = layout.primitives[i];
    Floats in(data[i]);
    switch (p.kind) {
      case Kind::kRod: {
        Scene::Rod rod{p.role, in.points(p.points), Eigen::VectorXd(p.radii)};
        for (uint32_t k = 0; k < p.radii; ++k) rod.radii(k) = in.next();
        scene.rods.push_back(std::move(rod));
        break;
      }
      case Kind::kSphere: {
        const Eigen::Vector3d centre = in.vector();
        scene.spheres.push_back({p.role, centre, in.next()});
        break;
      }
      case Kind::kCylinder: {
        const Eigen::Vector3d start = in.vector(), end = in.vector();
        scene.cylinders.push_back({p.role, start, end, in.next(), p.capped});
        break;
      }
      case Kind::kBox: {
        const Eigen::Vector3d centre = in.vector(), half_extents = in.vector();
        const double w = in.next(), x = in.next(), y = in.next(), z = in.next();
        scene.boxes.push_back({p.role, centre, half_extents, Eigen::Quaterniond(w, x, y, z)});
        break;
      }
      case Kind::kPlane: {
        const Eigen::Vector3d point = in.vector(), normal = in.vector();
        scene.planes.push_back({p.role, point, normal});
        break;
      }
      case Kind::kLattice: {
        Scene::Lattice lattice{p.role, in.points(p.points), {}};
        for (const auto& [a, b] : p.springs) {
          lattice.springs.push_back({static_cast<int>(a), static_cast<int>(b)});
        }
        scene.lattices.push_back(std::move(lattice));
        break;
      }
      case Kind::kPath:
        scene.paths.push_back({p.role, in.points(p.points)});
        break;
    }
  }
}

void Bytes::text(std::string_view value) {
  u32(static_cast<uint32_t>(value.size()));
  raw(value.data(), value.size());
}

void Bytes::raw(const void* data, std::size_t size) {
  buffer_.append(static_cast<const char*>(data), size);
}

void Cursor::expect(std::size_t size) const {
  if (size > bytes_.size() - position_) {
    throw Error("record ends inside a field (byte " + std::to_string(position_) + " of " +
                    std::to_string(bytes_.size()) + ")",
                where_);
  }
}

void Cursor::raw(void* data, std::size_t size) {
  expect(size);
  if (size == 0) return;  // an empty array's data() may be null, which memcpy must not be given
  std::memcpy(data, bytes_.data() + position_, size);
  position_ += size;
}

void Cursor::skip(std::size_t size) {
  expect(size);
  position_ += size;
}

uint8_t Cursor::u8() {
  uint8_t value;
  raw(&value, sizeof value);
  return value;
}

uint32_t Cursor::u32() {
  uint32_t value;
  raw(&value, sizeof value);
  return value;
}

float Cursor::f32() {
  float value;
  raw(&value, sizeof value);
  return value;
}

double Cursor::f64() {
  double value;
  raw(&value, sizeof value);
  return value;
}

std::string Cursor::text() {
  const uint32_t size = count(1);
  std::string value(size, '\0');
  raw(value.data(), size);
  return value;
}

uint32_t Cursor::count(std::size_t item_bytes) {
  const uint32_t n = u32();
  if (item_bytes > 0 && n > (bytes_.size() - position_) / item_bytes) {
    throw Error("a count of " + std::to_string(n) + " exceeds the record's remaining " +
                    std::to_string(bytes_.size() - position_) + " bytes",
                where_);
  }
  return n;
}

void encode_layout(const Layout& layout, Bytes& out) {
  out.u32(layout.action_size);
  out.u32(static_cast<uint32_t>(layout.info_names.size()));
  for (const std::string& name : layout.info_names) out.text(name);
  out.u32(static_cast<uint32_t>(layout.value_names.size()));
  for (const std::string& name : layout.value_names) out.text(name);
  out.u32(static_cast<uint32_t>(layout.primitives.size()));
  for (const Primitive& p : layout.primitives) {
    out.u8(static_cast<uint8_t>(p.kind));
    out.text(p.role);
    switch (p.kind) {
      case Kind::kRod:
        out.u32(p.points);
        out.u32(p.radii);
        break;
      case Kind::kCylinder:
        out.u8(p.capped ? 1 : 0);
        break;
      case Kind::kLattice:
        out.u32(p.points);
        out.u32(static_cast<uint32_t>(p.springs.size()));
        for (const auto& [a, b] : p.springs) out.u32(a), out.u32(b);
        break;
      case Kind::kPath:
        out.u32(p.points);
        break;
      default:
        break;
    }
  }
}

Layout decode_layout(Cursor& in) {
  Layout layout;
  layout.action_size = in.u32();
  for (uint32_t n = in.count(4); n > 0; --n) layout.info_names.push_back(in.text());
  for (uint32_t n = in.count(4); n > 0; --n) layout.value_names.push_back(in.text());
  for (uint32_t n = in.count(5); n > 0; --n) {
    Primitive p;
    const uint8_t kind = in.u8();
    if (kind < 1 || kind > 7) throw Error("unknown primitive kind " + std::to_string(kind));
    p.kind = static_cast<Kind>(kind);
    p.role = in.text();
    switch (p.kind) {
      case Kind::kRod:
        p.points = in.u32();
        p.radii = in.u32();
        if (p.points < 2 || (p.radii != 1 && p.radii != p.points - 1)) {
          throw Error("a rod of " + std::to_string(p.points) + " nodes with " +
                      std::to_string(p.radii) + " radii");
        }
        break;
      case Kind::kCylinder:
        p.capped = in.u8() != 0;
        break;
      case Kind::kLattice:
        p.points = in.u32();
        for (uint32_t s = in.count(8); s > 0; --s) {
          const uint32_t a = in.u32(), b = in.u32();
          if (a >= p.points || b >= p.points) {
            throw Error("a spring between nodes " + std::to_string(a) + " and " +
                        std::to_string(b) + " of a lattice of " + std::to_string(p.points));
          }
          p.springs.emplace_back(a, b);
        }
        break;
      case Kind::kPath:
        p.points = in.u32();
        break;
      default:
        break;
    }
    layout.primitives.push_back(std::move(p));
  }
  return layout;
}

}  // namespace tendril::episode_format
