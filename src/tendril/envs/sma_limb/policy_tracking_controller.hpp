#pragma once

#include <memory>

#include "tendril/control/tracking_controller.hpp"
#include "tendril/core/policy.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/sma_limb/learned_reach_task.hpp"
#include "tendril/envs/sma_limb/reach_observation.hpp"

namespace tendril::envs::sma_limb {

// A policy trained in SmaLimb/LearnedReach-v0 as a tracking controller on the limb (`tendril track
// --policy`; seed 001 §5.2, Fig. 5.4): each control step it reads the filtered state, builds the
// training observation (ReachObserver, with the run's power-proxy and history settings; goal
// velocity 0) with the waypoint follower's current point as the goal, and applies the policy's
// throttles rounded to whole throttles. `deterministic`: the policy's mean action; otherwise
// sampled (the thesis' deployed policy samples), from a stream seeded with `seed`.
class PolicyTrackingController final : public control::TrackingController {
 public:
  PolicyTrackingController(std::shared_ptr<const Policy> policy, const LearnedReachOptions& options,
                           bool deterministic, uint64_t seed);

  void reset() override;
  Eigen::Vector2d throttles(const control::LimbState& state, const Eigen::Vector2d& goal,
                            double dt_s) override;

 private:
  std::shared_ptr<const Policy> policy_;
  ReachObserver observer_;
  bool deterministic_;
  uint64_t seed_;
  Rng rng_;
  bool started_ = false;
  Observation observation_;
};

}  // namespace tendril::envs::sma_limb
