#pragma once

#include <Eigen/Core>

namespace tendril::envs {

// A learned model of a robot fed the robot's measured history (GPRCA's F_φ, seed 002 §IV-C,
// Fig. 5), in the units of a ReachCommandTask's states and commands (reach_command_task.hpp).
class RobotHistoryModel {
 public:
  virtual ~RobotHistoryModel() = default;

  // The history is the robot at rest in `state` (command at rest).
  virtual void reset(const Eigen::VectorXd& state) = 0;
  // x̂_{t+1} for `command` held from now, from the history; the history does not move.
  virtual Eigen::VectorXd predict(const Eigen::VectorXd& command) = 0;
  // Appends the measured x_{t+1} (answering the command of the last predict) to the history.
  virtual void follow(const Eigen::VectorXd& state) = 0;
};

}  // namespace tendril::envs
