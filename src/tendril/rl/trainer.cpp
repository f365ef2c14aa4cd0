#include "tendril/rl/trainer.hpp"

#include <chrono>
#include <fstream>
#include <optional>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/rl/training_observers.hpp"

namespace tendril::rl {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// One training run: the vector env, the algorithm and the observers that log, evaluate,
// checkpoint and print (rl/training_observers).
class Run {
 public:
  Run(const Experiment& experiment, fs::path directory, const TrainOptions& options, bool resuming)
      : experiment_(experiment),
        directory_(std::move(directory)),
        options_(options),
        env_(make_vec_env(experiment.env)),
        algorithm_(make_algorithm(experiment, *env_)) {
    fs::create_directories(directory_ / "checkpoints");
    fs::path last_buffer;
    if (resuming) {
      const fs::path checkpoint = latest_checkpoint(directory_);
      algorithm_->load(checkpoint);
      if (algorithm_->has_replay_buffer() && experiment_.save_replay_buffer) {
        algorithm_->load_replay_buffer(buffer_path(checkpoint));
        last_buffer = buffer_path(checkpoint);
      }
    }
    const int64_t first_step = algorithm_->num_timesteps();
    log_.emplace(directory_, resuming, first_step);
    evaluation_.emplace(experiment_, directory_, *algorithm_, *env_, resuming);
    checkpoints_.emplace(experiment_, directory_, *algorithm_, options_.stop_at, last_buffer);
    progress_line_.emplace(experiment_.n_timesteps, first_step);
  }

  TrainResult execute() {
    const auto start = Clock::now();
    const int64_t first_step = algorithm_->num_timesteps();
    Observers observers{&*log_, &*evaluation_, &*checkpoints_};
    if (!options_.quiet) observers.push_back(&*progress_line_);
    algorithm_->learn(experiment_.n_timesteps, observers);
    if (!options_.quiet) progress_line_->finish();

    TrainResult result;
    result.run_directory = directory_;
    result.timesteps = algorithm_->num_timesteps();
    result.finished = result.timesteps >= experiment_.n_timesteps;
    if (result.finished) {
      const EvaluationResult final_eval = evaluation_->evaluate(result.timesteps);
      result.final_eval_mean = final_eval.mean_return();
      result.final_eval_std = final_eval.std_return();
      algorithm_->save_policy(directory_ / "model.policy");
    }
    if (evaluation_->best_mean()) {
      result.best_eval_mean = evaluation_->best_mean();
      result.best_eval_timesteps = evaluation_->best_timesteps();
    }
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.steps_per_second = static_cast<double>(result.timesteps - first_step) / result.seconds;
    return result;
  }

 private:
  const Experiment& experiment_;
  fs::path directory_;
  TrainOptions options_;
  std::unique_ptr<envs::VecEnv> env_;
  std::unique_ptr<Algorithm> algorithm_;
  std::optional<ScalarLogObserver> log_;
  std::optional<EvaluationObserver> evaluation_;
  std::optional<CheckpointObserver> checkpoints_;
  std::optional<ProgressLine> progress_line_;
};

}  // namespace

fs::path latest_checkpoint(const fs::path& run_directory) {
  const fs::path folder = run_directory / "checkpoints";
  fs::path newest;
  int64_t newest_steps = -1;
  if (fs::is_directory(folder)) {
    for (const auto& entry : fs::directory_iterator(folder)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("step_", 0) != 0 || entry.path().extension() != ".ckpt") continue;
      try {
        const int64_t steps = std::stoll(name.substr(5, name.size() - 10));
        if (steps > newest_steps) newest_steps = steps, newest = entry.path();
      } catch (const std::exception&) {
        continue;
      }
    }
  }
  if (newest_steps < 0) throw Error("no checkpoint to resume from", folder.string());
  return newest;
}

TrainResult train(const Experiment& experiment, const fs::path& run_directory,
                  const TrainOptions& options) {
  if (fs::exists(run_directory) && !fs::is_empty(run_directory)) {
    throw Error("run directory is not empty; choose another (nothing was overwritten)",
                run_directory.string());
  }
  fs::create_directories(run_directory);
  std::ofstream(run_directory / "config.yaml") << experiment.config.dump_resolved();
  Run run(experiment, run_directory, options, /*resuming=*/false);
  return run.execute();
}

TrainResult resume(const fs::path& run_directory, const TrainOptions& options) {
  const fs::path config_file = run_directory / "config.yaml";
  if (!fs::exists(config_file))
    throw Error("not a run directory (no config.yaml)", run_directory.string());
  const Experiment experiment = Experiment::from_config(Config::load_file(config_file));
  Run run(experiment, run_directory, options, /*resuming=*/true);
  return run.execute();
}

}  // namespace tendril::rl
