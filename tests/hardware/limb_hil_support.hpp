#pragma once

// Hardware-in-the-loop fixtures: the SMA limb's firmware (TENDRIL_FIRMWARE_ELF, built by the
// tendril_firmware target) in its simavr emulator, and bridges to it over the pseudo-terminal.

#include <memory>
#include <string>

#include "tendril/core/config.hpp"
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

}  // namespace tendril::hardware::testing
