#include "tendril/rl/training_observers.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/interrupt.hpp"
#include "tendril/core/progress_clock.hpp"
#include "tendril/envs/wrappers/episode_recorder.hpp"
#include "tendril/rl/trainer.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// success_rate: the fraction of the evaluation's episodes that ended at their goal (their last
// info's is_success; seed 001 §5.3.1's success rate), empty for envs that report no success.
constexpr const char* kEvalHeader =
    "timesteps,mean_return,std_return,mean_length,episodes,success_rate\n";
// eval.csv of runs from before success rates were evaluated; resuming one adds the column.
constexpr const char* kOldEvalHeader = "timesteps,mean_return,std_return,mean_length,episodes\n";

double seconds_between(Clock::time_point start, Clock::time_point end) {
  return std::chrono::duration<double>(end - start).count();
}

// The shortest decimal text that reads back as exactly `value`: a resumed run recalls its best
// evaluation from eval.csv and must compare as the uninterrupted run does.
std::string exact_text(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

// Whether the step count crossed a multiple of `every` since `previous`.
bool crossed(int64_t every, int64_t previous, int64_t now) {
  return every > 0 && now / every > previous / every;
}

}  // namespace

fs::path checkpoint_path(const fs::path& run, int64_t steps) {
  return run / "checkpoints" / ("step_" + std::to_string(steps) + ".ckpt");
}

fs::path buffer_path(const fs::path& checkpoint) {
  return fs::path(checkpoint).replace_extension(".buffer");
}

ScalarLogObserver::ScalarLogObserver(const fs::path& directory, bool resuming, int64_t first_step)
    : log_(directory, resuming, first_step), start_(Clock::now()), first_step_(first_step) {}

bool ScalarLogObserver::on_iteration(const Progress& p) {
  const double elapsed = seconds_between(start_, Clock::now());
  const double fps = static_cast<double>(p.timesteps - first_step_) / std::max(elapsed, 1e-9);
  log_.record("time/total_timesteps", static_cast<double>(p.timesteps));
  log_.record("time/iterations", static_cast<double>(p.iterations));
  log_.record("time/fps", fps);
  log_.record("time/time_elapsed", elapsed);
  if (p.episodes > 0) {
    log_.record("rollout/ep_rew_mean", p.episode_return_mean);
    log_.record("rollout/ep_len_mean", p.episode_length_mean);
  }
  if (p.success_rate) log_.record("rollout/success_rate", *p.success_rate);
  if (p.curriculum_level) log_.record("rollout/curriculum_level", *p.curriculum_level);
  for (const auto& [name, value] : p.train) log_.record(name, value);
  if (companion_ != nullptr) {
    TrainStats extra;
    companion_->add_scalars(extra);
    for (const auto& [name, value] : extra) log_.record(name, value);
  }
  log_.dump(p.timesteps);
  return true;
}

void ScalarLogObserver::log_evaluation(int64_t timesteps, const envs::RunResult& evaluation) {
  std::map<std::string, double> scalars = {{"eval/mean_reward", evaluation.mean_return()},
                                           {"eval/mean_ep_length", evaluation.mean_length()}};
  if (const std::optional<double> rate = evaluation.success_rate()) {
    scalars["eval/success_rate"] = *rate;
  }
  log_.write_events(timesteps, scalars);
}

EvaluationObserver::EvaluationObserver(const Experiment& experiment, const fs::path& directory,
                                       Algorithm& algorithm, const envs::VecEnv& training_env,
                                       bool resuming)
    : experiment_(experiment),
      directory_(directory),
      algorithm_(algorithm),
      training_env_(training_env),
      last_timesteps_(algorithm.num_timesteps()) {
  if (resuming) {
    restore(last_timesteps_);
  } else {
    write_file_atomically(directory_ / "eval.csv", kEvalHeader, "eval.csv");
  }
}

bool EvaluationObserver::on_iteration(const Progress& progress) {
  const int64_t previous = last_timesteps_;
  last_timesteps_ = progress.timesteps;
  if (crossed(experiment_.eval_freq, previous, progress.timesteps) &&
      progress.timesteps < experiment_.n_timesteps) {
    evaluate(progress.timesteps);
  }
  return true;
}

envs::RunResult EvaluationObserver::evaluate(int64_t timesteps) {
  // Seeds of their own per evaluation point, so evaluating never disturbs training: episode k
  // resets with seed + k (the policy runner's rule).
  envs::RunSettings settings;
  settings.episodes = experiment_.eval_episodes;
  settings.seed = experiment_.seed + 1000003 + timesteps;
  settings.deterministic = experiment_.eval_deterministic;
  envs::RunResult eval;
  if (experiment_.eval_n_envs > 1) {
    VecEnvOptions options = evaluation_env_options(experiment_);
    options.n_envs = experiment_.eval_n_envs;
    options.normalize_observation = options.normalize_reward = false;
    const std::unique_ptr<envs::VecEnv> envs = make_vec_env(options);
    eval = envs::run_policy(algorithm_.policy(), *envs, settings);
  } else {
    std::unique_ptr<Env> env =
        make_evaluation_env(evaluation_env_options(experiment_), training_env_);
    if (experiment_.eval_record > 0) {
      envs::RecordingOptions options;
      options.directory = directory_ / "episodes";
      options.prefix = "eval_" + std::to_string(timesteps);
      options.max_episodes = experiment_.eval_record;
      options.metadata = {
          {"env", experiment_.env.id},
          {"run", fs::absolute(directory_).lexically_normal().string()},
          {"model", "evaluation at step " + std::to_string(timesteps)},
          {"actions", experiment_.eval_deterministic ? "deterministic" : "stochastic"}};
      env = std::make_unique<envs::EpisodeRecorder>(std::move(env), std::move(options));
    }
    eval = envs::run_policy(algorithm_.policy(), *env, settings);
  }
  std::ostringstream row;
  row << timesteps << ',' << exact_text(eval.mean_return()) << ',' << exact_text(eval.std_return())
      << ',' << eval.mean_length() << ',' << eval.episodes.size() << ',';
  if (const std::optional<double> rate = eval.success_rate()) row << exact_text(*rate);
  row << '\n';
  append_to_file(directory_ / "eval.csv", row.str(), "eval.csv");
  if (log_ != nullptr) log_->log_evaluation(timesteps, eval);
  if (experiment_.eval_save_best && (!best_mean_ || eval.mean_return() >= *best_mean_)) {
    algorithm_.save_policy(directory_ / "best_model.policy");
    best_mean_ = eval.mean_return();
    best_timesteps_ = timesteps;
  }
  return eval;
}

void EvaluationObserver::restore(int64_t up_to) {
  const fs::path file = directory_ / "eval.csv";
  if (fs::exists(file) && !fs::is_regular_file(file)) {
    throw Error("not a regular file: evaluations cannot be logged", file.string());
  }
  std::ifstream stream(file, std::ios::binary);
  const std::string original((std::istreambuf_iterator<char>(stream)),
                             std::istreambuf_iterator<char>());
  // A row cut short by a kill (no newline yet) is dropped; its evaluation comes again.
  std::istringstream in(original.substr(0, original.rfind('\n') + 1));
  std::string line, kept = kEvalHeader;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() ||
        (number == 1 && (line + '\n' == kEvalHeader || line + '\n' == kOldEvalHeader))) {
      continue;
    }
    if (std::count(line.begin(), line.end(), ',') == 4) line += ',';  // an old row
    int64_t timesteps = 0;
    double mean = 0.0;
    const std::size_t comma = line.find(',');
    const std::size_t next = line.find(',', comma + 1);
    const bool parsed =
        comma != std::string::npos && next != std::string::npos &&
        std::from_chars(line.data(), line.data() + comma, timesteps).ptr == line.data() + comma &&
        std::from_chars(line.data() + comma + 1, line.data() + next, mean).ptr ==
            line.data() + next;
    if (!parsed) {
      throw Error("unreadable row " + std::to_string(number) + ": '" + line.substr(0, 80) + "'",
                  file.string());
    }
    if (timesteps > up_to) continue;  // evaluated after the checkpoint, by a killed process
    kept += line + '\n';
    if (experiment_.eval_save_best && (!best_mean_ || mean >= *best_mean_)) {
      best_mean_ = mean;
      best_timesteps_ = timesteps;
    }
  }
  if (kept != original) write_file_atomically(file, kept, "eval.csv");
  remove_recordings_after(up_to);
}

// Recordings of evaluations past the checkpoint (complete or cut short by a kill) go with their
// eval.csv rows; `tendril run --record`'s files and other names are left alone.
void EvaluationObserver::remove_recordings_after(int64_t up_to) const {
  const fs::path folder = directory_ / "episodes";
  if (!fs::is_directory(folder)) return;
  std::vector<fs::path> doomed;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("eval_", 0) != 0) continue;
    int64_t timesteps = 0;
    const char* last = name.data() + name.size();
    const auto [end, error] = std::from_chars(name.data() + 5, last, timesteps);
    if (error == std::errc() && end != last && *end == '_' && timesteps > up_to) {
      doomed.push_back(entry.path());
    }
  }
  for (const fs::path& file : doomed) fs::remove(file);
}

CheckpointObserver::CheckpointObserver(const Experiment& experiment, const fs::path& directory,
                                       Algorithm& algorithm, std::optional<int64_t> stop_at,
                                       std::string run_identity)
    : experiment_(experiment),
      directory_(directory),
      algorithm_(algorithm),
      stop_at_(stop_at),
      run_identity_(std::move(run_identity)),
      last_timesteps_(algorithm.num_timesteps()) {}

bool CheckpointObserver::on_iteration(const Progress& progress) {
  const int64_t previous = last_timesteps_;
  last_timesteps_ = progress.timesteps;
  if (progress.timesteps >= experiment_.n_timesteps) {
    // The run ends now. Its final state is kept beside the others, for a warm start of another
    // run (Algorithm::warm_start); a finished run is never resumed.
    if (experiment_.checkpoint_freq > 0) save(progress.timesteps);
    return true;
  }
  const bool due = crossed(experiment_.checkpoint_freq, previous, progress.timesteps);
  if (const int signal = interrupt_signal(); signal != 0) {
    save(progress.timesteps);
    interrupted_ = signal;
    return false;
  }
  if (!due) return true;
  save(progress.timesteps);
  return !(stop_at_ && progress.timesteps >= *stop_at_);
}

// The replay buffer goes first, so a checkpoint never exists without the buffer it needs; the
// buffers of older checkpoints than the newest two are then removed (buffers can be large).
void CheckpointObserver::save(int64_t timesteps) {
  const fs::path checkpoint = checkpoint_path(directory_, timesteps);
  const bool with_buffer = algorithm_.has_replay_buffer() && experiment_.save_replay_buffer;
  Algorithm::Labels labels = {{"run", run_identity_}};
  if (with_buffer) {
    const uint32_t checksum = algorithm_.save_replay_buffer(buffer_path(checkpoint));
    labels.emplace_back("replay_buffer", checksum_text(checksum));
  }
  const bool holds_environments = algorithm_.checkpoints_hold_environments();
  Algorithm::ExtraWriter extra;
  if (companion_ != nullptr) {
    labels.emplace_back("companion", companion_->name());
    extra = [this](ArchiveWriter& writer) { companion_->save(writer); };
  }
  algorithm_.save(checkpoint, labels, extra);
  // Without the environments in the checkpoint, a resumed run restarts them here: so does
  // this one, and both compute the same.
  if (!holds_environments) algorithm_.request_seeded_reset();
  if (!with_buffer) return;
  const std::vector<fs::path> saved = checkpoints(directory_);
  for (std::size_t i = 2; i < saved.size(); ++i) fs::remove(buffer_path(saved[i]));
}

ProgressLine::ProgressLine(int64_t total_timesteps, int64_t first_step,
                           std::function<void(const std::string&)> output)
    : total_timesteps_(total_timesteps),
      first_step_(first_step),
      output_(std::move(output)),
      start_(Clock::now()),
      last_print_(start_) {}

bool ProgressLine::on_iteration(const Progress& progress) {
  last_ = progress;
  const auto now = Clock::now();
  if (seconds_between(last_print_, now) >= 1.0) print(progress);
  return true;
}

void ProgressLine::finish() {
  if (last_) print(*last_);
  write("\n");
}

void ProgressLine::write(const std::string& text) const {
  if (output_) {
    output_(text);
    return;
  }
  std::fputs(text.c_str(), stderr);
  std::fflush(stderr);
}

void ProgressLine::print(const Progress& p) {
  const auto now = Clock::now();
  last_print_ = now;
  const double fps =
      static_cast<double>(p.timesteps - first_step_) / std::max(seconds_between(start_, now), 1e-9);
  const double remaining = static_cast<double>(total_timesteps_ - p.timesteps) / fps;
  char line[256];
  std::snprintf(line, sizeof line,
                "\rsteps %lld/%lld (%.1f%%)  %.0f steps/s  ep_rew_mean %s  ETA %s   ",
                static_cast<long long>(p.timesteps), static_cast<long long>(total_timesteps_),
                100.0 * static_cast<double>(p.timesteps) / static_cast<double>(total_timesteps_),
                fps, p.episodes > 0 ? std::to_string(p.episode_return_mean).c_str() : "-",
                duration_text(std::max(remaining, 0.0)).c_str());
  write(line);
}

}  // namespace tendril::rl
