// N tendril environments stepped in C++ (ThreadedVecEnv, GIL released) as the extension's
// `VecEnv`: batches come back as read-only NumPy views of the C++ buffers, valid until the next
// reset or step, or (copy=True) as copies made before another thread's call can refill them.
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "conversions.hpp"
#include "object_lock.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::python {

namespace {

class PyVecEnv {
 public:
  PyVecEnv(const std::string& id, const py::handle& num_envs_value, const std::string& params_json,
           const py::handle& num_threads_value)
      : who_("tendril vector env " + id + " step") {
    const std::string where = "tendril.make_vec('" + id + "')";
    const int num_envs = count_from_python(num_envs_value, "num_envs", where);
    const int num_threads = count_from_python(num_threads_value, "num_threads", where);
    rl::VecEnvOptions options;
    options.id = id;
    options.params = params_from_json(params_json, "tendril.make_vec('" + id + "') params");
    options.n_envs = num_envs;
    options.num_threads = num_threads;
    env_ = rl::make_vec_env(options);
  }

  envs::VecEnv& env() { return *env_; }
  ObjectLock& lock() { return lock_; }

  const envs::BatchMatrix& reset(const py::handle& seed_value) {
    const std::optional<uint64_t> seed = seed_from_python(
        seed_value, static_cast<uint64_t>(env_->num_envs()), "tendril vector env reset");
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
  // One call at a time from Python threads (object_lock.hpp): held while a call steps and while
  // it turns the batches and infos into Python objects.
  ObjectLock lock_;
};

py::array batch_array(const envs::BatchMatrix& batch, py::handle owner, bool copy) {
  if (copy) return float_copy(batch.data(), {batch.rows(), batch.cols()});
  return readonly_view(batch.data(), {batch.rows(), batch.cols()}, owner);
}

}  // namespace

void bind_vec_env(py::module_& m) {
  py::class_<PyVecEnv>(m, "VecEnv",
                       "N copies of a registered environment with auto-reset, stepped in C++.")
      .def(py::init<const std::string&, const py::handle&, const std::string&, const py::handle&>(),
           py::arg("id"), py::arg("num_envs"), py::arg("params_json") = "{}",
           py::arg("num_threads") = 1)
      .def_property_readonly("num_envs", [](PyVecEnv& self) { return self.env().num_envs(); })
      .def_property_readonly(
          "observation_space",
          [](PyVecEnv& self) { return space_to_dict(self.env().observation_space()); })
      .def_property_readonly(
          "action_space", [](PyVecEnv& self) { return space_to_dict(self.env().action_space()); })
      .def(
          "reset",
          [](py::object self, const py::handle& seed, bool copy) {
            PyVecEnv& env = self.cast<PyVecEnv&>();
            const auto lock = env.lock().acquire();
            return batch_array(env.reset(seed), self, copy);
          },
          py::arg("seed") = py::none(), py::arg("copy") = false,
          "Resets env i with seed + i; returns the (num_envs, obs size) observations.")
      .def(
          "step",
          [](py::object self, const py::handle& actions, bool copy) {
            PyVecEnv& env = self.cast<PyVecEnv&>();
            const auto lock = env.lock().acquire();
            const envs::VecStep& step = env.step(actions);
            const auto n = static_cast<py::ssize_t>(step.rewards.size());
            py::array rewards = copy ? float_copy(step.rewards.data(), {n})
                                     : readonly_view(step.rewards.data(), {n}, self);
            py::array_t<bool> terminated(n), truncated(n);
            py::list infos;
            for (py::ssize_t i = 0; i < n; ++i) {
              terminated.mutable_data()[i] = step.terminated[i] != 0;
              truncated.mutable_data()[i] = step.truncated[i] != 0;
              infos.append(info_to_dict(step.infos[i]));
            }
            return py::make_tuple(batch_array(step.observations, self, copy), rewards, terminated,
                                  truncated, batch_array(step.final_observations, self, copy),
                                  infos);
          },
          py::arg("actions"), py::arg("copy") = false,
          "Steps every env; returns (observations, rewards, terminated, truncated, "
          "final_observations, infos), auto-resetting finished episodes.")
      .def(
          "scene",
          [](PyVecEnv& self, int i) -> py::object {
            const auto lock = self.lock().acquire();
            Scene scene;
            if (!self.member(i).describe_scene(scene)) return py::none();
            return scene_to_dict(scene);
          },
          py::arg("index"));
}

}  // namespace tendril::python
