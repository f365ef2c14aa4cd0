#include "tendril/control/pid.hpp"

#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::control {

Pid::Pid(Gains gains) : gains_(gains) {
  require(std::isfinite(gains.kp) && std::isfinite(gains.ki) && std::isfinite(gains.kd),
          "PID gains must be finite", "control::Pid");
}

Eigen::Vector2d Pid::throttles(const Eigen::Vector2d& angles, const Eigen::Vector2d& rates,
                               const Eigen::Vector2d& goal, double dt_s) {
  require(angles.allFinite() && rates.allFinite() && goal.allFinite() && std::isfinite(dt_s) &&
              dt_s >= 0.0,
          "PID needs finite measurements and goal and dt >= 0, got dt = " + std::to_string(dt_s),
          "control::Pid");
  const Eigen::Vector2d error = goal - angles;
  integral_ += error * dt_s;
  const Eigen::Vector2d output = gains_.kp * error + gains_.ki * integral_ - gains_.kd * rates;
  return kMaxThrottle * output.cwiseMax(-1.0).cwiseMin(1.0);
}

}  // namespace tendril::control
