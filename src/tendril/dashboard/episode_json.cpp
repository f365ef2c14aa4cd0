#include "tendril/dashboard/episode_json.hpp"

#include <algorithm>
#include <vector>

#include "tendril/core/episode_reader.hpp"
#include "tendril/dashboard/json_writer.hpp"

namespace tendril::dashboard {

namespace {

// Recorded geometry is float32: seven significant digits carry it.
constexpr int kDigits = 7;

void vector3(JsonWriter& json, const char* name, const Eigen::Vector3d& v) {
  const float values[3] = {static_cast<float>(v.x()), static_cast<float>(v.y()),
                           static_cast<float>(v.z())};
  json.key(name).numbers(values, 3);
}

void points(JsonWriter& json, const char* name, const Eigen::Matrix3Xd& m) {
  const Eigen::Matrix3Xf as_float = m.cast<float>();
  json.key(name).numbers(as_float.data(), static_cast<std::size_t>(as_float.size()));
}

void named_values(JsonWriter& json, const char* name,
                  const std::vector<std::pair<std::string, double>>& values) {
  json.key(name).begin_object();
  for (const auto& [key, value] : values) json.key(key).value(value);
  json.end_object();
}

class SceneJson {
 public:
  explicit SceneJson(JsonWriter& json) : json_(json) {}

  void write(const Scene& scene) {
    json_.begin_object();
    json_.key("rods").begin_array();
    for (const Scene::Rod& rod : scene.rods) {
      json_.begin_object().key("role").value(rod.role);
      points(json_, "points", rod.centreline);
      const Eigen::VectorXf radii = rod.radii.cast<float>();
      json_.key("radii").numbers(radii.data(), static_cast<std::size_t>(radii.size()));
      json_.end_object();
    }
    json_.end_array().key("spheres").begin_array();
    for (const Scene::Sphere& sphere : scene.spheres) {
      json_.begin_object().key("role").value(sphere.role);
      vector3(json_, "centre", sphere.centre);
      json_.key("radius").value(sphere.radius, kDigits).end_object();
    }
    json_.end_array().key("cylinders").begin_array();
    for (const Scene::Cylinder& cylinder : scene.cylinders) {
      json_.begin_object().key("role").value(cylinder.role);
      vector3(json_, "start", cylinder.start);
      vector3(json_, "end", cylinder.end);
      json_.key("radius").value(cylinder.radius, kDigits).key("capped").value(cylinder.capped);
      json_.end_object();
    }
    json_.end_array().key("boxes").begin_array();
    for (const Scene::Box& box : scene.boxes) {
      json_.begin_object().key("role").value(box.role);
      vector3(json_, "centre", box.centre);
      vector3(json_, "half_extents", box.half_extents);
      const Eigen::Quaterniond& q = box.orientation;
      json_.key("orientation").numbers(std::vector<double>{q.w(), q.x(), q.y(), q.z()}, 7);
      json_.end_object();
    }
    json_.end_array().key("planes").begin_array();
    for (const Scene::Plane& plane : scene.planes) {
      json_.begin_object().key("role").value(plane.role);
      vector3(json_, "point", plane.point);
      vector3(json_, "normal", plane.normal);
      json_.end_object();
    }
    json_.end_array().key("lattices").begin_array();
    for (const Scene::Lattice& lattice : scene.lattices) {
      json_.begin_object().key("role").value(lattice.role);
      points(json_, "nodes", lattice.nodes);
      json_.key("springs").value(static_cast<int64_t>(springs_index(lattice.springs)));
      json_.end_object();
    }
    json_.end_array().key("paths").begin_array();
    for (const Scene::Path& path : scene.paths) {
      json_.begin_object().key("role").value(path.role);
      points(json_, "points", path.points);
      json_.end_object();
    }
    json_.end_array();
    json_.end_object();
  }

  void write_springs() {
    json_.begin_array();
    for (const auto& springs : springs_) {
      json_.begin_array();
      for (const auto& spring : springs) {
        json_.begin_array().value(spring[0]).value(spring[1]).end_array();
      }
      json_.end_array();
    }
    json_.end_array();
  }

 private:
  std::size_t springs_index(const std::vector<std::array<int, 2>>& springs) {
    for (std::size_t i = springs_.size(); i-- > 0;) {
      if (springs_[i] == springs) return i;
    }
    springs_.push_back(springs);
    return springs_.size() - 1;
  }

  JsonWriter& json_;
  std::vector<std::vector<std::array<int, 2>>> springs_;
};

}  // namespace

std::string episode_json(const std::filesystem::path& file, int max_frames, std::size_t max_bytes) {
  // Two passes over the file: which frames there are, then only the chosen ones built.
  const EpisodeOutline outline = outline_episode(file);
  const auto count = static_cast<std::size_t>(outline.frames());
  const std::size_t affordable = max_bytes / std::max<std::size_t>(outline.frame_bytes, 1);
  const std::size_t limit =
      std::max<std::size_t>({std::min(static_cast<std::size_t>(max_frames), affordable), 2});
  const std::size_t stride = count <= limit ? 1 : (count + limit - 2) / (limit - 1);
  std::vector<int64_t> picked;
  for (std::size_t i = 0; i < count; i += stride) picked.push_back(static_cast<int64_t>(i));
  if (count > 0 && picked.back() != static_cast<int64_t>(count - 1)) {
    picked.push_back(static_cast<int64_t>(count - 1));
  }
  // A file being written may have grown since: its first frames are the ones counted.
  const PartialEpisode chosen = read_partial_episode(file, picked);

  JsonWriter json;
  json.begin_object();
  json.key("metadata").begin_object();
  for (const auto& [key, value] : outline.metadata) json.key(key).value(value);
  json.end_object();
  json.key("complete").value(outline.problem.empty());
  json.key("truncated").value(outline.truncated);
  json.key("problem").value(outline.problem);
  json.key("action_size").value(outline.action_size);
  json.key("summary");
  if (outline.summary) {
    json.begin_object()
        .key("steps")
        .value(outline.summary->steps)
        .key("return")
        .value(outline.summary->episode_return)
        .key("terminated")
        .value(outline.summary->terminated)
        .key("truncated")
        .value(outline.summary->truncated)
        .end_object();
  } else {
    json.null();
  }
  std::vector<double> returns(count);  // the return up to each frame, over every frame
  for (std::size_t i = 0; i < count; ++i) {
    returns[i] = (i > 0 ? returns[i - 1] : 0.0) + outline.rewards[i];
  }
  json.key("frame_count").value(static_cast<int64_t>(count));
  json.key("stride").value(static_cast<int64_t>(stride));
  SceneJson scenes(json);
  json.key("frames").begin_array();
  const std::size_t built = std::min(picked.size(), chosen.episode.frames.size());
  for (std::size_t p = 0; p < built; ++p) {
    const EpisodeFrame& frame = chosen.episode.frames[p];
    json.begin_object();
    json.key("step").value(frame.step);
    json.key("time").value(frame.scene.time, 10);
    json.key("reward").value(frame.reward, 10);
    json.key("return").value(returns[static_cast<std::size_t>(picked[p])], 10);
    json.key("terminated").value(frame.terminated);
    json.key("truncated").value(frame.truncated);
    json.key("action").numbers(frame.action.data(), static_cast<std::size_t>(frame.action.size()));
    named_values(json, "info", frame.info);
    named_values(json, "values", frame.scene.values);
    json.key("scene");
    scenes.write(frame.scene);
    json.end_object();
  }
  json.end_array();
  json.key("springs");
  scenes.write_springs();
  json.end_object();
  return json.str();
}

}  // namespace tendril::dashboard
