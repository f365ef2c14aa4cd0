#pragma once

#include <Eigen/Core>

namespace tendril::control {

// The PID baseline of seed 001 (thesis §5.3.2, Fig. 5.12: Kp = 2, Ki = 0.001, Kd = 0.5, "tuned to
// the best of our ability"), one independent loop per bend axis, as its author's code runs it:
//   v = Kp e + Ki ∫ e dt − Kd θ̇,   e = θ_goal − θ  (degrees),
// with the derivative on the measured rate θ̇ (deg/s), not on the error, so a jump of the goal
// gives no kick; v is saturated to [−1, 1], the policy's action range, and scaled to throttles
// (±10). With Kp = 2 the output saturates for errors beyond 0.5°. The integral runs over the
// real time between control steps (s); the thesis gives no anti-windup and none is applied.
class Pid {
 public:
  struct Gains {
    double kp = 2.0;
    double ki = 0.001;
    double kd = 0.5;
  };
  static constexpr double kMaxThrottle = 10.0;

  Pid() : Pid(Gains{}) {}
  explicit Pid(Gains gains);

  // Throttles (u_x, u_y) ∈ [−10, 10]² for the measured angles (deg) and rates (deg/s) towards
  // `goal` (deg); `dt_s` is the time since the previous call (0 on the first).
  Eigen::Vector2d throttles(const Eigen::Vector2d& angles, const Eigen::Vector2d& rates,
                            const Eigen::Vector2d& goal, double dt_s);
  void reset() { integral_.setZero(); }

  const Gains& gains() const { return gains_; }
  const Eigen::Vector2d& integral() const { return integral_; }  // ∫ e dt, deg·s

 private:
  Gains gains_;
  Eigen::Vector2d integral_ = Eigen::Vector2d::Zero();
};

}  // namespace tendril::control
