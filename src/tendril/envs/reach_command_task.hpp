#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/envs/robot_history_model.hpp"

namespace tendril::envs {

// What the last reset or command of a ReachCommandTask scored, on the measured state.
struct ReachStatus {
  double goal_distance = 0.0;      // task point to goal, the state's units (mm)
  double obstacle_distance = 0.0;  // task point to the obstacle
  double reward = 0.0;             // the task's reward for the step (0 after a reset)
  bool success = false;            // within the task's success distance, no collision
  bool collision = false;          // the step crossed or touched the obstacle (ends a trial)
  bool outside = false;            // the task point is outside the boundary
  bool rate_limited = false;       // the command's change was limited
};

// A reaching task driven by absolute actuator commands, as online adaptation (adapt/: seed 002's
// BOAC §IV-B and GPRCA §IV-C) drives it: states are the task-space positions the robot measures
// (the pneumatic arm: the three module tips, mm), commands its actuator inputs (the nine
// normalised pressures a ∈ [−1, 1]⁹), and the trained policy sees observations built from a
// state and the held command. The adaptation layer finds it through any wrappers
// (find_wrapper<ReachCommandTask>) and drives the task itself, past them; a task gains online
// adaptation by implementing this in its own folder.
class ReachCommandTask {
 public:
  virtual ~ReachCommandTask() = default;

  virtual int state_dim() const = 0;
  virtual int command_dim() const = 0;
  // Column names of the state's coordinates, for logs.
  virtual std::vector<std::string> state_names() const = 0;

  // Starts a trial as Env::reset does (a seed restarts the task's random streams), the command
  // at rest; the status of the start.
  virtual ReachStatus reset_reach(std::optional<uint64_t> seed) = 0;
  // Holds `command` for one control period (the task may limit its change and range) and scores
  // the step. Raises Error for a command of the wrong size or a robot whose state became
  // non-finite.
  virtual ReachStatus hold_command(const Eigen::VectorXd& command) = 0;
  // The state measured after the last reset or command, and the command held.
  virtual Eigen::VectorXd measured_state() const = 0;
  virtual Eigen::VectorXd held_command() const = 0;

  // The policy's observation if the state were `state`, with the held command.
  virtual Observation observation_at(const Eigen::VectorXd& state) const = 0;
  // The command that the policy's action leads to from the held command.
  virtual Eigen::VectorXd command_after(const Action& action) const = 0;

  // The point of a state that must reach the goal (the pneumatic arm: module 3's tip), and the
  // goal.
  virtual Eigen::Vector3d task_point(const Eigen::VectorXd& state) const = 0;
  virtual Eigen::Vector3d goal() const = 0;
  // The task's success distance (the goal flag's threshold).
  virtual double success_distance() const = 0;

  // Where the task runs on a learned model of the robot: that model fed the robot's measured
  // history (GPRCA's F_φ); nullptr on the robot itself.
  virtual RobotHistoryModel* history_model() { return nullptr; }
};

}  // namespace tendril::envs
