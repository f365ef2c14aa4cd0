#pragma once

#include <cstdint>

#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::envs {

// The unsafe set of a task as a safety agent sees it, from observations alone (seed 001 eq.
// 6.4): the signed distance d to X_unsafe (unsafe where d ≤ 0), its maximum over the safe set,
// the episode time t held in the observation, and draws of unsafe observations for the
// supervised loss (eq. 6.6). Observations are the task's raw ones (no VecNormalize). A
// SafetyTask (safety_task.hpp) makes one for the safety filter (safety/).
class SafetyConstraint {
 public:
  virtual ~SafetyConstraint() = default;

  virtual double margin(const Observation& observation) const = 0;
  virtual double max_margin() const = 0;
  // The time step t of the observation within its episode.
  virtual int64_t time_step(const Observation& observation) const = 0;
  virtual int64_t horizon() const = 0;
  // An observation uniformly drawn over the absolute bounds (time uniform over the episode),
  // redrawn until it is unsafe.
  virtual Observation sample_unsafe(Rng& rng) const = 0;

  bool unsafe(const Observation& observation) const { return margin(observation) <= 0.0; }
};

}  // namespace tendril::envs
