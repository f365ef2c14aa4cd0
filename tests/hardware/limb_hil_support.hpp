#pragma once

// Hardware-in-the-loop fixtures: the SMA limb's firmware (TENDRIL_FIRMWARE_ELF, built by the
// tendril_firmware target) in its simavr emulator, bridges to it over the pseudo-terminal, and
// the limb env (twin or bridge) as the tracking loop's limb.

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>

#include "tendril/control/tracking_loop.hpp"
#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
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

// SmaLimb/Robot-v0 (observation θx, θy, t) as the tracking loop's limb: the rates are the finite
// difference of the last two readings, as the thesis' hardware node estimated them. Each reset
// uses `seed`; `info()` is the last step's.
class EnvLimb final : public control::TrackedLimb {
 public:
  explicit EnvLimb(Env& env, uint64_t seed = 3) : env_(env), seed_(seed) {}
  control::LimbState reset() override { return state(env_.reset(seed_)); }
  control::LimbState apply(const Eigen::Vector2d& throttles) override {
    const Step step = env_.step(throttles.cast<float>());
    info_ = step.info;
    return state(step.observation);
  }
  const Info& info() const { return info_; }

 private:
  control::LimbState state(const Observation& o) {
    const Eigen::Vector2d angles(o[0], o[1]);
    const double dt = o[2] - time_;
    const Eigen::Vector2d rates =
        dt > 0 ? ((angles - angles_) / dt).eval() : Eigen::Vector2d::Zero();
    time_ = o[2];
    angles_ = angles;
    return {o[2], angles, rates};
  }
  Env& env_;
  uint64_t seed_;
  Info info_;
  double time_ = 0.0;
  Eigen::Vector2d angles_ = Eigen::Vector2d::Zero();
};

}  // namespace tendril::hardware::testing
