#include "tendril/safety/filtered_policy.hpp"

namespace tendril::safety {

FilteredPolicy::FilteredPolicy(const Policy& inner, const SafetyCritic& critic, double threshold)
    : inner_(inner),
      filter_(std::make_unique<SafetyFilter>(
          [this](const Observation& observation) {
            return inner_.act(observation, deterministic_, *rng_);
          },
          critic, threshold)) {}

void FilteredPolicy::begin_episode(const Observation& observation) const {
  inner_.begin_episode(observation);
}

Action FilteredPolicy::act(const Observation& observation, bool deterministic, Rng& rng) const {
  deterministic_ = deterministic;
  rng_ = &rng;
  return filter_->act(observation);
}

}  // namespace tendril::safety
