#pragma once

#include <memory>
#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/hardware/arm_bridge.hpp"

namespace tendril::envs::pneumatic {

// PneumaticArm/Robot-v0 with `backend: bridge`: the arm of RobotEnv's comment — same action
// and observation spaces, same info keys — reached through the lab's two devices
// (hardware::ArmBridge: the regulators' command channel and the motion-capture stream) instead
// of the twin; plus "elapsed_s" (wall-clock time since reset) and "latency_s" (the step's
// command round trip) in info.
//
// Params: control_period_s, observe_pressures as RobotEnv; `bridge:` the ArmBridgeSettings
// keys and the links: udp_host, udp_port (the regulators' command channel), mocap_port (the
// local port the capture streams to), optional faults / mocap_faults maps.
class BridgeRobotEnv : public Env {
 public:
  static std::unique_ptr<Env> create(const Config& params);

  BridgeRobotEnv(std::unique_ptr<hardware::ArmBridge> bridge, bool observe_pressures);

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;

  hardware::ArmBridge& bridge() { return *bridge_; }

 private:
  Observation observe(const hardware::ArmBridgeSample& sample) const;

  std::unique_ptr<hardware::ArmBridge> bridge_;
  bool observe_pressures_;
  Space observation_space_, action_space_;
  Info info_;
};

}  // namespace tendril::envs::pneumatic
