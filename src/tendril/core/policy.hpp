#pragma once

#include "tendril/core/batch_matrix.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"

namespace tendril {

// Whatever chooses actions from observations: a trained network (rl::Policy), a PID or waypoint
// controller, a safety filter around another policy, a student of an adaptation. The policy
// runner (envs/runner) runs any of them on any environment, a twin or a robot behind a bridge.
//
// `deterministic` asks for the policy's mode (a stochastic policy's mean; controllers are
// deterministic anyway); random draws come from `rng`. Acting does not change what the policy is
// (its weights, its gains), so the calls are const; a policy with memory within an episode (a PID
// integrator, a filter's last intervention) keeps it in mutable members and forgets it in
// begin_episode. One policy acts from one thread at a time.
class Policy {
 public:
  virtual ~Policy() = default;

  virtual const Space& observation_space() const = 0;
  virtual const Space& action_space() const = 0;

  // A new episode begins; `observation` is its first.
  virtual void begin_episode(const Observation& /*observation*/) const {}
  virtual Action act(const Observation& observation, bool deterministic, Rng& rng) const = 0;
  // One row per observation in, one row per action out. By default row by row.
  virtual void act(const BatchMatrix& observations, bool deterministic, Rng& rng,
                   BatchMatrix& actions) const;
};

}  // namespace tendril
