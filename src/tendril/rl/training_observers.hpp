#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "tendril/core/scalar_log.hpp"
#include "tendril/envs/runner/policy_runner.hpp"
#include "tendril/rl/algorithm.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/rl/run_companion.hpp"

namespace tendril::rl {

// The observers a training run is made of (rl/trainer): each does one job on the iterations
// the algorithm reports.

// progress.csv and the TensorBoard event file (core/scalar_log), Stable-Baselines3's names.
// On resume, `first_step` is the checkpoint's step: rows logged past it are dropped.
class ScalarLogObserver : public Observer {
 public:
  ScalarLogObserver(const std::filesystem::path& directory, bool resuming, int64_t first_step);
  bool on_iteration(const Progress& progress) override;
  // An evaluation into the event file under SB3's EvalCallback names: eval/mean_reward,
  // eval/mean_ep_length and, for envs that report success, eval/success_rate.
  void log_evaluation(int64_t timesteps, const envs::RunResult& evaluation);
  // Scalars of what trains beside the algorithm, appended to every iteration's (none when
  // null).
  void add_scalars_of(RunCompanion* companion) { companion_ = companion; }

 private:
  ScalarLog log_;
  RunCompanion* companion_ = nullptr;
  std::chrono::steady_clock::time_point start_;
  int64_t first_step_;
};

// Evaluation every `eval.freq` steps into eval.csv, and with `eval.save_best` the policy of the
// best evaluation so far as best_model.policy (highest mean return; the latest of equals, which
// has trained longest). Evaluates on a fresh environment with the training vector env's frozen
// observation statistics and raw rewards (SB3's EvalCallback on a VecNormalize'd model).
// eval.csv gets its header when the observer is made; on resume, rows past the checkpoint
// (evaluations of a process killed after it) are dropped and a missing header is restored.
// Every row is written with a check: a failed write raises Error naming eval.csv.
class EvaluationObserver : public Observer {
 public:
  EvaluationObserver(const Experiment& experiment, const std::filesystem::path& directory,
                     Algorithm& algorithm, const envs::VecEnv& training_env, bool resuming);
  bool on_iteration(const Progress& progress) override;
  // Evaluates now (the final evaluation), records it and returns it.
  envs::RunResult evaluate(int64_t timesteps);
  // Every evaluation is also logged to `log` (the TensorBoard event file); none when null.
  void report_to(ScalarLogObserver* log) { log_ = log; }

  std::optional<double> best_mean() const { return best_mean_; }
  int64_t best_timesteps() const { return best_timesteps_; }

 private:
  // On resume: eval.csv up to the checkpoint, and the best evaluation in it.
  void restore(int64_t up_to);
  // Removes the recorded episodes of evaluations after step `up_to`.
  void remove_recordings_after(int64_t up_to) const;

  const Experiment& experiment_;
  std::filesystem::path directory_;
  Algorithm& algorithm_;
  const envs::VecEnv& training_env_;
  int64_t last_timesteps_;
  std::optional<double> best_mean_;
  int64_t best_timesteps_ = 0;
  ScalarLogObserver* log_ = nullptr;
};

// A checkpoint every `checkpoint_freq` steps (checkpoints/step_<N>.ckpt, the replay buffer
// beside the newest two when asked, so a resume can fall back one checkpoint), and the pause at
// `stop_at`. Each checkpoint is labelled with `run_identity` and its replay buffer's checksum
// (Algorithm::save), so a resume never pairs it with another run's files. After SIGINT/SIGTERM
// (core/interrupt) it writes a checkpoint at the end of the current iteration and stops
// training; `interrupted()` is then the signal.
class CheckpointObserver : public Observer {
 public:
  CheckpointObserver(const Experiment& experiment, const std::filesystem::path& directory,
                     Algorithm& algorithm, std::optional<int64_t> stop_at,
                     std::string run_identity);
  bool on_iteration(const Progress& progress) override;
  int interrupted() const { return interrupted_; }
  // What trains beside the algorithm goes into every checkpoint too (none when null).
  void carry(const RunCompanion* companion) { companion_ = companion; }

 private:
  void save(int64_t timesteps);
  const RunCompanion* companion_ = nullptr;

  const Experiment& experiment_;
  std::filesystem::path directory_;
  Algorithm& algorithm_;
  std::optional<int64_t> stop_at_;
  std::string run_identity_;
  int64_t last_timesteps_;
  int interrupted_ = 0;
};

// The live progress line: steps, steps/s, mean return, ETA; on standard error, or to `output`
// (e.g. Python's sys.stderr) when set.
class ProgressLine : public Observer {
 public:
  ProgressLine(int64_t total_timesteps, int64_t first_step,
               std::function<void(const std::string&)> output = nullptr);
  bool on_iteration(const Progress& progress) override;
  void finish();  // the last line, then a newline

 private:
  void print(const Progress& progress);
  void write(const std::string& text) const;

  int64_t total_timesteps_, first_step_;
  std::function<void(const std::string&)> output_;
  std::chrono::steady_clock::time_point start_, last_print_;
  std::optional<Progress> last_;
};

// Paths inside a run directory.
std::filesystem::path checkpoint_path(const std::filesystem::path& run, int64_t steps);
std::filesystem::path buffer_path(const std::filesystem::path& checkpoint);

}  // namespace tendril::rl
