#pragma once

#include <Eigen/Core>

namespace tendril::envs {

// A robot that software can push: a force on its tip held for a while, the disturbance of
// robustness tests (seed 001 §5.2.2 (a): shoves along the path). Commands that disturb a robot
// (`tendril track --push`) find it through any wrappers (find_wrapper<PushableRobot>).
class PushableRobot {
 public:
  virtual ~PushableRobot() = default;

  // The number of force components push_tip takes (the SMA limb: 2, along its x and y).
  virtual int push_dim() const = 0;
  // A force on the tip (N, along the robot's own axes) for `duration_s` from now. Raises Error
  // for a force of the wrong size or a non-finite value, and where the robot behind the
  // interface cannot be pushed by software (a real robot: a hand pushes it).
  virtual void push_tip(const Eigen::VectorXd& force_n, double duration_s) = 0;
};

}  // namespace tendril::envs
