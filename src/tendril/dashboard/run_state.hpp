#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/dashboard/served_root.hpp"

namespace tendril::dashboard {

// What a run is doing and how far it got, read from its files alone (the dashboard's run list).
// Numbers not known are NaN (null in JSON).
struct RunState {
  static constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

  // "training" (tendril train: config.yaml with an algorithm), "fit" (tendril model fit:
  // progress.csv counts time/epochs), "" (logs from elsewhere, e.g. Stable-Baselines3's own).
  std::string kind;
  // "running"  — a live process holds the run's lock (run.lock);
  // "finished" — training wrote model.policy; a fit wrote evaluation.csv;
  // "paused"   — training left checkpoints and stopped (`--stop-at`, Ctrl-C): resumable;
  // "stopped"  — neither (killed before its first checkpoint, a fit cut short);
  // ""         — not known (logs from elsewhere).
  std::string status;
  int64_t pid = 0;                // running: the process holding the lock
  double steps = kUnknown;        // training: time/total_timesteps of the last row; fit: epochs
  double total = kUnknown;        // the budget: n_timesteps, or the fit's training.epochs
  double last_return = kUnknown;  // rollout/ep_rew_mean of the last progress row
  double last_eval = kUnknown;    // mean_return of eval.csv's last row
  double last_loss = kUnknown;    // fit: train/val_loss of the last row (else train/loss)
  int64_t checkpoint = -1;        // the newest checkpoint's steps (checkpoints/step_N.ckpt)
};

// The processes holding flock(2) locks now, by the locked file's (device, inode), from
// /proc/locks: who holds a run's lock without touching the lock.
using HeldLocks = std::map<std::pair<uint64_t, uint64_t>, int64_t>;
HeldLocks held_locks();

// The state of the run in `directory` (inside `root`); `config` is its config.yaml when
// readable (else null). Only files that pass the root's check are read or counted.
RunState read_run_state(const ServedRoot& root, const std::filesystem::path& directory,
                        const Config* config, const HeldLocks& locks);

// The header and the last complete row of a CSV file, reading only the file's start and its
// last 64 KiB; empty when there is no complete row (or no such file). Cells that are empty or
// not numbers are NaN.
struct LastRow {
  std::vector<std::string> columns;
  std::vector<double> values;
  double value(const std::string& column) const;  // NaN when the column is absent
};
LastRow last_csv_row(const std::filesystem::path& file);

}  // namespace tendril::dashboard
