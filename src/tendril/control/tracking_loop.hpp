#pragma once

#include <Eigen/Core>
#include <functional>

#include "tendril/control/pid.hpp"
#include "tendril/control/waypoint_follower.hpp"

namespace tendril::control {

// What a tracking controller knows of the limb at one control step: the reading's time (s), the
// bend angles (deg) and their rates (deg/s), as estimated from the sensor.
struct LimbState {
  double time_s = 0.0;
  Eigen::Vector2d angles = Eigen::Vector2d::Zero();
  Eigen::Vector2d rates = Eigen::Vector2d::Zero();
};

// The limb under closed-loop control — the twin now, the hardware later (adapters over the
// robot interface live above this layer).
class TrackedLimb {
 public:
  virtual ~TrackedLimb() = default;
  virtual LimbState reset() = 0;
  // Applies throttles (u_x, u_y) for one control step and returns the next state.
  virtual LimbState apply(const Eigen::Vector2d& throttles) = 0;
};

// Throttles from the state and the current goal: the PID baseline, a trained policy.
class TrackingController {
 public:
  virtual ~TrackingController() = default;
  virtual void reset() {}
  virtual Eigen::Vector2d throttles(const LimbState& state, const Eigen::Vector2d& goal,
                                    double dt_s) = 0;
};

class PidController final : public TrackingController {
 public:
  explicit PidController(Pid::Gains gains = {}) : pid_(gains) {}
  void reset() override { pid_.reset(); }
  Eigen::Vector2d throttles(const LimbState& state, const Eigen::Vector2d& goal,
                            double dt_s) override {
    return pid_.throttles(state.angles, state.rates, goal, dt_s);
  }

 private:
  Pid pid_;
};

// One run along a path: column k of each matrix is control step k.
struct TrackingRun {
  Eigen::VectorXd times;    // s
  Eigen::Matrix2Xd angles;  // deg, after the step
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

// Resets the limb, the controller and the follower, then each step: advance the follower on the
// latest state, ask the controller, apply; until the path is finished or `max_steps` steps.
// `before_step` (optional) is called before each step with the step index and the follower —
// where tests apply disturbances (the thesis' pushes at 1/4 and 3/4 of the circle).
TrackingRun track(TrackedLimb& limb, TrackingController& controller, WaypointFollower& follower,
                  int max_steps,
                  const std::function<void(int step, const WaypointFollower&)>& before_step = {});

}  // namespace tendril::control
