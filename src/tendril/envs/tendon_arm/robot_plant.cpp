#include "tendril/envs/tendon_arm/robot_plant.hpp"

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"

namespace tendril::envs::tendon_arm {

RobotPlant::RobotPlant(std::unique_ptr<Env> robot) : robot_(std::move(robot)) {
  require(robot_ != nullptr, "no robot", "tendon_arm::RobotPlant");
  require(robot_->action_space().is_box() && robot_->action_space().size() >= 1,
          "the robot must take a box of tendon tensions", "tendon_arm::RobotPlant");
  require(robot_->observation_space().size() >= 3, "the robot must observe the tip first",
          "tendon_arm::RobotPlant");
  action_ = Action::Zero(robot_->action_space().size());
}

Eigen::Vector3d RobotPlant::reset(std::optional<uint64_t> seed) {
  finite_ = true;
  return robot_->reset(seed).head<3>().cast<double>();
}

Eigen::Vector3d RobotPlant::step(const Eigen::VectorXd& tensions) {
  action_ = tensions.cast<float>();
  const Step step = robot_->step(action_);
  finite_ = step.info.get(info_keys::kNan).value_or(0.0) == 0.0;
  return step.observation.head<3>().cast<double>();
}

void RobotPlant::save_state(SnapshotWriter& out) const {
  out.section("tendon_arm::RobotPlant");
  out.put(finite_);
  robot_->save_state(out);
}

void RobotPlant::load_state(SnapshotReader& in) {
  in.section("tendon_arm::RobotPlant");
  const bool finite = in.get_bool();
  robot_->load_state(in);
  finite_ = finite;
}

}  // namespace tendril::envs::tendon_arm
