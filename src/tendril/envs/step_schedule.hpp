#pragma once

#include <cstdint>
#include <string>

#include "tendril/core/config.hpp"

namespace tendril::envs {

// A parameter of an environment that changes with the environment's own step count — a reward
// weight on a curriculum, say — so that the schedule needs nothing from the trainer: constant,
// or linear from `start` at step 0 to `end` at step `steps`, and `end` after that.
//
// The count is that of one environment instance, over all its episodes (resets do not restart
// it; snapshots carry it). With n_envs copies stepped in parallel, `steps` env steps of each are
// n_envs × steps steps of training: a curriculum over a budget of T training steps uses
// steps = T / n_envs. Training checkpoints do not hold environment snapshots (yet), so a run
// resumed from a checkpoint builds fresh environments whose counts start again from 0.
class StepSchedule {
 public:
  static StepSchedule constant(double value);
  // Raises Error unless start and end are finite and steps ≥ 1.
  static StepSchedule linear(double start, double end, int64_t steps);

  // From an environment's params: `<key>: value` (a constant), or
  //   `<key>_schedule: {start: a, end: b, steps: n}` (linear),
  // or `fallback` when neither is given; both at once, or a bad value, raise Error naming the key.
  static StepSchedule from_config(const Config& params, const std::string& key, double fallback);

  double value(int64_t step) const;
  bool is_constant() const { return steps_ == 0; }
  double start() const { return start_; }
  double end() const { return end_; }
  int64_t steps() const { return steps_; }

 private:
  StepSchedule(double start, double end, int64_t steps) : start_(start), end_(end), steps_(steps) {}

  double start_ = 0.0;
  double end_ = 0.0;
  int64_t steps_ = 0;  // 0: constant
};

}  // namespace tendril::envs
