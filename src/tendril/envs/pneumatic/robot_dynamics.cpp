#include "tendril/envs/pneumatic/robot_dynamics.hpp"

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"

namespace tendril::envs::pneumatic {

void ArmDynamics::save_state(SnapshotWriter&) const {
  throw Error("this arm dynamics does not support snapshots", "ArmDynamics::save_state");
}

void ArmDynamics::load_state(SnapshotReader&) {
  throw Error("this arm dynamics does not support snapshots", "ArmDynamics::load_state");
}

RobotDynamics::RobotDynamics(std::unique_ptr<Env> robot)
    : robot_(std::move(robot)), action_(Action::Zero(physics::pneumatic::kChambers)) {
  require(robot_ != nullptr, "no robot", "RobotDynamics");
  require(robot_->action_space().is_box() &&
              robot_->action_space().size() == physics::pneumatic::kChambers,
          "the robot must take 9 pressures", "RobotDynamics");
  require(robot_->observation_space().size() >= 9, "the robot must observe 9 tip coordinates",
          "RobotDynamics");
}

TipVector RobotDynamics::tips(const Observation& observation) {
  return observation.head<9>().cast<double>();
}

TipVector RobotDynamics::reset(std::optional<uint64_t> seed) {
  finite_ = true;
  return tips(robot_->reset(seed));
}

TipVector RobotDynamics::step(const ChamberVector& pressures_bar) {
  action_ = pressures_bar.cast<float>();
  const Step step = robot_->step(action_);
  finite_ = step.info.get(info_keys::kNan).value_or(0.0) == 0.0;
  return tips(step.observation);
}

void RobotDynamics::save_state(SnapshotWriter& out) const {
  out.section("RobotDynamics");
  out.put(finite_);
  robot_->save_state(out);
}

void RobotDynamics::load_state(SnapshotReader& in) {
  in.section("RobotDynamics");
  const bool finite = in.get_bool();
  robot_->load_state(in);
  finite_ = finite;
}

}  // namespace tendril::envs::pneumatic
