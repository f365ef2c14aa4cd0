#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "tendril/rl/trainer.hpp"
#include "tendril/sweeps/sweep.hpp"
#include "tendril/sweeps/sweep_share.hpp"

namespace tendril::sweeps {

// What one process did with one run of a sweep.
enum class SweepRunStatus {
  started,           // trained from the beginning
  restarted,         // an earlier start that never reached a checkpoint, trained again
  resumed,           // continued from its newest checkpoint
  finished_earlier,  // model.policy was there: kept as it is
  busy,              // another live process holds its run.lock: left to it
};
const char* to_string(SweepRunStatus status);

struct SweepRunRecord {
  int index = 0;
  std::filesystem::path directory;
  SweepRunStatus status = SweepRunStatus::started;
  rl::TrainResult result;  // of the training (started, restarted, resumed)
};

// Trains the runs `indices` of `sweep`, one after the other, into `sweep.directory(run)`.
// Whichever process reaches a run: a finished one is kept, an interrupted one resumes from its
// newest checkpoint, one interrupted before its first checkpoint starts again, and one whose
// run.lock a live process holds (core/run_lock) is passed over, so two processes never train
// the same run. Returns after the last run, or after the first one stopped by SIGINT/SIGTERM
// (its record has result.interrupted set). `on_run` sees each record before training
// (result empty) and after.
std::vector<SweepRunRecord> train_sweep_runs(
    const Sweep& sweep, const std::vector<int>& indices, rl::TrainOptions options,
    const std::function<void(const SweepRunRecord&, bool done)>& on_run = {});

// Whether every run of the sweep has finished (holds model.policy).
bool sweep_finished(const Sweep& sweep);

// Appends a row `event,unix_time,host,pid,rank,ranks` to <output>/sweep_log.csv (one write(2)
// with O_APPEND, so concurrent processes on one file system never interleave within a row).
// Each process of a sweep logs "start" and "end"; the summary's wall time spans them.
void log_sweep_event(const Sweep& sweep, const std::string& event, const SweepShare& share);

// Runs `action` while holding <output>/summary.lock; returns false without running it when
// another process holds that lock (it is writing the same summary).
bool with_summary_lock(const Sweep& sweep, const std::function<void()>& action);

}  // namespace tendril::sweeps
