#include "tendril/envs/sma_limb/bridge_limb_robot.hpp"

#include "tendril/envs/hardware_info.hpp"
#include "tendril/envs/sma_limb/sma_limb_env.hpp"
#include "tendril/hardware/transport_config.hpp"

namespace tendril::envs::sma_limb {

BridgeLimbRobot::BridgeLimbRobot(std::unique_ptr<hardware::LimbBridge> bridge)
    : bridge_(std::move(bridge)) {
  require(bridge_ != nullptr, "needs a bridge", "BridgeLimbRobot");
}

LimbSample BridgeLimbRobot::reset(uint64_t seed) {
  last_ = bridge_->reset(seed);
  return {last_.time_s, last_.angles_deg};
}

LimbSample BridgeLimbRobot::command(const std::array<int, 4>& pwm) {
  last_ = bridge_->command(pwm);
  return {last_.time_s, last_.angles_deg};
}

std::string BridgeLimbRobot::description() const {
  return "SMA limb '" + bridge_->identity().robot + "' (firmware " +
         bridge_->identity().firmware_version() + ") on " + bridge_->port_name();
}

std::unique_ptr<Env> make_bridge_limb_env(const Config& bridge, LimbCalibration calibration,
                                          uint64_t seed) {
  hardware::LimbBridgeSettings settings =
      hardware::LimbBridgeSettings::from(bridge, SmaLimbEnv::kId);
  auto robot = std::make_unique<BridgeLimbRobot>(
      std::make_unique<hardware::LimbBridge>(hardware::open_transport(bridge), settings));
  BridgeLimbRobot* link = robot.get();
  auto env = std::make_unique<SmaLimbEnv>(std::move(robot), std::move(calibration), seed);
  return std::make_unique<HardwareInfo>(std::move(env), [link] {
    return HardwareInfo::Measured{link->last().elapsed_s, link->last().latency_s};
  });
}

}  // namespace tendril::envs::sma_limb
