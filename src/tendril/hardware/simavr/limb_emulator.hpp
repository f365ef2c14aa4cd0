#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "tendril/hardware/emulator_pace.hpp"
#include "tendril/physics/twins/sma/sma_limb_spec.hpp"

namespace tendril::hardware {

struct LimbEmulatorSettings {
  std::filesystem::path firmware;  // the firmware's ELF (build/firmware/sma_limb.elf)
  std::string link;                // a symlink to the pseudo-terminal (empty: none)
  physics::SmaLimbSpec spec = physics::SmaLimbSpec::stiff();
  uint64_t seed = 0;  // the twin's until the host's first RESET
  EmulatorPace pace = EmulatorPace::kLockstep;
  double host_wait_s = 5.0;
};

// Hardware-in-the-loop without hardware: the limb's real firmware (its ELF, unchanged) runs on
// simavr's ATmega328P at 16 MHz; its serial port is a pseudo-terminal that a bridge opens like
// /dev/ttyACM0; its PWM outputs drive the SMA twin and the twin's readings come back through an
// emulated bend sensor on I2C with its data-ready line.
//
// Coupling (docs/hardware.md): the sensor raises data-ready when the twin's next reading is due
// (the twin's own 55–75 ms clock, counted in AVR cycles from the epoch's first reading); the
// twin integrates each sensor interval with the duties the firmware drives when the interval
// ends — so the command sent after a reading, if it arrives within the interval, acts for the
// whole interval, exactly as in the direct twin path (which has no wire); a later command acts
// from the next interval on. The host's RESET frame, seen on the wire, rebuilds the twin with
// its seed (coil wear kept), as TwinLimbRobot::reset does.
class LimbEmulator {
 public:
  explicit LimbEmulator(LimbEmulatorSettings settings);
  ~LimbEmulator();
  LimbEmulator(const LimbEmulator&) = delete;
  LimbEmulator& operator=(const LimbEmulator&) = delete;

  // The pseudo-terminal's path (/dev/pts/N) — what a bridge opens.
  const std::string& port() const;

  // Runs the emulation on a thread of its own until stop() (or destruction).
  void start();
  void stop();
  // Runs it in the calling thread until `done()` holds (checked every millisecond of robot
  // time) or `wall_timeout_s` passed; returns whether `done()` held.
  bool run_until(const std::function<bool()>& done, double wall_timeout_s);

  struct PwmChange {
    double time_s;  // robot time since boot
    std::array<int, 4> pwm;
  };
  // Thread-safe views.
  double time_s() const;                       // robot time since boot
  std::array<int, 4> pwm() const;              // duties driven now
  std::vector<PwmChange> pwm_history() const;  // every change (sampled every 100 µs)
  double last_host_frame_s() const;            // robot time the host's last frame arrived
  int readings() const;                        // readings served since boot
  int host_frames() const;

  // Sensor faults: frozen (readings keep coming, values stuck), silent (no more readings).
  void freeze_sensor(bool frozen);
  void silence_sensor(bool silent);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
};

}  // namespace tendril::hardware
