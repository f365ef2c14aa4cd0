#pragma once

#include <cstdint>
#include <functional>

#include "tendril/core/rng.hpp"
#include "tendril/core/space.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/safety/safety_critic.hpp"

namespace tendril::safety {

// Any controller that acts from observations: a trained rl::Policy (policy_actor), a scripted
// sequence, a random one.
using TaskActor = std::function<Action(const Observation&)>;

// The least-restrictive safety filter of seed 001 eq. (6.5):
//
//   π_filter(x) = π_task(x)               if Q_s(x, π_task(x)) > ε₂
//                 argmax_u Q_s(x, u)       otherwise,
//
// around any task actor; the task actor need not be the one the critic was co-trained with
// (Table 6.2). Counts its decisions and interventions. Borrows the critic.
class SafetyFilter {
 public:
  SafetyFilter(TaskActor task, const SafetyCritic& critic, double threshold);

  Action act(const Observation& observation);

  double threshold() const { return threshold_; }
  void set_threshold(double threshold) { threshold_ = threshold; }
  bool last_intervened() const { return last_intervened_; }
  int64_t decisions() const { return decisions_; }
  int64_t interventions() const { return interventions_; }
  double intervention_rate() const;
  void reset_counts();

 private:
  TaskActor task_;
  const SafetyCritic& critic_;
  double threshold_;
  bool last_intervened_ = false;
  int64_t decisions_ = 0, interventions_ = 0;
};

// A policy as a task actor (its mode when `deterministic`, else draws from `rng`, which must
// outlive the actor, as must the policy).
TaskActor policy_actor(const rl::Policy& policy, bool deterministic, Rng& rng);
// Uniform random actions over a Box or Discrete space (Table 6.2's random policy).
TaskActor random_actor(const Space& action_space, Rng& rng);

}  // namespace tendril::safety
