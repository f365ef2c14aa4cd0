#include "tendril/safety/safety_filter.hpp"

#include <utility>

#include "tendril/core/error.hpp"

namespace tendril::safety {

SafetyFilter::SafetyFilter(TaskActor task, const SafetyCritic& critic, double threshold)
    : task_(std::move(task)), critic_(critic), threshold_(threshold) {
  require(static_cast<bool>(task_), "the task actor is empty", "SafetyFilter");
}

Action SafetyFilter::act(const Observation& observation) {
  Action action = task_(observation);
  ++decisions_;
  last_intervened_ = critic_.value(observation, action) <= threshold_;
  if (!last_intervened_) return action;
  ++interventions_;
  return critic_.safe_action(observation);
}

double SafetyFilter::intervention_rate() const {
  return decisions_ == 0 ? 0.0
                         : static_cast<double>(interventions_) / static_cast<double>(decisions_);
}

void SafetyFilter::reset_counts() {
  decisions_ = interventions_ = 0;
  last_intervened_ = false;
}

TaskActor policy_actor(const rl::Policy& policy, bool deterministic, Rng& rng) {
  return [&policy, deterministic, &rng](const Observation& observation) {
    return policy.act(observation, deterministic, rng);
  };
}

TaskActor random_actor(const Space& action_space, Rng& rng) {
  return [action_space, &rng](const Observation&) -> Action {
    if (action_space.is_discrete()) {
      return Action::Constant(1, static_cast<float>(rng.below(action_space.n())));
    }
    Action action(action_space.size());
    for (Eigen::Index i = 0; i < action.size(); ++i) {
      action[i] = static_cast<float>(rng.uniform(action_space.low()[i], action_space.high()[i]));
    }
    return action;
  };
}

}  // namespace tendril::safety
