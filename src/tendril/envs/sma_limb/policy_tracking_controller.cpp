#include "tendril/envs/sma_limb/policy_tracking_controller.hpp"

#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs::sma_limb {

PolicyTrackingController::PolicyTrackingController(std::shared_ptr<const Policy> policy,
                                                   const LearnedReachOptions& options,
                                                   bool deterministic, uint64_t seed)
    : policy_(std::move(policy)),
      observer_(options),
      deterministic_(deterministic),
      seed_(seed),
      rng_(seed),
      observation_(Observation::Zero(observer_.observation_size())) {
  require(policy_->observation_space().size() == observer_.observation_size() &&
              policy_->action_space().size() == 2,
          "the policy reads " + std::to_string(policy_->observation_space().size()) +
              " values and acts on " + std::to_string(policy_->action_space().size()) +
              "; the limb's reaching observation has " +
              std::to_string(observer_.observation_size()) + " and 2 throttles",
          "tendril track --policy");
}

void PolicyTrackingController::reset() {
  started_ = false;
  rng_ = Rng(seed_);
}

Eigen::Vector2d PolicyTrackingController::throttles(const control::LimbState& state,
                                                    const Eigen::Vector2d& goal, double) {
  Eigen::Vector4d x;
  x << state.angles, state.rates;
  const bool first = !started_;
  if (started_) {
    observer_.reached(x);
  } else {
    observer_.reset(x);
    started_ = true;
  }
  observer_.observe(Eigen::Vector4d(goal.x(), goal.y(), 0.0, 0.0), observation_);
  // A policy with memory within an episode (a safety filter around the trained one) starts one.
  if (first) policy_->begin_episode(observation_);
  const Action action = policy_->act(observation_, deterministic_, rng_);
  const Eigen::Vector2d throttles =
      action.cast<double>().array().round().cwiseMax(-kMaxThrottle).cwiseMin(kMaxThrottle);
  observer_.apply(throttles);
  return throttles;
}

}  // namespace tendril::envs::sma_limb
