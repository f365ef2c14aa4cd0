#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tendril/core/run_curves.hpp"
#include "tendril/sweeps/sweep.hpp"

namespace tendril::sweeps {

// Seeds are grouped and their curves aggregated by core/run_curves (seed_group,
// aggregate_curves, spread_of), as in `tendril plot curves` and the dashboard.

// What a run directory holds, read from progress.csv and eval.csv.
struct RunSummary {
  std::string name;
  std::filesystem::path directory;
  bool finished = false;  // model.policy is there
  int64_t steps = 0;      // the last progress.csv row's time/total_timesteps
  // Training time and speed over every process that trained it: progress.csv's clock restarts
  // when a run resumes, so each stretch adds its last time/time_elapsed and fps × elapsed steps.
  double seconds = 0.0;
  double steps_per_second = 0.0;
  // The last eval.csv row (a finished run's evaluation at its end).
  std::optional<double> final_eval_mean, final_eval_std;
  int64_t final_eval_steps = 0;
  // The training return where the run stopped: the last finite rollout/ep_rew_mean (the mean
  // return of the last 100 training episodes).
  std::optional<double> final_train_mean;
  Curve train;  // rollout/ep_rew_mean against time/total_timesteps
  Curve eval;   // eval.csv's mean_return against timesteps
};
RunSummary summarize_run(const std::filesystem::path& directory);

// The runs of one configuration: the sweep's runs that differ only by seed.
struct ConfigurationSummary {
  std::string name;                                           // seed_group of its runs' names
  std::vector<std::pair<std::string, std::string>> settings;  // its overrides but the seed
  std::vector<int> runs;                                      // indices into SweepSummary::runs
  Spread final_eval;  // over the finished runs' final evaluations (mean returns)
  Spread steps_per_second;
  CurveStats train, eval;
};

struct SweepSummary {
  std::vector<RunSummary> runs;                      // in the sweep's order
  std::vector<ConfigurationSummary> configurations;  // in order of first appearance
  // From sweep_log.csv: the first process's start to the last one's end (NaN without a log),
  // the time at least one process ran (the union of the start-to-end intervals of the processes
  // that logged both; a killed process logs no end), the processes that logged a start and those
  // that logged an end, and the training time summed over runs.
  double wall_seconds = 0.0;
  double busy_seconds = 0.0;
  int processes = 0;
  int ended_processes = 0;
  double run_seconds = 0.0;
};
SweepSummary summarize_sweep(const Sweep& sweep);

// The runs among `paths`: a directory holding a progress.csv is a run; any other directory adds
// the runs directly inside it, in name order. An Error names a path that is not a directory or
// holds no run.
std::vector<std::filesystem::path> run_directories(const std::vector<std::filesystem::path>& paths);
// Runs outside a sweep (each a run directory), grouped into configurations by seed_group of their
// names (the parent directory's name for a name that is only a seed), in order of first
// appearance: no settings, no sweep_log.csv (wall time NaN).
SweepSummary summarize_runs(const std::vector<std::filesystem::path>& runs);
// The training mean (rollout/ep_rew_mean) of the run's last progress.csv row at or before
// `step`; none when the run has not trained `step` steps or has no such row.
std::optional<double> training_mean_at(const RunSummary& run, double step);

// Writes <directory>/configurations.csv, runs.csv, curves/<configuration>.{train,eval}.csv and
// summary.md (each atomically). `figures` are PNG files in `directory` the page links to.
void write_sweep_summary(const Sweep& sweep, const SweepSummary& summary,
                         const std::filesystem::path& directory,
                         const std::vector<std::pair<std::string, std::string>>& figures);

}  // namespace tendril::sweeps
