// Trained policies (rl::Policy, torch-free) and the trainer, as the extension's `Policy` and
// `train`.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "bindings.hpp"
#include "conversions.hpp"
#include "object_lock.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/interrupt.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/trainer.hpp"

namespace tendril::python {

namespace {

class PyPolicy {
 public:
  PyPolicy(const std::filesystem::path& path, bool best, uint64_t seed) : rng_(seed) {
    std::filesystem::path file = path;
    if (std::filesystem::is_directory(path)) {
      file = path / (best ? "best_model.policy" : "model.policy");
      require(std::filesystem::exists(file),
              "the run has no " + file.filename().string() +
                  " (a run writes model.policy when it finishes; best_model.policy with "
                  "eval.save_best)",
              path.string());
    }
    policy_ = rl::load_policy(file);
    file_ = file;
  }

  const rl::Policy& policy() const { return *policy_; }
  const std::filesystem::path& file() const { return file_; }

  // One observation (obs size,) → one action; a batch (B, obs size) → (B, action size).
  py::array act(const py::handle& value, bool deterministic) {
    // The policy's buffers (and its network's) and its random stream serve one call at a time.
    const auto lock = lock_.acquire();
    const FloatArray array = FloatArray::ensure(value);
    const std::string who = "policy " + file_.string();
    require(static_cast<bool>(array), "observations must be a number array", who);
    const auto size = static_cast<py::ssize_t>(policy_->observation_space().size());
    const bool single = array.ndim() == 1 && array.shape(0) == size;
    const bool batch = array.ndim() == 2 && array.shape(1) == size;
    require(single || batch,
            "expected an observation of shape (" + std::to_string(size) + ",) or a batch (B, " +
                std::to_string(size) + "), got " + std::to_string(array.ndim()) + "-d array of " +
                std::to_string(array.size()) + " values",
            who);
    const py::ssize_t rows = single ? 1 : array.shape(0);
    observations_.resize(rows, size);
    std::copy(array.data(), array.data() + rows * size, observations_.data());
    {
      py::gil_scoped_release release;
      policy_->act(observations_, deterministic, rng_, actions_);
    }
    const auto cols = static_cast<py::ssize_t>(actions_.cols());
    if (policy_->action_space().is_discrete()) {
      py::array_t<int64_t> out(rows);
      for (py::ssize_t r = 0; r < rows; ++r) {
        out.mutable_data()[r] = static_cast<int64_t>(actions_(r, 0));
      }
      if (single) return out.attr("reshape")(py::tuple()).cast<py::array>();
      return out;
    }
    py::array_t<float> out(single ? std::vector<py::ssize_t>{cols}
                                  : std::vector<py::ssize_t>{rows, cols});
    std::copy(actions_.data(), actions_.data() + rows * cols, out.mutable_data());
    return out;
  }

 private:
  std::unique_ptr<rl::Policy> policy_;
  std::filesystem::path file_;
  Rng rng_;
  envs::BatchMatrix observations_, actions_;
  ObjectLock lock_;  // object_lock.hpp
};

// What a training on its worker thread has for Python — the progress line and, with a
// callback, each iteration's report — kept under a lock until the thread that holds the GIL
// passes them on: the line to sys.stderr (so Jupyter shows it), the reports to the callback.
class ProgressRelay {
 public:
  explicit ProgressRelay(py::object callback) : callback_(std::move(callback)) {}

  void connect(rl::TrainOptions& options) {
    options.progress_output = [this](const std::string& text) {
      const std::lock_guard<std::mutex> lock(mutex_);
      text_ += text;
    };
    if (callback_.is_none()) return;
    options.on_iteration = [this](const rl::Progress& progress) {
      const std::lock_guard<std::mutex> lock(mutex_);
      iterations_.push_back(progress);
    };
  }

  // With the GIL held. A callback's exception propagates.
  void deliver() {
    std::string text;
    std::vector<rl::Progress> iterations;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      text.swap(text_);
      iterations.swap(iterations_);
    }
    if (!text.empty()) {
      const py::object stderr_stream = py::module_::import("sys").attr("stderr");
      stderr_stream.attr("write")(text);
      stderr_stream.attr("flush")();
    }
    for (const rl::Progress& progress : iterations) callback_(progress_dict(progress));
  }

 private:
  static py::dict progress_dict(const rl::Progress& p) {
    py::dict report;
    report["timesteps"] = p.timesteps;
    report["iterations"] = p.iterations;
    report["episodes"] = p.episodes;
    if (p.episodes > 0) {
      report["ep_rew_mean"] = p.episode_return_mean;
      report["ep_len_mean"] = p.episode_length_mean;
    }
    if (p.success_rate) report["success_rate"] = *p.success_rate;
    py::dict train;
    for (const auto& [name, value] : p.train) train[py::str(name)] = value;
    report["train"] = train;
    return report;
  }

  py::object callback_;
  std::mutex mutex_;
  std::string text_;
  std::vector<rl::Progress> iterations_;
};

// Runs `work` (a training, GIL-free) on a thread of its own while this thread, holding the GIL
// between short waits, lets Python run its signal handlers: Ctrl-C raises KeyboardInterrupt
// there, which becomes tendril's polite stop (core/interrupt.hpp) — the trainer writes a
// checkpoint at the end of its iteration and returns. The KeyboardInterrupt is then raised with
// where the run stands. Python handles signals in its main thread only; elsewhere this only waits.
// Passes the relay's reports on; a callback that raises stops the training politely (its
// exception is raised once the worker has returned).
void deliver_or_stop(ProgressRelay& relay, std::optional<py::error_already_set>& raised) {
  try {
    relay.deliver();
  } catch (py::error_already_set& error) {
    if (raised) return;
    raised.emplace(std::move(error));
    request_interrupt(SIGINT);
  }
}

rl::TrainResult train_interruptibly(const std::function<rl::TrainResult()>& work,
                                    const std::string& resume_call, ProgressRelay& relay) {
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  rl::TrainResult result;
  std::exception_ptr failure;
  std::thread worker([&] {
    try {
      result = work();
    } catch (...) {
      failure = std::current_exception();
    }
    const std::lock_guard<std::mutex> lock(mutex);
    done = true;
    finished.notify_all();
  });
  std::optional<py::error_already_set> raised;
  while (true) {
    {
      py::gil_scoped_release release;
      std::unique_lock<std::mutex> lock(mutex);
      if (finished.wait_for(lock, std::chrono::milliseconds(100), [&] { return done; })) break;
    }
    deliver_or_stop(relay, raised);
    if (!raised && PyErr_CheckSignals() != 0) {
      raised.emplace();  // takes the exception a signal handler raised
      request_interrupt(SIGINT);
    }
  }
  deliver_or_stop(relay, raised);
  {
    py::gil_scoped_release release;
    worker.join();
  }
  if (raised) clear_interrupt();  // the stop asked for is done; a later run starts afresh
  if (failure) std::rethrow_exception(failure);
  if (!raised) return result;
  if (!raised->matches(PyExc_KeyboardInterrupt)) throw *raised;
  const std::string run = result.run_directory.string();
  const std::string message =
      result.interrupted
          ? "training stopped at " + std::to_string(result.timesteps) +
                " steps; a checkpoint holds the run: " + resume_call + "('" + run +
                "') continues it (or: tendril resume " + run + ")"
          : "training had finished (" + std::to_string(result.timesteps) + " steps, " + run + ")";
  std::fprintf(stderr, "interrupted: %s\n", message.c_str());
  PyErr_SetString(PyExc_KeyboardInterrupt, message.c_str());
  throw py::error_already_set();
}

py::dict train_summary(const rl::TrainResult& result) {
  py::dict summary;
  summary["run_directory"] = result.run_directory.string();
  summary["timesteps"] = result.timesteps;
  summary["finished"] = result.finished;
  summary["final_eval_mean"] = result.final_eval_mean;
  summary["final_eval_std"] = result.final_eval_std;
  summary["seconds"] = result.seconds;
  summary["steps_per_second"] = result.steps_per_second;
  return summary;
}

}  // namespace

void bind_policy(py::module_& m) {
  py::class_<PyPolicy>(m, "Policy", "A trained policy file (rl::load_policy).")
      .def(py::init<const std::filesystem::path&, bool, uint64_t>(), py::arg("path"),
           py::arg("best") = false, py::arg("seed") = 0)
      .def_property_readonly("kind", [](PyPolicy& self) { return self.policy().kind(); })
      .def_property_readonly("file", [](PyPolicy& self) { return self.file().string(); })
      .def_property_readonly(
          "observation_space",
          [](PyPolicy& self) { return space_to_dict(self.policy().observation_space()); })
      .def_property_readonly(
          "action_space",
          [](PyPolicy& self) { return space_to_dict(self.policy().action_space()); })
      .def("act", &PyPolicy::act, py::arg("observation"), py::arg("deterministic") = true);
}

void bind_train(py::module_& m) {
  m.def(
      "train",
      [](const std::filesystem::path& config_file, const std::vector<std::string>& overrides,
         std::optional<std::filesystem::path> out, std::optional<int64_t> stop_at, bool quiet,
         py::object callback) {
        Config config = Config::load_file(config_file);
        for (const std::string& assignment : overrides) {
          const auto equals = assignment.find('=');
          require(equals != std::string::npos && equals > 0,
                  "an override is key.path=value, got '" + assignment + "'", "tendril.train");
          config.set(assignment.substr(0, equals), assignment.substr(equals + 1));
        }
        const rl::Experiment experiment = rl::Experiment::from_config(config);
        const std::filesystem::path run = out ? *out : rl::default_run_directory(experiment);
        rl::TrainOptions options;
        options.stop_at = stop_at;
        options.quiet = quiet;
        ProgressRelay relay(std::move(callback));
        relay.connect(options);
        return train_summary(train_interruptibly(
            [&] { return rl::train(experiment, run, options); }, "tendril.resume", relay));
      },
      py::arg("config_file"), py::arg("overrides") = std::vector<std::string>{},
      py::arg("out") = py::none(), py::arg("stop_at") = py::none(), py::arg("quiet") = false,
      py::arg("callback") = py::none(),
      "Runs an experiment file in-process (tendril train), GIL released; Ctrl-C stops it at a "
      "checkpoint and raises KeyboardInterrupt.");
  m.def(
      "resume",
      [](const std::filesystem::path& run, std::optional<int64_t> stop_at, bool quiet,
         py::object callback) {
        rl::TrainOptions options;
        options.stop_at = stop_at;
        options.quiet = quiet;
        ProgressRelay relay(std::move(callback));
        relay.connect(options);
        return train_summary(
            train_interruptibly([&] { return rl::resume(run, options); }, "tendril.resume", relay));
      },
      py::arg("run_directory"), py::arg("stop_at") = py::none(), py::arg("quiet") = false,
      py::arg("callback") = py::none(),
      "Continues a run from its newest checkpoint (tendril resume), GIL released.");
}

}  // namespace tendril::python
