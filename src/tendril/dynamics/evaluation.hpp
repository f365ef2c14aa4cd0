#pragma once

#include <cstdint>
#include <functional>
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

// Which window ends t a one-step error pools; every one when empty.
using PointFilter = std::function<bool(int64_t t)>;
// Sees the share of a measurement's model calls done (0 to 1) after each call, for progress lines.
using Progress = std::function<void(double done)>;

// One-step prediction (eq. 4.11): x̂_{t+1} = x_t + φ(recorded window ending at t), for every
// window of `split` (that `include` accepts).
ErrorReport one_step_errors(Model& model, const WindowSet& windows, Split split,
                            int batch_size = 256, const PointFilter& include = {},
                            const Progress& on_progress = {});

// The "predict no change" baseline on the points the model is measured on: x̂_{t+1} = x_t one
// step ahead (Δx = 0) over the same windows, and x̂ = the start's recorded state throughout each
// rollout piece of rollout_errors (same pieces). A model has learned the dynamics only where it
// beats this.
ErrorReport persistence_one_step_errors(const SequenceData& data, const WindowSet& windows,
                                        Split split, const PointFilter& include = {});
ErrorReport persistence_rollout_errors(const SequenceData& data, Split split, double horizon,
                                       double max_gap, int window_length);

// Whether the input changed at one of the `readings` newest rows of the window ending at t
// (u_k ≠ u_{k−1} for some k in t − readings + 1 … t): the points right after a throttle change,
// where an under-damped limb rings.
bool input_changed_within(const SequenceData& data, int64_t t, int readings);

// Recursive rollouts (eq. 4.12): from a recorded window, x̂_{t+1} = x̂_t + φ(x̂_t, …, u_t) with
// the predictions fed back and the recorded inputs applied. Each segment of `split` is cut into
// consecutive pieces of `horizon` seconds of recorded time, each started from the recorded
// window at its first row; all pieces are rolled out together (one environment each).
ErrorReport rollout_errors(Model& model, const SequenceData& data, Split split, double horizon,
                           double max_gap, const Progress& on_progress = {});

// The recursive prediction of `steps` states after row `start` of `data`, started from the
// recorded window ending at `start` and driven by the recorded inputs u_start …: rows
// x̂_{start+1} … x̂_{start+steps}. Several starts run as one batch.
std::vector<RowMatrixXd> rollouts(Model& model, const SequenceData& data,
                                  const std::vector<int64_t>& starts,
                                  const std::vector<int64_t>& steps,
                                  const Progress& on_progress = {});

}  // namespace tendril::dynamics
