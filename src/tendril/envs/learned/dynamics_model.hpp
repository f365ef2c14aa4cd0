#pragma once

#include "tendril/envs/learned/history_windows.hpp"
#include "tendril/envs/vector/vec_step.hpp"

namespace tendril::envs {

// A learned forward model of a robot (DESIGN.md, "The learned-model pipeline"): the next state
// from a window of recent states and inputs, for N environments at once, each with its own
// window. Declared here without LibTorch; implemented in dynamics/ (tendril::dynamics::Model).
// States and inputs are in the data's physical units (seed 001: degrees, degrees per second and
// throttles); the model normalises internally.
class DynamicsModel {
 public:
  virtual ~DynamicsModel() = default;

  virtual int state_dim() const = 0;
  virtual int input_dim() const = 0;
  // Rows of history one prediction reads (HistoryWindows' layout).
  virtual int window_length() const = 0;
  // Seconds one prediction advances: the sampling period of the data the model learned from.
  virtual double sample_period() const = 0;

  // windows: N × (window_length · (state_dim + input_dim)), HistoryWindows' layout, newest row
  // holding x_t and u_t. Writes x̂_{t+1} of every env to `next_states` (resized to
  // N × state_dim). Raises Error on a wrong width.
  virtual void predict(const BatchMatrix& windows, BatchMatrix& next_states) = 0;

  // One step of N environments: sets `inputs` (N × input_dim) as u_t, predicts x̂_{t+1} into
  // `next_states` and advances the windows by it.
  void step(HistoryWindows& windows, const BatchMatrix& inputs, BatchMatrix& next_states);
};

}  // namespace tendril::envs
