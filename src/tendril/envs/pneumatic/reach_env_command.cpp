// ReachEnv as a ReachCommandTask: the pneumatic arm's reaching task as online adaptation drives
// it (seed 002 §IV-B, §IV-C).
#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/envs/pneumatic/reach_env.hpp"

namespace tendril::envs::pneumatic {
namespace {

bool flag(const Info& info, const char* key) { return info.get(key).value_or(0.0) != 0.0; }

}  // namespace

std::vector<std::string> ReachEnv::state_names() const {
  std::vector<std::string> names;
  for (int module = 1; module <= 3; ++module) {
    for (const char* axis : {"x", "y", "z"}) {
      names.push_back("tip_m" + std::to_string(module) + "_" + axis + "_mm");
    }
  }
  return names;
}

ReachStatus ReachEnv::reset_reach(std::optional<uint64_t> seed) {
  reset(seed);
  // The distances from the tips (a reset scores no step).
  const Eigen::Vector3d tip = tips_.tail<3>();
  ReachStatus status;
  status.goal_distance = (tip - setup_.task.goal).norm();
  status.obstacle_distance = obstacle_distance(setup_.task, tip);
  return status;
}

ReachStatus ReachEnv::hold_command(const Eigen::VectorXd& command) {
  require(command.size() == 9, "the command must have 9 values", setup_.id);
  const Step step = step_command(command);
  require(step.info.get(info_keys::kNan).value_or(0.0) == 0.0, "the arm's state became non-finite",
          setup_.id);
  ReachStatus status;
  status.goal_distance = step.info.get("goal_distance_mm").value_or(0.0);
  status.obstacle_distance = step.info.get("obstacle_distance_mm").value_or(0.0);
  status.reward = step.reward;
  status.success = flag(step.info, info_keys::kIsSuccess);
  status.collision = flag(step.info, info_keys::kCollision);
  status.outside = flag(step.info, "outside_boundary");
  status.rate_limited = flag(step.info, "rate_limited");
  return status;
}

Observation ReachEnv::observation_at(const Eigen::VectorXd& state) const {
  require(state.size() == 9, "the state must have 9 values", setup_.id);
  return observation_of(TipVector(state));
}

Eigen::VectorXd ReachEnv::command_after(const Action& action) const {
  require(action.size() == 9 && action.allFinite(), "the action must be 9 finite values",
          setup_.id);
  const ChamberVector delta = action.cast<double>();
  // As step(): a delta beyond the rate limit is not taken.
  if (delta.cwiseAbs().maxCoeff() > setup_.rate_limit * (1.0 + 1e-6)) return command_;
  return (command_ + delta).cwiseMax(-1.0).cwiseMin(1.0);
}

Eigen::Vector3d ReachEnv::task_point(const Eigen::VectorXd& state) const {
  require(state.size() == 9, "the state must have 9 values", setup_.id);
  return state.tail<3>();
}

}  // namespace tendril::envs::pneumatic
