#include "tendril/adapt/task_reaching_robot.hpp"

#include "tendril/core/error.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::adapt {

namespace {

envs::ReachCommandTask& reach_task_of(Env& env, const char* where) {
  auto* task = envs::find_wrapper<envs::ReachCommandTask>(env);
  require(task != nullptr,
          "the environment's task is no reaching task driven by commands (envs::ReachCommandTask)",
          where);
  return *task;
}

}  // namespace

TaskReachingRobot::TaskReachingRobot(std::unique_ptr<Env> env)
    : env_(std::move(env)),
      task_(&reach_task_of(*env_, "adapt::TaskReachingRobot")),
      command_(task_->held_command()) {}

Eigen::VectorXd TaskReachingRobot::reset(std::optional<uint64_t> seed) {
  status_ = task_->reset_reach(seed);
  command_ = task_->held_command();
  return task_->measured_state();
}

Eigen::VectorXd TaskReachingRobot::step(const Eigen::VectorXd& command) {
  status_ = task_->hold_command(command);
  command_ = task_->held_command();
  return task_->measured_state();
}

TaskHistoryModel::TaskHistoryModel(std::unique_ptr<Env> env)
    : env_(std::move(env)),
      model_(reach_task_of(*env_, "adapt::TaskHistoryModel").history_model()) {
  require(model_ != nullptr, "the reaching task runs on no learned model of the robot",
          "adapt::TaskHistoryModel");
}

}  // namespace tendril::adapt
