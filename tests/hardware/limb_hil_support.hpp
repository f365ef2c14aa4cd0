#pragma once

// Hardware-in-the-loop fixtures: the SMA limb's firmware (TENDRIL_FIRMWARE_ELF, built by the
// tendril_firmware target) in its simavr emulator, bridges to it over the pseudo-terminal, and
// waypoint tracking on the limb env (twin or bridge) through the policy runner.

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>

#include "tendril/control/tracking_policy.hpp"
#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/envs/runner/policy_runner.hpp"
#include "tendril/hardware/limb_bridge.hpp"
#include "tendril/hardware/link_faults.hpp"
#include "tendril/hardware/serial_transport.hpp"
#include "tendril/hardware/simavr/limb_emulator.hpp"

namespace tendril::hardware::testing {

inline LimbEmulatorSettings emulator_settings(double host_wait_s = 30.0) {
  LimbEmulatorSettings settings;
  settings.firmware = TENDRIL_FIRMWARE_ELF;
  settings.spec = physics::SmaLimbSpec::stiff();
  settings.pace = EmulatorPace::kLockstep;
  settings.host_wait_s = host_wait_s;
  return settings;
}

// A bridge on the emulator's port, with `faults` (if given) between them.
inline std::unique_ptr<LimbBridge> bridge_to(const LimbEmulator& emulator,
                                             std::shared_ptr<LinkFaults> faults = nullptr,
                                             LimbBridgeSettings settings = {}) {
  std::unique_ptr<Transport> link = std::make_unique<SerialTransport>(emulator.port(), 115200);
  if (faults) link = std::make_unique<FaultyTransport>(std::move(link), faults, 11);
  return std::make_unique<LimbBridge>(std::move(link), settings);
}

// SmaLimb/Robot-v0 over the bridge, on the nominal table and raw readings, as the twin it is
// compared with.
inline Config bridge_env_params(const std::string& port, const std::string& extra = "") {
  return Config::parse("calibration: none\nbackend: bridge\nbridge:\n  port: " + port + "\n" +
                       extra);
}

// Waypoint tracking on SmaLimb/Robot-v0 (readings θx, θy, t) on the raw readings: the rates are
// the finite difference of the last two (StateFilter with α = 1), as the thesis' hardware node
// estimated them.
inline control::TrackingPolicy raw_reading_tracking(
    const Env& limb, std::shared_ptr<control::TrackingController> controller,
    const Eigen::Matrix2Xd& path) {
  return control::TrackingPolicy(limb, std::move(controller), control::WaypointFollower(path),
                                 control::StateFilter(1.0));
}

// The info of a run's last step.
class LastInfo final : public envs::RunObserver {
 public:
  void on_step(const envs::StepView& step) override { info = step.result.info; }
  Info info;
};

}  // namespace tendril::hardware::testing
