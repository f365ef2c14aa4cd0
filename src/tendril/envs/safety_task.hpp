#pragma once

#include <memory>

#include "tendril/envs/safety_constraint.hpp"
#include "tendril/envs/safety_search_space.hpp"

namespace tendril::envs {

// A task with a state constraint to keep (seed 001 ch. 6): what the safety filter (safety/)
// needs of it, its constraint for co-training and evaluation, and its search space for the
// filter's tools (the ε₂ search, value maps). The safety layer finds it through any wrappers
// (find_wrapper<SafetyTask>), so a task gains the filter by implementing this in its own
// folder. Both are made from the task's parameters and outlive it.
class SafetyTask {
 public:
  virtual ~SafetyTask() = default;

  virtual std::unique_ptr<SafetyConstraint> safety_constraint() const = 0;
  virtual std::unique_ptr<SafetySearchSpace> safety_search_space() const = 0;
};

}  // namespace tendril::envs
