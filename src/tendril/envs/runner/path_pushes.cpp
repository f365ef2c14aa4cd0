#include "tendril/envs/runner/path_pushes.hpp"

#include <utility>

#include "tendril/core/error.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs {

PathPushes::PathPushes(const control::TrackingPolicy& policy, Env& robot, Eigen::VectorXd force_n,
                       double duration_s, std::vector<int> waypoints, int64_t max_steps)
    : policy_(policy),
      robot_(find_wrapper<PushableRobot>(robot)),
      force_n_(std::move(force_n)),
      duration_s_(duration_s),
      waypoints_(std::move(waypoints)),
      max_steps_(max_steps) {
  require(robot_ != nullptr, "the robot cannot be pushed", "PathPushes");
}

void PathPushes::on_episode_start(int64_t /*episode*/, uint64_t /*seed*/,
                                  const Observation& reading, const Env& /*env*/) {
  pushes_ = 0;
  before_acting_on(reading);
}

void PathPushes::on_step(const StepView& step) {
  const bool last = step.result.terminated || step.result.truncated || step.step + 1 >= max_steps_;
  if (!last) before_acting_on(step.result.observation);
}

void PathPushes::before_acting_on(const Observation& reading) {
  if (pushes_ >= waypoints_.size()) return;
  const control::TrackingPolicy::Progress next = policy_.progress(reading);
  // A finished path takes no further step.
  if (!next.finished && next.waypoint >= waypoints_[pushes_]) {
    robot_->push_tip(force_n_, duration_s_);
    ++pushes_;
  }
}

}  // namespace tendril::envs
