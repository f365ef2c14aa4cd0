#pragma once

#include <string>
#include <vector>

#include "tendril/dynamics/model.hpp"
#include "tendril/dynamics/sequence_data.hpp"
#include "tendril/dynamics/window_set.hpp"

namespace tendril::dynamics {

// State columns reported together (thesis eqs. 4.9–4.10: angle and velocity separately).
struct StateGroup {
  std::string name;  // "angle", "velocity", or the column's own name
  std::string unit;  // "deg", "deg/s", or ""
  std::vector<int> columns;
};

// theta_* columns form "angle" (deg), omega_* columns "velocity" (deg/s); every other column is
// a group of its own.
std::vector<StateGroup> state_groups(const std::vector<std::string>& state_names);

// Root-mean-square errors per group, pooled over every predicted point and every column of the
// group: RMSE = √(Σ (x̂ − x)² / N) with N the number of values (eqs. 4.9–4.10).
struct ErrorReport {
  std::vector<StateGroup> groups;
  std::vector<double> rmse;  // one per group
  int64_t points = 0;        // predicted states
  int64_t rollouts = 0;      // independent starts (1-step: windows)
};

// One-step prediction (eq. 4.11): x̂_{t+1} = x_t + φ(recorded window ending at t), for every
// window of `split`.
ErrorReport one_step_errors(Model& model, const WindowSet& windows, Split split,
                            int batch_size = 256);

// Recursive rollouts (eq. 4.12): from a recorded window, x̂_{t+1} = x̂_t + φ(x̂_t, …, u_t) with
// the predictions fed back and the recorded inputs applied. Each segment of `split` is cut into
// consecutive pieces of `horizon` seconds of recorded time, each started from the recorded
// window at its first row; all pieces are rolled out together (one environment each).
ErrorReport rollout_errors(Model& model, const SequenceData& data, Split split, double horizon,
                           double max_gap);

// The recursive prediction of `steps` states after row `start` of `data`, started from the
// recorded window ending at `start` and driven by the recorded inputs u_start …: rows
// x̂_{start+1} … x̂_{start+steps}. Several starts run as one batch.
std::vector<RowMatrixXd> rollouts(Model& model, const SequenceData& data,
                                  const std::vector<int64_t>& starts,
                                  const std::vector<int64_t>& steps);

}  // namespace tendril::dynamics
