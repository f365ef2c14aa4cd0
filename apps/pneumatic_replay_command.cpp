// `tendril replay-pneumatic`: seed 002's stochasticity analysis and gap across damage scenarios.
#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/file_kind.hpp"
#include "tendril/envs/pneumatic/open_loop_reach.hpp"
#include "tendril/envs/pneumatic/replay_trials.hpp"

namespace tendril::apps {

int pneumatic_replay(const Arguments& line) {
  const Config config = line.load_config(file_kind::kDataProtocol);
  const std::string directory = line.value("output", config.get_or<std::string>("output", ""));
  require(!directory.empty(), "no output directory: set `output` or pass -o", config.source());
  std::string invocation = "tendril data replay";
  for (const std::string& arg : line.raw) invocation += " " + arg;
  const bool open_loop = config.has("open_loop");
  const envs::pneumatic::OpenLoopOptions options =
      envs::pneumatic::open_loop_options(config.child("open_loop"));
  const envs::pneumatic::ReplayReport report = envs::pneumatic::replay_trials(config);
  envs::pneumatic::write_replay_report(report, directory, invocation);

  // Mean MAD over the trials per scenario and module, from the reference and from the
  // scenario's own first trial (which is 0 for trial 1, so it is left out of that mean).
  std::printf("tendril replay-pneumatic: %zu scenarios in %.1f s of wall time\n",
              report.scenarios.size(), report.wall_seconds);
  std::printf("%-9s %-7s %24s %24s\n", "scenario", "module", "MAD from reference [mm]",
              "MAD from own base [mm]");
  for (const std::string& scenario : report.scenarios) {
    for (int module = 1; module <= 3; ++module) {
      double reference = 0.0, own = 0.0;
      int trials = 0;
      for (const auto& row : report.rows) {
        if (row.scenario != scenario || row.module != module) continue;
        reference += row.mad_from_reference_mm;
        if (row.trial > 1) own += row.mad_from_own_base_mm;
        ++trials;
      }
      std::printf("%-9s %-7d %24.2f %24.2f\n", scenario.c_str(), module, reference / trials,
                  trials > 1 ? own / (trials - 1) : 0.0);
    }
  }
  std::printf("wrote %s/replay_gap.csv and replay_gap_series.csv\n", directory.c_str());
  if (!open_loop) return 0;

  const envs::pneumatic::OpenLoopReport plans = envs::pneumatic::open_loop_reach(
      config.child("robot").child("params"), report.scenarios, options);
  envs::pneumatic::write_open_loop_report(plans, directory, invocation);
  std::printf("\nopen-loop plans from the noise-free model, replayed on the twin (%.1f s):\n",
              plans.wall_seconds);
  for (const auto& goal : plans.goals) {
    std::printf("goal %-4s model's final distance %.2f mm\n", goal.name.c_str(),
                goal.model_distance);
  }
  std::printf("%-9s %-5s %12s %12s %12s\n", "scenario", "goal", "mean [mm]", "min [mm]",
              "max [mm]");
  for (const std::string& scenario : report.scenarios) {
    for (const auto& goal : plans.goals) {
      double sum = 0.0, low = 1e300, high = 0.0;
      int n = 0;
      for (const auto& row : plans.rows) {
        if (row.scenario != scenario || row.goal != goal.name) continue;
        sum += row.final_distance_mm;
        low = std::min(low, row.final_distance_mm);
        high = std::max(high, row.final_distance_mm);
        ++n;
      }
      std::printf("%-9s %-5s %12.2f %12.2f %12.2f\n", scenario.c_str(), goal.name.c_str(), sum / n,
                  low, high);
    }
  }
  std::printf("wrote %s/open_loop_reach.csv\n", directory.c_str());
  return 0;
}

}  // namespace tendril::apps
