// `tendril robot`: the link to a real robot — run an emulator of one (the SMA limb's firmware
// in simavr on a pseudo-terminal, the pneumatic arm's lab on UDP), check a connection
// (handshake, round trips, sensor and control rates, limits). A policy runs on the robot with
// `tendril run` and the robot's `backend: bridge` (docs/hardware.md).
#include <atomic>
#include <csignal>
#include <cstdio>
#include <memory>
#include <string>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/pneumatic/arm_params.hpp"
#include "tendril/hardware/arm_bridge.hpp"
#include "tendril/hardware/arm_emulator.hpp"
#include "tendril/hardware/limb_bridge.hpp"
#include "tendril/hardware/link_check.hpp"
#include "tendril/hardware/serial_transport.hpp"
#include "tendril/hardware/transport_config.hpp"
#include "tendril/hardware/udp_transport.hpp"
#ifdef TENDRIL_WITH_SIMAVR
#include "tendril/hardware/simavr/limb_emulator.hpp"
#endif

namespace tendril::apps {

namespace {

std::atomic<bool> interrupted{false};

void on_signal(int) { interrupted = true; }

void catch_signals() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

}  // namespace

int robot_emulate_command(const Arguments& line) {
  const std::string robot = line.positional.front();
  const hardware::EmulatorPace pace = hardware::pace_from(line.value("pace", "realtime"), "--pace");
  catch_signals();
  if (robot == "limb") {
#ifdef TENDRIL_WITH_SIMAVR
    hardware::LimbEmulatorSettings settings;
    settings.firmware = line.value("firmware", TENDRIL_FIRMWARE_ELF);
    settings.link = line.value("link", "/tmp/tendril-limb");
    settings.spec = physics::SmaLimbSpec::variant(line.value("limb", "stiff"));
    settings.seed = line.unsigned_integer("seed", 0);
    settings.pace = pace;
    hardware::LimbEmulator emulator(settings);
    std::printf("SMA limb firmware %s in simavr; its serial port: %s (%s)\nCtrl-C stops it.\n",
                settings.firmware.c_str(), settings.link.c_str(), emulator.port().c_str());
    std::fflush(stdout);
    emulator.run_until([] { return interrupted.load(); }, 1e9);
    std::printf("stopped after %.3f s of robot time, %d readings, %d host frames\n",
                emulator.time_s(), emulator.readings(), emulator.host_frames());
    return 0;
#else
    throw Error("this build has no simavr (libsimavr-dev) or no avr-gcc", "tendril robot emulate");
#endif
  }
  require(robot == "arm", "expected `limb` or `arm`, got '" + robot + "'", "tendril robot emulate");
  hardware::ArmEmulatorSettings settings;
  // The twin's parameters as PneumaticArm/Robot-v0 takes them, from --set key=value.
  Config params = Config::parse("{}");
  for (const auto& [key, value] : line.overrides) params.set(key, value);
  settings.spec = envs::pneumatic::arm_spec_from(params);
  settings.command_port = static_cast<int>(line.integer("command-port", 51000, 1, 65535));
  settings.mocap_port = static_cast<int>(line.integer("mocap-port", 51001, 1, 65535));
  settings.pace = pace;
  hardware::ArmEmulator emulator(settings);
  std::printf(
      "pneumatic arm lab: regulators on udp 127.0.0.1:%d, motion capture streaming to "
      "127.0.0.1:%d\nCtrl-C stops it.\n",
      emulator.command_port(), settings.mocap_port);
  std::fflush(stdout);
  emulator.run_until([] { return interrupted.load(); }, 1e9);
  return 0;
}

int robot_check_command(const Arguments& line) {
  const int pings = static_cast<int>(line.integer("pings", 50, 0, 100000));
  const int steps = static_cast<int>(line.integer("steps", 100, 1, 1000000));
  hardware::LinkCheck result;
  if (line.positional.front() == "limb") {
    require(line.has("port"), "needs --port (the limb's serial device)", "tendril robot check");
    hardware::LimbBridge bridge(
        std::make_unique<hardware::SerialTransport>(
            line.value("port", ""), static_cast<int>(line.integer("baud", 115200, 1, 4000000))),
        {});
    result = hardware::check_limb(bridge, pings, steps);
  } else {
    require(line.positional.front() == "arm", "expected `limb` or `arm`", "tendril robot check");
    auto commands = std::make_unique<hardware::UdpTransport>(
        "127.0.0.1", 0, "127.0.0.1", static_cast<int>(line.integer("udp-port", 51000, 1, 65535)));
    auto mocap = std::make_unique<hardware::UdpTransport>(
        "127.0.0.1", static_cast<int>(line.integer("mocap-port", 51001, 1, 65535)), "", 0);
    hardware::ArmBridge bridge(std::move(commands), std::move(mocap), {}, 10);
    result = hardware::check_arm(bridge, pings, steps);
  }
  std::fputs(result.report().c_str(), stdout);
  return 0;
}

}  // namespace tendril::apps
