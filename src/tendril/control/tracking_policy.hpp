#pragma once

#include <Eigen/Core>
#include <memory>

#include "tendril/control/state_filter.hpp"
#include "tendril/control/tracking_controller.hpp"
#include "tendril/control/waypoint_follower.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/policy.hpp"

namespace tendril::control {

// Seed 001's waypoint tracking (thesis §5.2, §5.3.2) as a policy on the limb's readings
// (θx, θy in deg, t in s: SmaLimb/Robot-v0's observation). Each reading passes through the state
// estimate (StateFilter, by default the thesis' α = 0.8 of the training data), the follower
// advances on the estimated angles, and the controller (the PID baseline, a trained policy) gives
// the throttles towards the follower's current point.
//
// The path is over once a reading reaches its last point, and that reading is not acted on:
// progress() tells observers what the policy will make of a step's reading before it is asked to
// act on it, so that the run can stop there (envs::TrackingRecord). The runner takes at least one
// step, so a path whose every point is reached at the first reading still gets one.
//
// The estimate, the follower's position and the controller's memory are the policy's state
// within an episode: mutable members, forgotten in begin_episode (core/policy.hpp). The runner's
// `deterministic` and random stream are not used: the PID is deterministic, and a trained
// controller keeps its own mode and stream.
class TrackingPolicy final : public Policy {
 public:
  // What the policy makes of a reading.
  struct Progress {
    LimbState state;        // the estimate
    int waypoint = 0;       // the follower's index after the reading
    bool finished = false;  // past the last point: the path is over
  };
  // One control step as the policy took it.
  struct Decision {
    LimbState state;                                      // the estimate acted on
    Eigen::Vector2d goal = Eigen::Vector2d::Zero();       // deg, the point steered to
    Eigen::Vector2d throttles = Eigen::Vector2d::Zero();  // as the controller gave them
    bool on_path = false;                                 // the path's first point had been reached
  };

  // `limb` gives the spaces: a reading of 3 values in, 2 throttles out (Error otherwise).
  TrackingPolicy(const Env& limb, std::shared_ptr<TrackingController> controller,
                 WaypointFollower follower, StateFilter filter = StateFilter{});

  const Space& observation_space() const override { return readings_; }
  const Space& action_space() const override { return throttles_; }
  void begin_episode(const Observation& reading) const override;
  Action act(const Observation& reading, bool deterministic, Rng& rng) const override;

  // What the next act would make of `reading`, without acting.
  Progress progress(const Observation& reading) const;
  const Decision& last_decision() const { return decision_; }
  const WaypointFollower& follower() const { return follower_; }

 private:
  Space readings_, throttles_;
  std::shared_ptr<TrackingController> controller_;
  mutable WaypointFollower follower_;
  mutable StateFilter filter_;
  mutable bool started_ = false;
  mutable double previous_time_s_ = 0.0;
  mutable Decision decision_;
};

}  // namespace tendril::control
