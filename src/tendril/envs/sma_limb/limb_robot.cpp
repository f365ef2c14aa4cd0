#include "tendril/envs/sma_limb/limb_robot.hpp"

#include "tendril/core/error.hpp"

namespace tendril::envs::sma_limb {

void LimbRobot::save_state(SnapshotWriter& /*out*/) const {
  throw Error("this robot cannot save its state", "LimbRobot::save_state");
}

void LimbRobot::load_state(SnapshotReader& /*in*/) {
  throw Error("this robot cannot load a state", "LimbRobot::load_state");
}

void LimbRobot::push(const Eigen::Vector2d& /*force_n*/, double /*duration_s*/) {
  throw Error("this robot cannot be pushed by software", "LimbRobot::push");
}

}  // namespace tendril::envs::sma_limb
