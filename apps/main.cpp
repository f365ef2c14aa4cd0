// tendril — simulate soft robots, train and evaluate controllers for them.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "commands.hpp"
#include "tendril/core/error.hpp"

namespace {

constexpr const char* kUsage = R"(usage: tendril <command> [arguments]

commands:
  simulate <experiment.yaml> [--set key=value ...] [--out DIR]
      Simulate a Cosserat-rod arm under a spline muscle couple; write its tip trajectory
      (tip.csv) and final shape (nodes.csv) to DIR, and print what happened.
  train <experiment.yaml> [--set key=value ...] [--out DIR] [--stop-at STEPS] [--quiet]
  train --resume <run-dir>
      Train a controller; write the run directory (config, progress.csv, TensorBoard events,
      eval.csv, checkpoints/, model.pt). --stop-at pauses at the first checkpoint past STEPS.
  eval <run-dir> [--episodes N] [--deterministic] [--seed S] [--best]
      Evaluate a run's model (model.pt, else its newest checkpoint; --best: best_model.pt).
  sweep <sweep.yaml> [--list] [--only I] [--quiet]
      Train the runs of a sweep file (a grid of overrides of one experiment) one after the
      other into <output>/<run>; finished runs are kept, interrupted ones resumed.
  metrics <run-dir> [--steps N] [--seed S] [--stochastic] [--best] [--set key=value ...]
          [--trace FILE]
      Run a run's model for N steps (auto-reset; deterministic unless --stochastic) and print
      the mean per step of the reward and of every info value; --set changes the run's
      experiment for this (e.g. env.params); --trace writes every step's info and scene
      values as CSV.
  list-envs
      The registered environment ids.
  help
      Show this text.
)";

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  try {
    if (args[0] == "simulate") return tendril::apps::simulate_command(rest);
#ifdef TENDRIL_WITH_ENVS
    if (args[0] == "list-envs") return tendril::apps::list_envs_command(rest);
#endif
#ifdef TENDRIL_WITH_RL
    if (args[0] == "train") return tendril::apps::train_command(rest);
    if (args[0] == "eval") return tendril::apps::eval_command(rest);
    if (args[0] == "sweep") return tendril::apps::sweep_command(rest);
    if (args[0] == "metrics") return tendril::apps::metrics_command(rest);
#endif
    std::fprintf(stderr, "tendril: unknown command '%s'\n\n%s", args[0].c_str(), kUsage);
    return 2;
  } catch (const tendril::Error& e) {
    std::fprintf(stderr, "tendril %s: error: %s\n", args[0].c_str(), e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tendril %s: unexpected error: %s\n", args[0].c_str(), e.what());
    return 1;
  }
}
