#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "tendril/control/tracking_policy.hpp"
#include "tendril/envs/pushable_robot.hpp"
#include "tendril/envs/runner/policy_runner.hpp"

namespace tendril::envs {

// The robustness test's disturbance (seed 001 §5.2.2 (a)): a shove on the robot's tip when a
// control::TrackingPolicy's follower first steers to each of the given waypoints, applied before
// the step that steers to it; never after a run's last step (the step budget `max_steps` used, or
// the episode ended). The robot is found through any wrappers (PushableRobot; Error when there is
// none); a robot that cannot be pushed by software raises Error at the first push.
class PathPushes final : public RunObserver {
 public:
  // `waypoints` in increasing order; `force_n` along the robot's own axes (N), held for
  // `duration_s`; `max_steps` the run's step budget (track_path's).
  PathPushes(const control::TrackingPolicy& policy, Env& robot, Eigen::VectorXd force_n,
             double duration_s, std::vector<int> waypoints, int64_t max_steps);

  void on_episode_start(int64_t episode, uint64_t seed, const Observation& reading,
                        const Env& env) override;
  void on_step(const StepView& step) override;

  std::size_t pushes() const { return pushes_; }  // in the episode running or ended last

 private:
  // Pushes when the policy, acting next on `reading`, steers to the next due waypoint.
  void before_acting_on(const Observation& reading);

  const control::TrackingPolicy& policy_;
  PushableRobot* robot_;
  Eigen::VectorXd force_n_;
  double duration_s_;
  std::vector<int> waypoints_;
  int64_t max_steps_;
  std::size_t pushes_ = 0;
};

}  // namespace tendril::envs
