// N tendril environments stepped in C++ (ThreadedVecEnv, GIL released) as the extension's
// `VecEnv`: batches come back as read-only NumPy views of the C++ buffers, valid until the next
// reset or step.
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "conversions.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::python {

namespace {

class PyVecEnv {
 public:
  PyVecEnv(const std::string& id, int num_envs, const std::string& params_json, int num_threads)
      : who_("tendril vector env " + id + " step") {
    require(num_envs >= 1, "num_envs must be at least 1, got " + std::to_string(num_envs),
            "tendril.make_vec('" + id + "')");
    require(num_threads >= 1, "num_threads must be at least 1, got " + std::to_string(num_threads),
            "tendril.make_vec('" + id + "')");
    rl::VecEnvOptions options;
    options.id = id;
    options.params = params_from_json(params_json, "tendril.make_vec('" + id + "') params");
    options.n_envs = num_envs;
    options.num_threads = num_threads;
    env_ = rl::make_vec_env(options);
  }

  envs::VecEnv& env() { return *env_; }

  const envs::BatchMatrix& reset(std::optional<uint64_t> seed) {
    const envs::BatchMatrix* observations = nullptr;
    {
      py::gil_scoped_release release;
      observations = &env_->reset(seed);
    }
    ready_ = true;
    return *observations;
  }

  const envs::VecStep& step(const py::handle& actions_value) {
    require(ready_, "call reset() before step() (and after an error)", who_);
    batch_from_python(env_->action_space(), env_->num_envs(), actions_value, who_, actions_);
    try {
      py::gil_scoped_release release;
      return env_->step(actions_);
    } catch (...) {
      ready_ = false;  // a failed step leaves the batch to be reset (VecEnv::step)
      throw;
    }
  }

  Env& member(int i) {
    auto* threaded = dynamic_cast<envs::ThreadedVecEnv*>(env_.get());
    require(threaded != nullptr, "this vector env does not expose its environments", who_);
    require(
        i >= 0 && i < env_->num_envs(),
        "env index " + std::to_string(i) + " outside [0, " + std::to_string(env_->num_envs()) + ")",
        who_);
    return threaded->env(i);
  }

 private:
  std::string who_;
  std::unique_ptr<envs::VecEnv> env_;
  envs::BatchMatrix actions_;
  bool ready_ = false;
};

py::array batch_view(const envs::BatchMatrix& batch, py::handle owner) {
  return readonly_view(batch.data(), {batch.rows(), batch.cols()}, owner);
}

}  // namespace

void bind_vec_env(py::module_& m) {
  py::class_<PyVecEnv>(m, "VecEnv",
                       "N copies of a registered environment with auto-reset, stepped in C++.")
      .def(py::init<const std::string&, int, const std::string&, int>(), py::arg("id"),
           py::arg("num_envs"), py::arg("params_json") = "{}", py::arg("num_threads") = 1)
      .def_property_readonly("num_envs", [](PyVecEnv& self) { return self.env().num_envs(); })
      .def_property_readonly(
          "observation_space",
          [](PyVecEnv& self) { return space_to_dict(self.env().observation_space()); })
      .def_property_readonly(
          "action_space", [](PyVecEnv& self) { return space_to_dict(self.env().action_space()); })
      .def(
          "reset",
          [](py::object self, std::optional<uint64_t> seed) {
            return batch_view(self.cast<PyVecEnv&>().reset(seed), self);
          },
          py::arg("seed") = py::none(),
          "Resets env i with seed + i; returns the (num_envs, obs size) observations.")
      .def(
          "step",
          [](py::object self, const py::handle& actions) {
            const envs::VecStep& step = self.cast<PyVecEnv&>().step(actions);
            const auto n = static_cast<py::ssize_t>(step.rewards.size());
            py::array rewards = readonly_view(step.rewards.data(), {n}, self);
            py::array_t<bool> terminated(n), truncated(n);
            py::list infos;
            for (py::ssize_t i = 0; i < n; ++i) {
              terminated.mutable_data()[i] = step.terminated[i] != 0;
              truncated.mutable_data()[i] = step.truncated[i] != 0;
              infos.append(info_to_dict(step.infos[i]));
            }
            return py::make_tuple(batch_view(step.observations, self), rewards, terminated,
                                  truncated, batch_view(step.final_observations, self), infos);
          },
          py::arg("actions"),
          "Steps every env; returns (observations, rewards, terminated, truncated, "
          "final_observations, infos), auto-resetting finished episodes.")
      .def(
          "scene",
          [](PyVecEnv& self, int i) -> py::object {
            Scene scene;
            if (!self.member(i).describe_scene(scene)) return py::none();
            return scene_to_dict(scene);
          },
          py::arg("index"));
}

}  // namespace tendril::python
