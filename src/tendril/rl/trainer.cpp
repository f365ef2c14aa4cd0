#include "tendril/rl/trainer.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iterator>
#include <new>
#include <optional>
#include <string>
#include <string_view>

#include "tendril/core/archive.hpp"
#include "tendril/core/atomic_file.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/log.hpp"
#include "tendril/core/run_lock.hpp"
#include "tendril/core/run_record.hpp"
#include "tendril/rl/replay_buffer.hpp"
#include "tendril/rl/training_observers.hpp"

namespace tendril::rl {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The step count of "step_<N>.ckpt", -1 for other names.
int64_t checkpoint_steps(const fs::path& file) {
  const std::string name = file.filename().string();
  if (name.rfind("step_", 0) != 0 || file.extension() != ".ckpt") return -1;
  try {
    std::size_t used = 0;
    const std::string digits = name.substr(5, name.size() - 10);
    const int64_t steps = std::stoll(digits, &used);
    return used == digits.size() ? steps : -1;
  } catch (const std::exception&) {
    return -1;
  }
}

// Removes what killed writers leave behind: temporary files of atomic writes, and replay
// buffers whose checkpoint was never written. Called with the run's lock held.
void remove_leftovers(const fs::path& directory) {
  for (const fs::path& folder : {directory, directory / "checkpoints"}) {
    if (!fs::is_directory(folder)) continue;
    std::vector<fs::path> doomed;
    for (const auto& entry : fs::directory_iterator(folder)) {
      const fs::path& file = entry.path();
      const std::string name = file.filename().string();
      const bool orphan_buffer =
          file.extension() == ".buffer" && !fs::exists(fs::path(file).replace_extension(".ckpt"));
      if (is_atomic_write_leftover(name) || name == "progress.csv.tmp" || orphan_buffer) {
        doomed.push_back(file);
      }
    }
    for (const fs::path& file : doomed) {
      log::info("removing ", file.string(), ", left by an interrupted write");
      fs::remove(file);
    }
  }
}

// What ties a run's checkpoints to it: the checksum of its config.yaml (experiment and seed).
// Two runs of the same file compute the same, so sharing an identity is harmless.
std::string run_identity(const fs::path& directory) {
  std::ifstream in(directory / "config.yaml", std::ios::binary);
  require(in.good(), "cannot read the run's config.yaml", directory.string());
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return checksum_text(crc32c(text.data(), text.size()));
}

// Whether the directory holds nothing but its lock and leftovers of atomic writes.
bool holds_nothing(const fs::path& directory) {
  for (const auto& entry : fs::directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (name != RunLock::kFileName && !is_atomic_write_leftover(name)) return false;
  }
  return true;
}

// Whether the directory holds an earlier start of this very experiment that never reached a
// checkpoint (a sweep interrupted early): its files can only be recomputed, never lost.
bool unstarted_attempt(const fs::path& directory, const std::string& config_text) {
  if (fs::exists(directory / "model.policy") || !checkpoints(directory).empty()) return false;
  std::ifstream in(directory / "config.yaml", std::ios::binary);
  if (!in) return false;
  const std::string saved((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return saved == with_checksum(config_text);
}

// One training run: the vector env, the algorithm and the observers that log, evaluate,
// checkpoint and print (rl/training_observers).
class Run {
 public:
  Run(const Experiment& experiment, fs::path directory, const TrainOptions& options, RunLock lock,
      bool resuming)
      : experiment_(experiment),
        directory_(std::move(directory)),
        options_(options),
        lock_(std::move(lock)),
        companion_(options.companion ? options.companion() : nullptr),
        env_(companion_ ? companion_->attach(make_vec_env(experiment.env))
                        : make_vec_env(experiment.env)),
        algorithm_(make_algorithm(experiment, *env_)) {
    if (companion_) companion_->bind(*algorithm_);
    fs::create_directories(directory_ / "checkpoints");
    const std::string identity = run_identity(directory_);
    if (resuming) {
      restore_newest_usable(identity);
    } else if (!experiment_.warm_start.empty()) {
      algorithm_->warm_start(experiment_.warm_start);
      log::info("warm start from ", experiment_.warm_start);
    }
    const int64_t first_step = algorithm_->num_timesteps();
    log_.emplace(directory_, resuming, first_step);
    evaluation_.emplace(experiment_, directory_, *algorithm_, *env_, resuming);
    evaluation_->report_to(&*log_);
    checkpoints_.emplace(experiment_, directory_, *algorithm_, options_.stop_at, identity);
    log_->add_scalars_of(companion_.get());
    checkpoints_->carry(companion_.get());
    progress_line_.emplace(experiment_.n_timesteps, first_step, options_.progress_output);
  }

  TrainResult execute() {
    const auto start = Clock::now();
    const int64_t first_step = algorithm_->num_timesteps();
    Observers observers;
    if (companion_) observers.push_back(companion_.get());
    observers.insert(observers.end(), {&*log_, &*evaluation_, &*checkpoints_});
    if (!options_.quiet) observers.push_back(&*progress_line_);
    IterationCallback monitor([this](const Progress& progress) {
      options_.on_iteration(progress);
      return true;
    });
    if (options_.on_iteration) observers.push_back(&monitor);
    algorithm_->learn(experiment_.n_timesteps, observers);
    if (companion_) companion_->unbind(*algorithm_);
    if (!options_.quiet) progress_line_->finish();

    TrainResult result;
    result.run_directory = directory_;
    result.timesteps = algorithm_->num_timesteps();
    result.finished = result.timesteps >= experiment_.n_timesteps;
    result.interrupted = result.finished ? 0 : checkpoints_->interrupted();
    if (result.finished) {
      const envs::RunResult final_eval = evaluation_->evaluate(result.timesteps);
      result.final_eval_mean = final_eval.mean_return();
      result.final_eval_std = final_eval.std_return();
      if (companion_) companion_->finish(directory_);
      algorithm_->save_policy(directory_ / "model.policy");
    }
    if (companion_) companion_->add_scalars(result.companion_scalars);
    if (evaluation_->best_mean()) {
      result.best_eval_mean = evaluation_->best_mean();
      result.best_eval_timesteps = evaluation_->best_timesteps();
    }
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.steps_per_second = static_cast<double>(result.timesteps - first_step) / result.seconds;
    return result;
  }

 private:
  // Loads the newest checkpoint that verifies, belongs to this run and, when the run keeps its
  // replay buffer, comes with its own intact buffer. Newer unusable checkpoints are set aside
  // as `.corrupt` (kept for inspection; training writes their steps again).
  void restore_newest_usable(const std::string& identity) {
    const bool with_buffer = algorithm_->has_replay_buffer() && experiment_.save_replay_buffer;
    const auto load = [&](const fs::path& file) {
      Algorithm::Labels expected = {{"run", identity}};
      if (with_buffer) {
        const uint32_t buffer = replay_buffer_checksum(buffer_path(file));
        expected.emplace_back("replay_buffer", checksum_text(buffer));
      }
      if (companion_) expected.emplace_back("companion", companion_->name());
      const Algorithm::ExtraReader read_companion =
          [this](const ArchiveReader& reader) -> std::function<void()> {
        if (companion_) return companion_->load(reader);
        if (reader.contains("label/companion")) {
          throw Error("holds the state of a " + reader.get_string("label/companion") +
                          " trained beside the algorithm; resume it with what trains that too "
                          "(tendril resume reads it from the run's config.yaml)",
                      reader.name());
        }
        return nullptr;
      };
      algorithm_->load(file, expected, read_companion);
      if (with_buffer) algorithm_->load_replay_buffer(buffer_path(file));
    };
    std::vector<std::string> skipped;
    const fs::path checkpoint = newest_usable_checkpoint(directory_, load, &skipped);
    for (const fs::path& newer : checkpoints(directory_)) {
      if (newer == checkpoint) break;
      fs::rename(newer, newer.string() + ".corrupt");
    }
    for (const std::string& reason : skipped) {
      log::warning("skipped ", reason, " (kept as .corrupt); resuming from ",
                   checkpoint.filename().string());
    }
    if (algorithm_->has_replay_buffer() && !with_buffer) {
      log::warning("resuming from ", checkpoint.filename().string(),
                   " with an empty replay buffer: this run does not keep its buffer "
                   "(save_replay_buffer: false), so from here on it differs from an "
                   "uninterrupted run");
    }
    remove_leftovers(directory_);
  }

  const Experiment& experiment_;
  fs::path directory_;
  TrainOptions options_;
  RunLock lock_;  // held for the run's lifetime
  // Before the env: a wrapper in env_ may borrow what the companion owns.
  std::unique_ptr<RunCompanion> companion_;
  std::unique_ptr<envs::VecEnv> env_;
  std::unique_ptr<Algorithm> algorithm_;
  std::optional<ScalarLogObserver> log_;
  std::optional<EvaluationObserver> evaluation_;
  std::optional<CheckpointObserver> checkpoints_;
  std::optional<ProgressLine> progress_line_;
};

TrainResult run(const Experiment& experiment, const fs::path& directory,
                const TrainOptions& options, RunLock lock, bool resuming) {
  try {
    Run run(experiment, directory, options, std::move(lock), resuming);
    return run.execute();
  } catch (const std::bad_alloc&) {
    throw Error(out_of_memory_message(experiment), experiment.config.source());
  }
}

}  // namespace

std::vector<fs::path> checkpoints(const fs::path& run_directory) {
  std::vector<std::pair<int64_t, fs::path>> found;
  const fs::path folder = run_directory / "checkpoints";
  if (fs::is_directory(folder)) {
    for (const auto& entry : fs::directory_iterator(folder)) {
      const int64_t steps = checkpoint_steps(entry.path());
      if (steps >= 0) found.emplace_back(steps, entry.path());
    }
  }
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<fs::path> files;
  for (auto& [steps, file] : found) files.push_back(std::move(file));
  return files;
}

fs::path latest_checkpoint(const fs::path& run_directory) {
  const std::vector<fs::path> files = checkpoints(run_directory);
  if (files.empty())
    throw Error("no checkpoint to resume from", (run_directory / "checkpoints").string());
  return files.front();
}

fs::path newest_usable_checkpoint(const fs::path& run_directory,
                                  const std::function<void(const fs::path&)>& use,
                                  std::vector<std::string>* skipped) {
  std::vector<std::string> reasons;
  for (const fs::path& file : checkpoints(run_directory)) {
    try {
      use(file);
      if (skipped) *skipped = reasons;
      return file;
    } catch (const Error& e) {
      reasons.push_back(e.what());
    }
  }
  if (reasons.empty()) {
    throw Error("no checkpoint to resume from", (run_directory / "checkpoints").string());
  }
  std::string text = "no usable checkpoint to resume from:";
  for (const std::string& reason : reasons) text += "\n  " + reason;
  throw Error(text, (run_directory / "checkpoints").string());
}

fs::path newest_intact_checkpoint(const fs::path& run_directory,
                                  std::vector<std::string>* skipped) {
  return newest_usable_checkpoint(
      run_directory, [](const fs::path& file) { ArchiveReader verified(file, "checkpoint"); },
      skipped);
}

fs::path default_run_directory(const Experiment& experiment) {
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
  return experiment.output + "-seed" + std::to_string(experiment.seed) + "-" + stamp;
}

namespace {

// A pause lands on a checkpoint: without checkpoints it would never come.
void require_checkpoints_for_pause(const Experiment& experiment, const TrainOptions& options) {
  require(!options.stop_at || experiment.checkpoint_freq > 0,
          "needs checkpoints to pause at: set checkpoint_freq (e.g. --set checkpoint_freq=100000)",
          "--stop-at");
}

}  // namespace

TrainResult train(const Experiment& experiment, const fs::path& run_directory,
                  const TrainOptions& options) {
  const std::string where = run_directory.string();
  require_checkpoints_for_pause(experiment, options);
  require(!run_directory.empty(), "the run directory needs a name", "--out");
  require(experiment.warm_start.empty() || fs::is_regular_file(experiment.warm_start),
          "no checkpoint file " + experiment.warm_start + " to start from",
          experiment.config.source() + ": warm_start");
  std::error_code error;
  fs::create_directories(run_directory, error);
  if (error || !fs::is_directory(run_directory)) {
    throw Error("cannot create the run directory: " +
                    (error ? error.message() : std::string("a file of that name exists")),
                where);
  }
  const bool had_lock_file = fs::exists(run_directory / RunLock::kFileName);
  RunLock lock(run_directory);
  const std::string config_text = experiment.config.dump_resolved();
  if (!holds_nothing(run_directory)) {
    if (!options.restart_unstarted || !unstarted_attempt(run_directory, config_text)) {
      if (!had_lock_file) fs::remove(lock.file());
      throw Error("run directory is not empty; choose another (nothing was overwritten)", where);
    }
    log::info("restarting ", where, ": its earlier start never reached a checkpoint");
    for (const auto& entry : fs::directory_iterator(run_directory)) {
      if (entry.path().filename() != RunLock::kFileName) fs::remove_all(entry.path());
    }
  }
  remove_leftovers(run_directory);
  write_run_record(run_directory, config_text);
  return run(experiment, run_directory, options, std::move(lock), /*resuming=*/false);
}

Experiment load_run_experiment(const fs::path& run_directory,
                               const std::vector<std::pair<std::string, std::string>>& overrides) {
  return Experiment::from_config(load_run_config(run_directory, overrides));
}

Config load_run_config(const fs::path& run_directory,
                       const std::vector<std::pair<std::string, std::string>>& overrides) {
  Config config = tendril::load_run_config(run_directory);
  for (const auto& [key, value] : overrides) config.set(key, value);
  return config;
}

TrainResult resume(const fs::path& run_directory, const TrainOptions& options) {
  const fs::path config_file = run_directory / "config.yaml";
  if (!fs::exists(config_file))
    throw Error("not a run directory (no config.yaml)", run_directory.string());
  return resume(run_directory, load_run_experiment(run_directory), options);
}

TrainResult resume(const fs::path& run_directory, const Experiment& experiment,
                   const TrainOptions& options) {
  require_checkpoints_for_pause(experiment, options);
  RunLock lock(run_directory);
  if (fs::exists(run_directory / "model.policy")) {
    throw Error(
        "the run has finished (model.policy is there): nothing to resume, nothing "
        "was changed; start a new run to train longer",
        run_directory.string());
  }
  return run(experiment, run_directory, options, std::move(lock), /*resuming=*/true);
}

}  // namespace tendril::rl
