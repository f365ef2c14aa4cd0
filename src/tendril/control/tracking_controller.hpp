#pragma once

#include <Eigen/Core>

#include "tendril/control/pid.hpp"

namespace tendril::control {

// What a tracking controller knows of the limb at one control step: the reading's time (s), the
// bend angles (deg) and their rates (deg/s), as estimated from the sensor (StateFilter).
struct LimbState {
  double time_s = 0.0;
  Eigen::Vector2d angles = Eigen::Vector2d::Zero();
  Eigen::Vector2d rates = Eigen::Vector2d::Zero();
};

// Throttles from the state and the current goal, the inner part of a TrackingPolicy: the PID
// baseline, a trained policy (envs::sma_limb::PolicyTrackingController).
class TrackingController {
 public:
  virtual ~TrackingController() = default;
  // A new path begins.
  virtual void reset() {}
  // `dt_s`: the time since the previous call of this path (0 on its first).
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

}  // namespace tendril::control
