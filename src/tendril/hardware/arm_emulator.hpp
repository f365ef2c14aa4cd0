#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "tendril/hardware/emulator_pace.hpp"
#include "tendril/physics/twins/pneumatic/pneumatic_arm_spec.hpp"

namespace tendril::hardware {

struct ArmEmulatorSettings {
  physics::pneumatic::PneumaticArmSpec spec;
  int command_port = 0;  // UDP port of the pressure-command channel (0: any free one)
  std::string mocap_host = "127.0.0.1";
  int mocap_port = 0;  // where the motion capture streams to (the host's port)
  EmulatorPace pace = EmulatorPace::kLockstep;
  int samples_per_command = 10;  // lockstep: robot time one command buys (10 × 10 ms)
  double host_wait_s = 5.0;
};

// The pneumatic arm's lab, as seed 002 §III had it, serving the twin (PneumaticArm) on
// loopback UDP as two devices:
// - the pressure regulators: a command channel (wire protocol v1) taking PRESSURE_COMMAND at
//   the controller's 10 Hz, answering COMMAND_ACK, and reporting the measured pressures of
//   every sample (PRESSURE_REPORT); HELLO, RESET (begins a trial with its seed), PING, ESTOP
//   (vent and latch) and CLEAR as for the limb;
// - the motion capture: a 100 Hz stream of MOCAP_FRAME datagrams (sample number, time stamp,
//   the three module-tip markers) to the host's port, as Vicon or OptiTrack stream.
// Each sample the newest command takes effect, the twin advances one sample period, and both
// devices report it.
class ArmEmulator {
 public:
  explicit ArmEmulator(ArmEmulatorSettings settings);
  ~ArmEmulator();
  ArmEmulator(const ArmEmulator&) = delete;
  ArmEmulator& operator=(const ArmEmulator&) = delete;

  int command_port() const;
  void start();
  void stop();
  bool run_until(const std::function<bool()>& done, double wall_timeout_s);

  int samples() const;  // since the trial began
  int commands() const;
  // Motion-capture faults: frozen (frames keep coming with stuck markers), silent (no frames).
  void freeze_capture(bool frozen);
  void silence_capture(bool silent);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
};

}  // namespace tendril::hardware
