#pragma once

#include <filesystem>
#include <string>

#include "tendril/sweeps/sweep.hpp"

namespace tendril::sweeps {

// A Slurm job-array script for a sweep (`tendril sweep <file> --slurm`): array task i of K runs
//   cd <working directory> && <tendril> sweep <file> --rank i --ranks K --quiet
// so it trains the runs r with r mod K == i (sweeps/sweep_share), skipping finished ones and
// resuming interrupted ones; the task that finds every run finished writes the summary. With
// K = the number of runs, each task trains one run.
struct SlurmOptions {
  std::filesystem::path tendril;            // the program, absolute
  std::filesystem::path sweep_file;         // absolute
  std::filesystem::path working_directory;  // absolute: the sweep's output is relative to it
  int tasks = 0;                            // array tasks K; 0: one per run
  int max_running = 0;    // at most this many tasks at once (--array=0-N%M); 0: no limit
  int cpus_per_task = 0;  // 0: the largest env.n_envs of the sweep's runs
  std::string job_name;   // "" : tendril-<output's last part>
  std::string time = "24:00:00";
  std::string mem, partition, account;  // left out when ""
  // Slurm sends SIGTERM this many seconds before the time limit (--signal=B:TERM@N), so the run
  // in training writes a checkpoint and the task ends cleanly; submitting again resumes it.
  // 0: no early signal (Slurm's own SIGTERM comes KillWait, 30 s by default, before SIGKILL).
  int stop_before = 300;
};

std::string slurm_script(const Sweep& sweep, const SlurmOptions& options);

}  // namespace tendril::sweeps
