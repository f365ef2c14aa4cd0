#pragma once

#include <memory>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/envs/sma_limb/limb_calibration.hpp"
#include "tendril/envs/sma_limb/limb_robot.hpp"
#include "tendril/hardware/limb_bridge.hpp"

namespace tendril::envs::sma_limb {

// The LimbRobot interface over the host bridge to the limb's firmware (hardware::LimbBridge):
// a real limb on a serial port, or the firmware in its emulator. Readings are the firmware's,
// raw; the bridge's safety checks raise Error rather than return stale data.
class BridgeLimbRobot final : public LimbRobot {
 public:
  explicit BridgeLimbRobot(std::unique_ptr<hardware::LimbBridge> bridge);

  LimbSample reset(uint64_t seed) override;
  LimbSample command(const std::array<int, 4>& pwm) override;
  std::string description() const override;

  hardware::LimbBridge& bridge() { return *bridge_; }
  const hardware::LimbBridgeSample& last() const { return last_; }

 private:
  std::unique_ptr<hardware::LimbBridge> bridge_;
  hardware::LimbBridgeSample last_;
};

// SmaLimb/Robot-v0 with `backend: bridge`: the same environment over a BridgeLimbRobot, its
// info with "elapsed_s" (wall-clock time since reset) and "latency_s" (the step's command
// round trip) added. `bridge` is the env's `bridge:` map (hardware::open_transport,
// hardware::LimbBridgeSettings).
std::unique_ptr<Env> make_bridge_limb_env(const Config& bridge, LimbCalibration calibration,
                                          uint64_t seed);

}  // namespace tendril::envs::sma_limb
