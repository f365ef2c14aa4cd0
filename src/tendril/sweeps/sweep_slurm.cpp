#include "tendril/sweeps/sweep_slurm.hpp"

#include <algorithm>

#include "tendril/core/error.hpp"
#include "tendril/rl/experiment.hpp"

namespace tendril::sweeps {

namespace {

// A word for bash: in single quotes, each ' written as '\''.
std::string quoted(const std::string& word) {
  std::string text = "'";
  for (const char c : word) text += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return text + "'";
}

// Slurm reads #SBATCH values up to the line's end: no newlines in them.
std::string line_value(const std::string& value, const char* option) {
  require(value.find_first_of("\n\r") == std::string::npos, "must be one line", option);
  return value;
}

}  // namespace

std::string slurm_script(const Sweep& sweep, const SlurmOptions& options) {
  namespace fs = std::filesystem;
  const auto runs = sweep.runs();
  const int run_count = static_cast<int>(runs.size());
  require(options.tasks >= 0, "must be at least 1", "--tasks");
  const int tasks = options.tasks == 0 ? run_count : std::min(options.tasks, run_count);
  int cpus = options.cpus_per_task;
  if (cpus == 0) {
    for (const auto& run : runs) {
      cpus = std::max(cpus, rl::Experiment::from_config(sweep.experiment(run)).env.n_envs);
    }
  }
  const fs::path output = options.working_directory / sweep.output;
  std::string name = options.job_name;
  if (name.empty()) name = "tendril-" + fs::path(sweep.output).filename().string();

  std::string s = "#!/bin/bash\n";
  const std::string k = std::to_string(tasks);
  s += "# The sweep " + options.sweep_file.string() + "\n";
  s += "# as a Slurm job array: task i of " + k + " trains the runs r with r mod " + k + " == i (" +
       std::to_string(run_count) + " runs).\n";
  s += "# Finished runs are kept and interrupted ones resumed, so the array can be submitted\n"
       "# again after a time limit or a failure; the task that finds every run finished writes\n"
       "# " +
       (fs::path(sweep.output) / "summary").string() + ". Submit with: sbatch <this file>\n";
  s += "#SBATCH --job-name=" + line_value(name, "--job-name") + "\n";
  s += "#SBATCH --array=0-" + std::to_string(tasks - 1) +
       (options.max_running > 0 ? "%" + std::to_string(options.max_running) : "") + "\n";
  s += "#SBATCH --ntasks=1\n";
  s += "#SBATCH --cpus-per-task=" + std::to_string(cpus) + "\n";
  s += "#SBATCH --time=" + line_value(options.time, "--time") + "\n";
  require(options.stop_before >= 0, "must be 0 or more seconds", "--stop-before");
  if (options.stop_before > 0) {
    // B: to the batch shell, which `exec` below makes tendril itself.
    s += "#SBATCH --signal=B:TERM@" + std::to_string(options.stop_before) + "\n";
  }
  if (!options.mem.empty()) s += "#SBATCH --mem=" + line_value(options.mem, "--mem") + "\n";
  if (!options.partition.empty())
    s += "#SBATCH --partition=" + line_value(options.partition, "--partition") + "\n";
  if (!options.account.empty())
    s += "#SBATCH --account=" + line_value(options.account, "--account") + "\n";
  s += "#SBATCH --output=" + line_value((output / "slurm" / "%A_%a.out").string(), "output") + "\n";
  s += "set -euo pipefail\n";
  s += "cd " + quoted(options.working_directory.string()) + "\n";
  s += "exec " + quoted(options.tendril.string()) + " sweep run " +
       quoted(options.sweep_file.string()) + " --rank \"$SLURM_ARRAY_TASK_ID\" --ranks " +
       std::to_string(tasks) + " --quiet\n";
  return s;
}

}  // namespace tendril::sweeps
