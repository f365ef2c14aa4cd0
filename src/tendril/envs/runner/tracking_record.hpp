#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "tendril/control/tracking_policy.hpp"
#include "tendril/envs/runner/policy_runner.hpp"

namespace tendril::envs {

// One run along a path: column k of each matrix is control step k.
struct TrackingRun {
  Eigen::VectorXd times;    // s, of the reading after the step
  Eigen::Matrix2Xd angles;  // deg, estimated from the reading after the step
  Eigen::Matrix2Xd goals;   // deg, the goal steered to during the step
  Eigen::Matrix2Xd throttles;
  bool finished = false;  // the last waypoint was reached within the step budget
  // The first step after the path's first point was reached: the steps before bring the limb
  // from wherever it rests onto the path and are not tracking.
  Eigen::Index first_on_path = 0;
  // tracking_rmse of angles[first_on_path:] to the follower's path; NaN when the path's first
  // point was never reached (nothing was tracked).
  double rmse_deg = 0.0;
};

// The record of a control::TrackingPolicy's run along its path (seed 001 §5.2, Tables 5.4 and
// 5.5): per step the estimated state after it, the goal and the throttles; whether the path was
// finished, where tracking began and its error. over() says when the run is done, for
// RunSettings::stop_requested: the reading after a step finishes the path, or the episode ended
// (a time limit). Raises Error when the limb's state becomes non-finite (a terminated step).
class TrackingRecord final : public RunObserver {
 public:
  explicit TrackingRecord(const control::TrackingPolicy& policy) : policy_(policy) {}

  void on_episode_start(int64_t episode, uint64_t seed, const Observation& reading,
                        const Env& env) override;
  void on_step(const StepView& step) override;

  bool over() const { return over_; }
  // The episode recorded last.
  TrackingRun run() const;

 private:
  const control::TrackingPolicy& policy_;
  std::vector<double> times_;
  std::vector<Eigen::Vector2d> angles_, goals_, throttles_;
  Eigen::Index first_on_path_ = -1;
  bool finished_ = false;
  bool over_ = false;
};

// Runs `policy` along its path on `limb` (run_policy, one episode reset with `seed`) until the
// path is finished or `max_steps` steps were taken, with a TrackingRecord and `observers` (e.g.
// PathPushes), and returns the record.
TrackingRun track_path(const control::TrackingPolicy& policy, Env& limb, int64_t max_steps,
                       uint64_t seed, const std::vector<RunObserver*>& observers = {});

}  // namespace tendril::envs
