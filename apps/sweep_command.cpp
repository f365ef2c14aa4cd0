// `tendril sweep`: the runs of a sweep file, one after the other.
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "command_line.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/interrupt.hpp"
#include "tendril/rl/sweep.hpp"
#include "tendril/rl/trainer.hpp"

namespace tendril::apps {

int sweep_command(const std::vector<std::string>& args) {
  namespace fs = std::filesystem;
  const CommandLine line = CommandLine::parse(args, {"only"}, {"list", "quiet"});
  require(line.positional.size() == 1 && line.overrides.empty(),
          "expects one sweep file (and no --set)", "command line");
  const rl::Sweep sweep = rl::Sweep::load(line.positional.front());
  const std::vector<rl::Sweep::Run> runs = sweep.runs();
  const int only =
      static_cast<int>(line.integer("only", -1, 0, static_cast<int64_t>(runs.size()) - 1));
  rl::TrainOptions options;
  options.quiet = line.has("quiet");
  // A sweep restarts runs interrupted before their first checkpoint (nothing of them is lost).
  options.restart_unstarted = true;
  catch_interrupts();
  for (int i = 0; i < static_cast<int>(runs.size()); ++i) {
    if (only >= 0 && i != only) continue;
    const fs::path directory = fs::path(sweep.output) / runs[i].name;
    if (line.has("list")) {
      std::printf("%3d  %s\n", i, directory.string().c_str());
      continue;
    }
    // Finished runs are kept; interrupted ones continue from their newest checkpoint.
    if (fs::exists(directory / "model.policy")) {
      std::printf("[%d/%zu] %s: finished earlier, kept\n", i + 1, runs.size(), directory.c_str());
      continue;
    }
    std::printf("[%d/%zu] %s\n", i + 1, runs.size(), directory.c_str());
    std::fflush(stdout);
    const bool resumable = !rl::checkpoints(directory).empty();
    const rl::TrainResult result =
        resumable
            ? rl::resume(directory, options)
            : rl::train(rl::Experiment::from_config(sweep.experiment(runs[i])), directory, options);
    if (result.interrupted) {
      std::printf(
          "  interrupted by %s after %lld steps; its checkpoint holds the run\n"
          "continue with:  tendril sweep %s\n",
          signal_name(result.interrupted), static_cast<long long>(result.timesteps),
          line.positional.front().c_str());
      return 128 + result.interrupted;
    }
    std::printf("  %lld steps in %.1f s, final evaluation %.2f +/- %.2f\n",
                static_cast<long long>(result.timesteps), result.seconds, result.final_eval_mean,
                result.final_eval_std);
  }
  return 0;
}

}  // namespace tendril::apps
