#pragma once

#include <memory>

#include "tendril/core/policy.hpp"
#include "tendril/safety/safety_critic.hpp"
#include "tendril/safety/safety_filter.hpp"

namespace tendril::safety {

// A policy behind the safety filter of seed 001 eq. (6.5): the inner policy's action where the
// critic deems it safe (Q_s(x, π(x)) > ε₂), the critic's safest action otherwise. What
// `tendril run --filter` deploys, on a twin or on a robot behind its bridge. Borrows the inner
// policy and the critic.
class FilteredPolicy : public Policy {
 public:
  FilteredPolicy(const Policy& inner, const SafetyCritic& critic, double threshold);

  const Space& observation_space() const override { return inner_.observation_space(); }
  const Space& action_space() const override { return inner_.action_space(); }
  void begin_episode(const Observation& observation) const override;
  Action act(const Observation& observation, bool deterministic, Rng& rng) const override;

  const SafetyFilter& filter() const { return *filter_; }

 private:
  const Policy& inner_;
  // The filter asks its task actor for the inner policy's action with the current call's
  // settings, which act() sets before asking.
  mutable bool deterministic_ = true;
  mutable Rng* rng_ = nullptr;
  std::unique_ptr<SafetyFilter> filter_;
};

}  // namespace tendril::safety
