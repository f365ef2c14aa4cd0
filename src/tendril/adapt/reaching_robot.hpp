#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tendril/core/space.hpp"
#include "tendril/envs/reach_command_task.hpp"
#include "tendril/envs/robot_history_model.hpp"

namespace tendril::adapt {

// What the last reset or step of a ReachingRobot scored (envs/reach_command_task.hpp).
using envs::ReachStatus;

// A robot with a reaching task, as the online adaptation of seed 002 (BOAC §IV-B, GPRCA §IV-C)
// drives it: states are the task-space positions the robot measures (the pneumatic arm: the
// three module tips, mm), commands its normalised actuator inputs (the nine pressures as
// a ∈ [−1, 1]⁹), and the trained policy (the oracle, π_θ) sees observations built from a state
// and the held command. Implemented over any envs::ReachCommandTask (TaskReachingRobot: the
// pneumatic arm's task on the robot interface or in its learned model) and by scripted plants
// in tests.
class ReachingRobot {
 public:
  virtual ~ReachingRobot() = default;

  virtual int state_dim() const = 0;
  virtual int command_dim() const = 0;
  // Column names of the state's coordinates, for logs.
  virtual std::vector<std::string> state_names() const = 0;

  // Starts a trial (a seed restarts the robot's random streams) with the command at rest;
  // returns x_0.
  virtual Eigen::VectorXd reset(std::optional<uint64_t> seed) = 0;
  // Holds `command` for one control period (the robot may limit its change and range) and
  // returns x_{t+1}.
  virtual Eigen::VectorXd step(const Eigen::VectorXd& command) = 0;
  // The command held now.
  virtual const Eigen::VectorXd& command() const = 0;
  virtual const ReachStatus& status() const = 0;

  // The policy's observation if the state were `state`, with the held command.
  virtual Observation observation_of(const Eigen::VectorXd& state) const = 0;
  // The command that the policy's action (a delta) leads to from the held command.
  virtual Eigen::VectorXd command_after(const Action& action) const = 0;

  // The point of a state that must reach the goal (module 3's tip), and the goal.
  virtual Eigen::Vector3d task_point(const Eigen::VectorXd& state) const = 0;
  virtual Eigen::Vector3d goal() const = 0;
  // The task's success distance (the goal flag's threshold).
  virtual double success_distance() const = 0;
};

// The learned model of the robot fed the robot's real history (GPRCA's F_φ, seed 002 §IV-C,
// Fig. 5; envs/robot_history_model.hpp).
using envs::RobotHistoryModel;

}  // namespace tendril::adapt
