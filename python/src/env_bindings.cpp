// tendril::Env as the extension's `Env`: the environment under tendril.make's gymnasium.Env.
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "conversions.hpp"
#include "object_lock.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/env_description.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/render/scene_rasterizer.hpp"

namespace tendril::python {

namespace {

class PyEnv {
 public:
  PyEnv(const std::string& id, const std::string& params_json)
      : id_(id),
        env_(envs::make(id, params_from_json(params_json, "tendril.make('" + id + "') params"))),
        who_("tendril env " + id + " step") {}

  py::array_t<float> reset(const py::handle& seed_value) {
    const auto lock = lock_.acquire();
    const std::optional<uint64_t> seed = seed_from_python(seed_value, 1, "tendril env " + id_);
    Observation observation;
    {
      py::gil_scoped_release release;
      observation = env_->reset(seed);
    }
    reset_ = true;
    view_.reset();  // each episode is framed anew
    Scene scene;
    if (!step_seconds_ && env_->describe_scene(scene)) reset_time_ = scene.time;
    return to_numpy(observation);
  }

  py::tuple step(const py::handle& action_value) {
    const auto lock = lock_.acquire();
    require(reset_, "call reset() before step()", who_);
    const Action action = action_from_python(env_->action_space(), action_value, who_);
    Step step;
    {
      py::gil_scoped_release release;
      step = env_->step(action);
    }
    if (!step_seconds_ && reset_time_) {  // the scene's clock after one step: its time step
      Scene scene;
      if (env_->describe_scene(scene) && scene.time > *reset_time_) {
        step_seconds_ = scene.time - *reset_time_;
      }
      reset_time_.reset();
    }
    return py::make_tuple(to_numpy(step.observation), step.reward, step.terminated, step.truncated,
                          info_to_dict(step.info));
  }

  py::object scene() {
    const auto lock = lock_.acquire();
    Scene scene;
    if (!env_->describe_scene(scene)) return py::none();
    return scene_to_dict(scene);
  }

  bool has_scene() {
    const auto lock = lock_.acquire();
    Scene scene;
    return env_->describe_scene(scene);
  }

  // The scene now as a height × width × 3 image (render::SceneRasterizer), seen from one view
  // per episode (framed at the first picture after reset); None without a scene.
  py::object render(int width, int height, int supersample) {
    const auto lock = lock_.acquire();
    Scene scene;
    if (!env_->describe_scene(scene)) return py::none();
    const render::RasterOptions options{width, height, supersample};
    if (!rasterizer_ || rasterizer_->options().width != width ||
        rasterizer_->options().height != height ||
        rasterizer_->options().supersample != supersample) {
      rasterizer_.emplace(options);
    }
    if (!view_) view_ = render::frame_scenes({&scene});
    {
      py::gil_scoped_release release;
      rasterizer_->draw(scene, *view_, image_);
    }
    return image_to_numpy(image_);
  }

  std::optional<double> step_seconds() {
    const auto lock = lock_.acquire();
    return step_seconds_;
  }

  // The snapshot with a checksum: a changed or damaged copy is refused, not loaded.
  py::bytes save_state() {
    const auto lock = lock_.acquire();
    Snapshot bytes;
    SnapshotWriter writer(bytes);
    env_->save_state(writer);
    return checksummed_state(
        std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  }

  void load_state(const py::bytes& state) {
    const auto lock = lock_.acquire();
    const std::string bytes =
        verified_state(static_cast<std::string>(state), "tendril env " + id_ + " load_state");
    SnapshotReader reader(
        std::span<const std::byte>(reinterpret_cast<const std::byte*>(bytes.data()), bytes.size()));
    env_->load_state(reader);
    reset_ = true;
  }

  void close() {
    const auto lock = lock_.acquire();
    env_->close();
  }

  const std::string& id() const { return id_; }
  Env& env() { return *env_; }

 private:
  static py::array_t<float> to_numpy(const Observation& observation) {
    py::array_t<float> out(observation.size());
    std::copy(observation.data(), observation.data() + observation.size(), out.mutable_data());
    return out;
  }

  std::string id_;
  std::unique_ptr<Env> env_;
  std::string who_;
  bool reset_ = false;
  std::optional<render::SceneRasterizer> rasterizer_;
  std::optional<render::View> view_;
  render::Image image_;
  std::optional<double> reset_time_, step_seconds_;
  ObjectLock lock_;  // one call at a time from Python threads (object_lock.hpp)
};

py::list entries_to_list(const std::vector<envs::EnvDescription::Entries>& entries) {
  py::list list;
  for (const auto& run : entries) {
    py::dict entry;
    entry["name"] = run.name;
    entry["unit"] = run.unit;
    entry["count"] = run.count;
    list.append(entry);
  }
  return list;
}

py::dict describe_env(const std::string& id) {
  const envs::Registry& registry = envs::builtin_registry();
  const envs::EnvSpec& spec = registry.spec(id);
  py::dict out;
  out["id"] = spec.id;
  out["summary"] = spec.summary;
  out["max_episode_steps"] = spec.max_episode_steps;
  if (!spec.description) return out;
  const envs::EnvDescription words = spec.description();
  const auto read = envs::parameters_read(registry, id);
  out["observation"] = entries_to_list(words.observation);
  out["action"] = entries_to_list(words.action);
  out["reward"] = words.reward;
  out["episode_end"] = words.episode_end;
  py::list parameters;
  for (const auto& p : words.parameters) {
    py::dict parameter;
    parameter["key"] = p.key;
    parameter["default"] = py::none();
    for (const auto& [key, value] : read) {
      if (key == p.key) parameter["default"] = value;  // YAML text, as the config file writes it
    }
    parameter["unit"] = p.unit;
    parameter["meaning"] = p.meaning;
    parameter["optional"] = p.optional;
    parameters.append(parameter);
  }
  out["parameters"] = parameters;
  return out;
}

}  // namespace

void bind_env(py::module_& m) {
  m.def("registered_ids", &envs::registered_ids, "Every registered environment id, sorted.");
  m.def(
      "max_episode_steps",
      [](const std::string& id) { return envs::builtin_registry().spec(id).max_episode_steps; },
      "The registered time limit of `id` (None when it has none).");
  m.def(
      "summary", [](const std::string& id) { return envs::builtin_registry().spec(id).summary; },
      "One line describing `id`.");
  m.def("describe", &describe_env,
        "`id` in words: its observation and action entries (name, unit, count), reward, "
        "episode end and parameters (key, the default it read or None, unit, meaning), as "
        "`tendril list envs --describe` prints them.");

  py::class_<PyEnv>(m, "Env", "One registered tendril environment (with its time limit).")
      .def(py::init<const std::string&, const std::string&>(), py::arg("id"),
           py::arg("params_json") = "{}")
      .def_property_readonly("id", &PyEnv::id)
      .def_property_readonly(
          "observation_space",
          [](PyEnv& self) { return space_to_dict(self.env().observation_space()); })
      .def_property_readonly("action_space",
                             [](PyEnv& self) { return space_to_dict(self.env().action_space()); })
      .def("reset", &PyEnv::reset, py::arg("seed") = py::none())
      .def("step", &PyEnv::step, py::arg("action"))
      .def("scene", &PyEnv::scene)
      .def_property_readonly("has_scene", &PyEnv::has_scene)
      .def("render", &PyEnv::render, py::arg("width") = 640, py::arg("height") = 480,
           py::arg("supersample") = 2)
      .def_property_readonly("step_seconds", &PyEnv::step_seconds,
                             "Seconds of the scene's clock per step (None until known).")
      .def_property_readonly("supports_snapshots",
                             [](PyEnv& self) { return self.env().supports_snapshots(); })
      .def("save_state", &PyEnv::save_state)
      .def("load_state", &PyEnv::load_state, py::arg("state"))
      .def("close", &PyEnv::close);
}

}  // namespace tendril::python
