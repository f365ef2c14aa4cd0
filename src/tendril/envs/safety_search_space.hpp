#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::envs {

// The states Algorithm 3 (seed 001 §6.3.2) and the value maps of Figs. 6.4 and 6.6 move
// through, for one task: a vector s of the physical state in normalized units (each coordinate
// over its scale, e.g. the safe bound), the observation of s at the start of an episode (t = 0),
// and placing an environment in s to roll a policy out from it. A SafetyTask
// (safety_task.hpp) makes one for the safety filter's tools (safety/).
class SafetySearchSpace {
 public:
  virtual ~SafetySearchSpace() = default;

  // Coordinate names and the physical value of one normalized unit of each.
  virtual const std::vector<std::string>& names() const = 0;
  virtual const Eigen::VectorXd& scales() const = 0;
  int dimension() const { return static_cast<int>(names().size()); }

  virtual Observation observation(const Eigen::VectorXd& state) const = 0;
  // Puts `env` (this space's task, through any wrappers, just reset) in `state` at t = 0.
  virtual void place(Env& env, const Eigen::VectorXd& state) const = 0;
  // A state drawn uniformly over the safe box.
  virtual Eigen::VectorXd sample(Rng& rng) const = 0;
  // Whether `state` lies in the analytic safe set, where one is known (the double integrator's
  // viability kernel); nullopt elsewhere.
  virtual std::optional<bool> analytically_safe(const Eigen::VectorXd& /*state*/) const {
    return std::nullopt;
  }
};

}  // namespace tendril::envs
