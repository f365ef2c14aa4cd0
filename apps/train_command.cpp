// `tendril train`: run an experiment file, or resume a run.
#include <cstdio>
#include <ctime>
#include <filesystem>

#include "command_line.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/rl/trainer.hpp"

namespace tendril::apps {

namespace {

std::filesystem::path new_run_directory(const std::string& output) {
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
  return output + "-" + stamp;
}

void report(const rl::TrainResult& result) {
  const std::string run = result.run_directory.string();
  std::printf("%s after %lld steps in %.1f s (%.0f steps/s)\n",
              result.finished ? "finished" : "paused", static_cast<long long>(result.timesteps),
              result.seconds, result.steps_per_second);
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
  if (!result.finished) {
    std::printf("continue with:  tendril train --resume %s\n", run.c_str());
  }
  std::printf("learning curve: %s/progress.csv (TensorBoard: %s)\n", run.c_str(), run.c_str());
  std::printf("evaluations:    %s/eval.csv\n", run.c_str());
}

}  // namespace

int train_command(const std::vector<std::string>& args) {
  const CommandLine line = CommandLine::parse(args, {"out", "resume", "stop-at"}, {"quiet"});
  rl::TrainOptions options;
  options.quiet = line.has("quiet");
  if (line.has("stop-at")) {
    try {
      options.stop_at = std::stoll(line.value("stop-at", ""));
    } catch (const std::exception&) {
      throw Error("--stop-at expects a number of steps", "command line");
    }
  }
  if (line.has("resume")) {
    require(line.positional.empty() && line.overrides.empty(),
            "--resume takes only the run directory (its config.yaml is used as saved)",
            "command line");
    report(rl::resume(line.value("resume", ""), options));
    return 0;
  }
  const rl::Experiment experiment = rl::Experiment::from_config(line.load_config());
  const std::filesystem::path run = line.has("out") ? std::filesystem::path(line.value("out", ""))
                                                    : new_run_directory(experiment.output);
  std::printf("training %s on %s (%d envs) for %lld steps, seed %llu -> %s\n",
              experiment.algorithm.c_str(), experiment.env.id.c_str(), experiment.env.n_envs,
              static_cast<long long>(experiment.n_timesteps),
              static_cast<unsigned long long>(experiment.seed), run.string().c_str());
  std::printf("watch it live: tendril serve %s\n", run.string().c_str());
  std::fflush(stdout);  // before the progress line on standard error
  report(rl::train(experiment, run, options));
  return 0;
}

}  // namespace tendril::apps
