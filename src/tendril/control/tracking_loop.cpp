#include "tendril/control/tracking_loop.hpp"

#include <limits>
#include <string>
#include <vector>

#include "tendril/control/reference_patterns.hpp"
#include "tendril/core/error.hpp"

namespace tendril::control {

TrackingRun track(TrackedLimb& limb, TrackingController& controller, WaypointFollower& follower,
                  int max_steps,
                  const std::function<void(int step, const WaypointFollower&)>& before_step) {
  require(max_steps >= 1, "max_steps must be >= 1, got " + std::to_string(max_steps),
          "control::track");
  controller.reset();
  follower.restart();
  LimbState state = limb.reset();
  std::vector<double> times;
  std::vector<Eigen::Vector2d> angles, goals, throttles;
  double previous_time = state.time_s;
  Eigen::Index first_on_path = -1;
  for (int step = 0; step < max_steps; ++step) {
    const Eigen::Vector2d goal = follower.update(state.angles);
    if (follower.finished()) break;
    if (first_on_path < 0 && follower.index() >= 1)
      first_on_path = static_cast<Eigen::Index>(times.size());
    if (before_step) before_step(step, follower);
    const Eigen::Vector2d u = controller.throttles(state, goal, state.time_s - previous_time);
    previous_time = state.time_s;
    state = limb.apply(u);
    times.push_back(state.time_s);
    angles.push_back(state.angles);
    goals.push_back(goal);
    throttles.push_back(u);
  }
  // The step that reached the last point is the run's last one.
  if (!follower.finished()) follower.update(state.angles);
  TrackingRun run;
  const auto n = static_cast<Eigen::Index>(times.size());
  run.times.resize(n);
  run.angles.resize(2, n);
  run.goals.resize(2, n);
  run.throttles.resize(2, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    run.times[k] = times[k];
    run.angles.col(k) = angles[k];
    run.goals.col(k) = goals[k];
    run.throttles.col(k) = throttles[k];
  }
  run.finished = follower.finished();
  run.first_on_path = first_on_path < 0 ? n : first_on_path;
  run.rmse_deg = run.first_on_path < n
                     ? tracking_rmse(run.angles.rightCols(n - run.first_on_path), follower.points())
                     : std::numeric_limits<double>::quiet_NaN();
  return run;
}

}  // namespace tendril::control
