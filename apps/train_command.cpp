// `tendril train`: run an experiment file, or resume a run.
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/file_kind.hpp"
#include "tendril/core/interrupt.hpp"
#include "tendril/rl/trainer.hpp"

namespace tendril::apps {

const char* signal_name(int signal) {
  return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal";
}

// The exit status: 0 when the run finished or paused as asked, 128 + the signal when a signal
// stopped it (the shell's convention), so scripts see the interruption.
int report_training(const rl::TrainResult& result) {
  const std::string run = result.run_directory.string();
  std::printf("%s after %lld steps in %.1f s (%.0f steps/s)\n",
              result.finished      ? "finished"
              : result.interrupted ? "interrupted"
                                   : "paused",
              static_cast<long long>(result.timesteps), result.seconds, result.steps_per_second);
  if (result.finished) {
    std::printf("final evaluation: mean return %.2f +/- %.2f\n", result.final_eval_mean,
                result.final_eval_std);
    std::printf("model:          %s/model.policy\n", run.c_str());
  }
  if (result.best_eval_mean) {
    std::printf("best model:     %s/best_model.policy (mean return %.2f at %lld steps)\n",
                run.c_str(), *result.best_eval_mean,
                static_cast<long long>(result.best_eval_timesteps));
  }
  std::printf("learning curve: %s/progress.csv (TensorBoard: %s)\n", run.c_str(), run.c_str());
  std::printf("evaluations:    %s/eval.csv\n", run.c_str());
  if (result.interrupted) {
    std::printf("interrupted by %s; a checkpoint at %lld steps holds the run\n",
                signal_name(result.interrupted), static_cast<long long>(result.timesteps));
  }
  if (!result.finished) {
    std::printf("continue with:  tendril resume %s\n", run.c_str());
  }
  return result.interrupted ? 128 + result.interrupted : 0;
}

namespace {

rl::TrainOptions train_options(const Arguments& line) {
  rl::TrainOptions options;
  options.quiet = line.has("quiet");
  options.stop_at = line.optional_integer("stop-at", 1, std::numeric_limits<int64_t>::max());
  return options;
}

}  // namespace

int resume_command(const Arguments& line) {
  const std::filesystem::path run = line.positional.front();
#ifdef TENDRIL_WITH_DYNAMICS
  if (const std::optional<int> status = resume_stopped_fit(line)) return *status;
#endif
  const rl::TrainOptions options = train_options(line);
#ifdef TENDRIL_WITH_SAFETY
  if (std::filesystem::exists(run / "config.yaml")) {
    const Config config = rl::load_run_config(run);
    if (config.has("safety") || config.has("constrained")) {
      return run_safety_training(config, run, options, /*resuming=*/true);
    }
  }
#endif
  catch_interrupts();
  return report_training(rl::resume(run, options));
}

int train_command(const Arguments& line) {
  const Config config = line.load_config(file_kind::kExperiment);
  const rl::TrainOptions options = train_options(line);
#ifdef TENDRIL_WITH_SAFETY
  // Safety co-training (a `safety:` section) and the constrained baselines (`constrained:`).
  if (config.has("safety") || config.has("constrained")) return safety_train(line, config, options);
#endif
  const rl::Experiment experiment = rl::Experiment::from_config(config);
  const std::filesystem::path run = line.has("output")
                                        ? std::filesystem::path(line.value("output", ""))
                                        : rl::default_run_directory(experiment);
  std::printf("training %s on %s (%d envs) for %lld steps, seed %llu -> %s\n",
              experiment.algorithm.c_str(), experiment.env.id.c_str(), experiment.env.n_envs,
              static_cast<long long>(experiment.n_timesteps),
              static_cast<unsigned long long>(experiment.seed), run.string().c_str());
  std::printf("watch it live: tendril serve %s\n", run.string().c_str());
  std::fflush(stdout);  // before the progress line on standard error
  catch_interrupts();
  return report_training(rl::train(experiment, run, options));
}

}  // namespace tendril::apps
