#pragma once

#include <memory>

#include "tendril/adapt/reaching_robot.hpp"
#include "tendril/core/env.hpp"
#include "tendril/envs/reach_command_task.hpp"

namespace tendril::adapt {

// A ReachingRobot over any environment whose task is an envs::ReachCommandTask, found through
// any wrappers (the pneumatic arm's PneumaticArm/Reach-v0 on its robot interface, or
// PneumaticArm/LearnedReach-v0 for the coach's trajectories). Raises Error for an environment
// without one.
class TaskReachingRobot final : public ReachingRobot {
 public:
  explicit TaskReachingRobot(std::unique_ptr<Env> env);

  int state_dim() const override { return task_->state_dim(); }
  int command_dim() const override { return task_->command_dim(); }
  std::vector<std::string> state_names() const override { return task_->state_names(); }
  Eigen::VectorXd reset(std::optional<uint64_t> seed) override;
  Eigen::VectorXd step(const Eigen::VectorXd& command) override;
  const Eigen::VectorXd& command() const override { return command_; }
  const ReachStatus& status() const override { return status_; }
  Observation observation_of(const Eigen::VectorXd& state) const override {
    return task_->observation_at(state);
  }
  Eigen::VectorXd command_after(const Action& action) const override {
    return task_->command_after(action);
  }
  Eigen::Vector3d task_point(const Eigen::VectorXd& state) const override {
    return task_->task_point(state);
  }
  Eigen::Vector3d goal() const override { return task_->goal(); }
  double success_distance() const override { return task_->success_distance(); }

  Env& env() { return *env_; }

 private:
  std::unique_ptr<Env> env_;
  envs::ReachCommandTask* task_;
  Eigen::VectorXd command_;
  ReachStatus status_;
};

// GPRCA's model F_φ: the history model of an environment whose task is a ReachCommandTask on a
// learned model of the robot (PneumaticArm/LearnedReach-v0). Raises Error for an environment
// without one.
class TaskHistoryModel final : public RobotHistoryModel {
 public:
  explicit TaskHistoryModel(std::unique_ptr<Env> env);

  void reset(const Eigen::VectorXd& state) override { model_->reset(state); }
  Eigen::VectorXd predict(const Eigen::VectorXd& command) override {
    return model_->predict(command);
  }
  void follow(const Eigen::VectorXd& state) override { model_->follow(state); }

 private:
  std::unique_ptr<Env> env_;
  RobotHistoryModel* model_;
};

}  // namespace tendril::adapt
