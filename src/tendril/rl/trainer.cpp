#include "tendril/rl/trainer.hpp"

#include <charconv>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/core/scalar_log.hpp"
#include "tendril/rl/evaluation.hpp"
#include "tendril/rl/off_policy_algorithm.hpp"

namespace tendril::rl {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The shortest decimal text that reads back as exactly `value`: a resumed run recalls its best
// evaluation from eval.csv and must compare as the uninterrupted run does.
std::string exact_text(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

fs::path checkpoint_path(const fs::path& run, int64_t steps) {
  return run / "checkpoints" / ("step_" + std::to_string(steps) + ".pt");
}

// The replay buffer saved with a checkpoint (only the newest checkpoint keeps one).
fs::path buffer_path(const fs::path& checkpoint) {
  return fs::path(checkpoint).replace_extension(".buffer");
}

std::string duration_text(double seconds) {
  const auto total = static_cast<long long>(seconds + 0.5);
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof text, "%lldh%02lldm", total / 3600, total / 60 % 60);
  } else {
    std::snprintf(text, sizeof text, "%lldm%02llds", total / 60, total % 60);
  }
  return text;
}

// Evaluation on a fresh environment with the training VecEnv's frozen observation statistics
// and raw rewards (SB3's EvalCallback on a VecNormalize'd model).
EvaluationResult evaluate(const Experiment& experiment, Algorithm& algorithm,
                          const envs::VecEnv& training, uint64_t seed) {
  const std::unique_ptr<Env> env = make_evaluation_env(experiment.env, training);
  return evaluate_policy(algorithm, *env, experiment.eval_episodes, experiment.eval_deterministic,
                         seed);
}

class Run {
 public:
  Run(const Experiment& experiment, fs::path directory, const TrainOptions& options, bool resuming)
      : experiment_(experiment),
        directory_(std::move(directory)),
        options_(options),
        env_(make_vec_env(experiment.env)),
        algorithm_(make_algorithm(experiment, *env_)),
        log_(directory_, resuming) {
    fs::create_directories(directory_ / "checkpoints");
    const bool eval_exists = fs::exists(directory_ / "eval.csv");
    eval_file_.open(directory_ / "eval.csv", std::ios::app);
    if (!eval_exists) eval_file_ << "timesteps,mean_return,std_return,mean_length,episodes\n";
    if (resuming) {
      const fs::path checkpoint = latest_checkpoint(directory_);
      algorithm_->load(checkpoint);
      if (auto* off_policy = dynamic_cast<OffPolicyAlgorithm*>(algorithm_.get());
          off_policy != nullptr && experiment_.save_replay_buffer) {
        off_policy->load_replay_buffer(buffer_path(checkpoint));
        last_buffer_ = buffer_path(checkpoint);
      }
    }
    last_timesteps_ = algorithm_->num_timesteps();
    if (resuming && experiment_.eval_save_best) recall_best_evaluation();
  }

  TrainResult execute() {
    const auto start = Clock::now();
    const int64_t first_step = algorithm_->num_timesteps();
    last_print_ = start;
    TrainResult result;
    result.run_directory = directory_;
    algorithm_->learn(experiment_.n_timesteps, [&](const Progress& progress) {
      return after_iteration(progress, start, first_step);
    });
    result.timesteps = algorithm_->num_timesteps();
    result.finished = result.timesteps >= experiment_.n_timesteps;
    if (result.finished) {
      const EvaluationResult final_eval = evaluate_now(result.timesteps);
      result.final_eval_mean = final_eval.mean_return();
      result.final_eval_std = final_eval.std_return();
      algorithm_->save(directory_ / "model.pt");
    }
    if (best_eval_mean_) {
      result.best_eval_mean = best_eval_mean_;
      result.best_eval_timesteps = best_eval_timesteps_;
    }
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.steps_per_second = static_cast<double>(result.timesteps - first_step) / result.seconds;
    if (!options_.quiet) std::fputc('\n', stderr);
    return result;
  }

 private:
  bool after_iteration(const Progress& p, Clock::time_point start, int64_t first_step) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    const double fps = static_cast<double>(p.timesteps - first_step) / std::max(elapsed, 1e-9);
    log_.record("time/total_timesteps", static_cast<double>(p.timesteps));
    log_.record("time/iterations", static_cast<double>(p.iterations));
    log_.record("time/fps", fps);
    log_.record("time/time_elapsed", elapsed);
    if (p.episodes > 0) {
      log_.record("rollout/ep_rew_mean", p.episode_return_mean);
      log_.record("rollout/ep_len_mean", p.episode_length_mean);
    }
    if (p.success_rate) log_.record("rollout/success_rate", *p.success_rate);
    for (const auto& [name, value] : p.train) log_.record(name, value);
    log_.dump(p.timesteps);

    const int64_t previous = last_timesteps_;
    last_timesteps_ = p.timesteps;
    auto crossed = [&](int64_t every) {
      return every > 0 && p.timesteps / every > previous / every;
    };
    if (crossed(experiment_.eval_freq) && p.timesteps < experiment_.n_timesteps) {
      evaluate_now(p.timesteps);
    }
    bool keep_going = true;
    if (crossed(experiment_.checkpoint_freq) && p.timesteps < experiment_.n_timesteps) {
      save_checkpoint(p.timesteps);
      algorithm_->restart_environments();
      if (options_.stop_at && p.timesteps >= *options_.stop_at) keep_going = false;
    }
    print_progress(p, fps, keep_going);
    return keep_going;
  }

  // The replay buffer goes first, so a checkpoint never exists without the buffer it needs;
  // the previous checkpoint's buffer is then removed (buffers can be large).
  void save_checkpoint(int64_t timesteps) {
    const fs::path checkpoint = checkpoint_path(directory_, timesteps);
    auto* off_policy = dynamic_cast<OffPolicyAlgorithm*>(algorithm_.get());
    const bool with_buffer = off_policy != nullptr && experiment_.save_replay_buffer;
    if (with_buffer) off_policy->save_replay_buffer(buffer_path(checkpoint));
    algorithm_->save(checkpoint);
    if (with_buffer && !last_buffer_.empty()) fs::remove(last_buffer_);
    if (with_buffer) last_buffer_ = buffer_path(checkpoint);
  }

  EvaluationResult evaluate_now(int64_t timesteps) {
    // A stream of its own per evaluation point, so evaluating never disturbs training.
    const EvaluationResult eval =
        evaluate(experiment_, *algorithm_, *env_, experiment_.seed + 1000003 + timesteps);
    double mean_length = 0.0;
    for (int64_t length : eval.lengths) mean_length += static_cast<double>(length);
    mean_length /= static_cast<double>(eval.lengths.size());
    eval_file_ << timesteps << ',' << exact_text(eval.mean_return()) << ','
               << exact_text(eval.std_return()) << ',' << mean_length << ',' << eval.returns.size()
               << '\n';
    eval_file_.flush();
    if (experiment_.eval_save_best &&
        (!best_eval_mean_ || eval.mean_return() >= *best_eval_mean_)) {
      algorithm_->save(directory_ / "best_model.pt");
      best_eval_mean_ = eval.mean_return();
      best_eval_timesteps_ = timesteps;
    }
    return eval;
  }

  // On resume: the best evaluation up to the checkpoint, from eval.csv (rows past it, written
  // before an interruption, are evaluated again).
  void recall_best_evaluation() {
    std::ifstream in(directory_ / "eval.csv");
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::stringstream cells(line);
      std::string timesteps_cell, mean_cell;
      std::getline(cells, timesteps_cell, ',');
      std::getline(cells, mean_cell, ',');
      try {
        const int64_t timesteps = std::stoll(timesteps_cell);
        const double mean = std::stod(mean_cell);
        if (timesteps > last_timesteps_) continue;
        if (!best_eval_mean_ || mean >= *best_eval_mean_) {
          best_eval_mean_ = mean;
          best_eval_timesteps_ = timesteps;
        }
      } catch (const std::exception&) {
        throw Error("unreadable row '" + line + "'", (directory_ / "eval.csv").string());
      }
    }
  }

  void print_progress(const Progress& p, double fps, bool keep_going) {
    if (options_.quiet) return;
    const auto now = Clock::now();
    const bool last = p.timesteps >= experiment_.n_timesteps || !keep_going;
    if (!last && std::chrono::duration<double>(now - last_print_).count() < 1.0) return;
    last_print_ = now;
    const double remaining = static_cast<double>(experiment_.n_timesteps - p.timesteps) / fps;
    std::fprintf(
        stderr, "\rsteps %lld/%lld (%.1f%%)  %.0f steps/s  ep_rew_mean %s  ETA %s   ",
        static_cast<long long>(p.timesteps), static_cast<long long>(experiment_.n_timesteps),
        100.0 * static_cast<double>(p.timesteps) / static_cast<double>(experiment_.n_timesteps),
        fps, p.episodes > 0 ? std::to_string(p.episode_return_mean).c_str() : "-",
        duration_text(std::max(remaining, 0.0)).c_str());
    std::fflush(stderr);
  }

  const Experiment& experiment_;
  fs::path directory_;
  TrainOptions options_;
  std::unique_ptr<envs::VecEnv> env_;
  std::unique_ptr<Algorithm> algorithm_;
  ScalarLog log_;
  std::ofstream eval_file_;
  Clock::time_point last_print_;
  int64_t last_timesteps_ = 0;  // at the previous progress report
  fs::path last_buffer_;
  std::optional<double> best_eval_mean_;
  int64_t best_eval_timesteps_ = 0;
};

}  // namespace

fs::path latest_checkpoint(const fs::path& run_directory) {
  const fs::path folder = run_directory / "checkpoints";
  fs::path newest;
  int64_t newest_steps = -1;
  if (fs::is_directory(folder)) {
    for (const auto& entry : fs::directory_iterator(folder)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("step_", 0) != 0 || entry.path().extension() != ".pt") continue;
      try {
        const int64_t steps = std::stoll(name.substr(5, name.size() - 8));
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
  std::ofstream(run_directory / "config.yaml") << experiment.config.dump();
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
