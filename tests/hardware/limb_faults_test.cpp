// Faults between the host and the limb's real firmware (simavr), each with its specified
// reaction (docs/hardware.md, "Faults") and nothing lost: every fault is either absorbed
// without changing a number, or answered by a safe command, a clear Error and a log entry.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <thread>

#include "limb_hil_support.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/sma_limb/twin_limb_robot.hpp"
#include "tendril/hardware/framed_link.hpp"

namespace tendril::hardware {
namespace {

using testing::bridge_to;
using testing::emulator_settings;

// A fixed throttle-like drive: alternating coils at duties the limb responds to.
std::array<int, 4> drive(int step) {
  const int duty = 22 + (step * 7) % 15;
  switch ((step / 6) % 4) {
    case 0:
      return {duty, 0, 0, 0};
    case 1:
      return {0, 0, duty, 0};
    case 2:
      return {0, duty, 0, 0};
    default:
      return {0, 0, 0, duty};
  }
}

std::vector<LimbBridgeSample> twin_run(int steps) {
  envs::sma_limb::TwinLimbRobot twin(physics::SmaLimbSpec::stiff());
  std::vector<LimbBridgeSample> out;
  auto first = twin.reset(9);
  out.push_back({first.time_s, first.angles_deg});
  for (int k = 0; k < steps; ++k) {
    const auto s = twin.command(drive(k));
    out.push_back({s.time_s, s.angles_deg});
  }
  return out;
}

bool coils_off(const LimbEmulator& emulator) { return emulator.pwm() == std::array<int, 4>{}; }

// Waits (up to 2 s of wall time) for the running emulator's coils to be off.
bool coils_go_off(const LimbEmulator& emulator) {
  for (int i = 0; i < 200 && !coils_off(emulator); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return coils_off(emulator);
}

TEST(LimbFaults, LatencyAndJitterAreMeasuredAndChangeNoNumber) {
  const auto expected = twin_run(30);
  LimbEmulator emulator(emulator_settings());
  emulator.start();
  auto faults = std::make_shared<LinkFaults>();
  faults->latency_s = 0.015;
  faults->jitter_s = 0.010;
  auto bridge = bridge_to(emulator, faults);
  auto first = bridge->reset(9);
  EXPECT_EQ(first.angles_deg, expected[0].angles_deg);
  for (int k = 0; k < 30; ++k) {
    const LimbBridgeSample s = bridge->command(drive(k));
    ASSERT_EQ(s.time_s, expected[k + 1].time_s) << k;
    ASSERT_EQ(s.angles_deg, expected[k + 1].angles_deg) << k;
    // The round trip carries the injected delay of the COMMAND_ACK (15–25 ms).
    EXPECT_GE(s.latency_s, 0.015) << k;
    EXPECT_LT(s.latency_s, 0.025 + 0.050) << k;  // 50 ms for a loaded machine
  }
  emulator.stop();
  EXPECT_EQ(bridge->latency().count(), 30);
  EXPECT_GE(bridge->latency().jitter(), 0.0005);  // the 10 ms uniform spread shows
  EXPECT_EQ(bridge->log().count("reading_lost"), 0);
}

TEST(LimbFaults, LostAndCorruptedCommandsAreResentAndTheRunStaysExact) {
  const auto expected = twin_run(30);
  LimbEmulator emulator(emulator_settings());
  emulator.start();
  auto faults = std::make_shared<LinkFaults>();
  auto bridge = bridge_to(emulator, faults);
  bridge->reset(9);
  for (int k = 0; k < 30; ++k) {
    if (k == 5) faults->drop_next_sent = 1;
    if (k == 12) faults->corrupt_next_sent = 1;
    const LimbBridgeSample s = bridge->command(drive(k));
    ASSERT_EQ(s.time_s, expected[k + 1].time_s) << k;
    ASSERT_EQ(s.angles_deg, expected[k + 1].angles_deg) << k;
  }
  emulator.stop();
  EXPECT_EQ(faults->dropped_sent, 1);
  EXPECT_EQ(faults->corrupted_sent, 1);
  EXPECT_EQ(bridge->log().count("command_resent"), 2);
  // The firmware caught the corrupted frame by its checksum and said so.
  EXPECT_EQ(bridge->log().count("firmware_frame_error"), 1);
}

TEST(LimbFaults, LostAndCorruptedReadingsAreCountedNeverReplayed) {
  LimbEmulator emulator(emulator_settings(/*host_wait_s=*/0.05));
  emulator.start();
  auto faults = std::make_shared<LinkFaults>();
  auto bridge = bridge_to(emulator, faults);
  bridge->reset(9);
  uint32_t index = 0;
  int missed = 0, gaps = 0;
  for (int k = 0; k < 20; ++k) {
    // The next two frames from the robot are the command's ACK and the reading after it.
    if (k == 4) faults->drop_next_received = 2;
    if (k == 11) faults->corrupt_next_received = 2;
    const LimbBridgeSample s = bridge->command(drive(k));
    EXPECT_EQ(s.index, index + 1 + s.readings_missed) << k;
    index = s.index;
    missed += s.readings_missed;
    gaps += s.readings_missed > 0 ? 1 : 0;
  }
  emulator.stop();
  EXPECT_EQ(faults->dropped_received, 2);
  EXPECT_EQ(faults->corrupted_received, 2);
  // Each lost reading shows as a gap in the firmware's reading index, logged once per gap.
  EXPECT_GE(missed, 2);
  EXPECT_EQ(bridge->log().count("reading_lost"), gaps);
  EXPECT_GE(bridge->link().parser().counters().checksum_errors, 1u);
}

TEST(LimbFaults, AFrozenSensorStopsTheCoilsWithAClearError) {
  LimbEmulator emulator(emulator_settings());
  emulator.start();
  LimbBridgeSettings settings;
  settings.frozen_readings = 8;
  auto bridge = bridge_to(emulator, nullptr, settings);
  bridge->reset(9);
  for (int k = 0; k < 5; ++k) bridge->command({30, 0, 0, 0});
  emulator.freeze_sensor(true);
  int steps = 0;
  try {
    for (; steps < 20; ++steps) bridge->command({30, 0, 0, 0});
    FAIL() << "a frozen sensor went unnoticed";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("frozen"), std::string::npos) << error.what();
  }
  EXPECT_LE(steps, 8);
  EXPECT_EQ(bridge->log().count("frozen_sensor"), 1);
  EXPECT_EQ(bridge->log().count("safe_command"), 1);
  EXPECT_TRUE(coils_go_off(emulator));
  emulator.stop();
}

TEST(LimbFaults, ASilentSensorIsStaleNeverAStepOnOldData) {
  LimbEmulator emulator(emulator_settings());
  emulator.start();
  LimbBridgeSettings settings;
  settings.reading_timeout_s = 0.3;
  auto bridge = bridge_to(emulator, nullptr, settings);
  bridge->reset(9);
  for (int k = 0; k < 3; ++k) bridge->command({30, 0, 0, 0});
  emulator.silence_sensor(true);
  EXPECT_THROW(bridge->command({30, 0, 0, 0}), Error);
  EXPECT_EQ(bridge->log().count("stale_sensor"), 1);
  EXPECT_TRUE(coils_go_off(emulator));
  emulator.stop();
}

TEST(LimbFaults, ADisconnectMidEpisodeReconnectsStopsTheCoilsAndDemandsAReset) {
  LimbEmulator emulator(emulator_settings());
  emulator.start();
  auto faults = std::make_shared<LinkFaults>();
  LimbBridgeSettings settings;
  settings.reconnect_wait_s = 0.05;
  auto bridge = bridge_to(emulator, faults, settings);
  bridge->reset(9);
  for (int k = 0; k < 5; ++k) bridge->command({30, 0, 0, 0});
  {
    std::lock_guard lock(faults->mutex);
    faults->disconnected = true;
    faults->failed_reopens = 1;  // the cable comes back on the second attempt
  }
  try {
    bridge->command({30, 0, 0, 0});
    FAIL() << "a lost link went unnoticed";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("must be reset"), std::string::npos) << error.what();
  }
  EXPECT_EQ(bridge->log().count("link_lost"), 1);
  EXPECT_EQ(bridge->log().count("reconnect"), 2);  // one failed attempt, one that worked
  EXPECT_EQ(faults->refused_reopens, 1);
  EXPECT_THROW(bridge->command({30, 0, 0, 0}), Error);  // no stepping on without a reset
  const LimbBridgeSample first = bridge->reset(10);
  EXPECT_EQ(first.time_s, 0.0);
  const LimbBridgeSample next = bridge->command({0, 0, 30, 0});
  EXPECT_GT(next.time_s, 0.05);
  emulator.stop();
}

TEST(LimbFaults, OutOfLimitCommandsAreClampedOrRefusedAsConfigured) {
  LimbEmulator emulator(emulator_settings());
  emulator.start();
  LimbBridgeSettings clamp;
  clamp.max_pwm = 30;
  auto bridge = bridge_to(emulator, nullptr, clamp);
  bridge->reset(9);
  const LimbBridgeSample s = bridge->command({50, 0, 0, 0});
  EXPECT_EQ(s.pwm[0], 30);  // what the firmware drove during the step
  EXPECT_EQ(bridge->log().count("clamp"), 1);
  // Both coils of a pair: refused on the host, never sent.
  EXPECT_THROW(bridge->command({20, 20, 0, 0}), Error);
  EXPECT_EQ(bridge->log().count("refuse"), 1);
  bridge.reset();

  LimbBridgeSettings refuse;
  refuse.max_pwm = 30;
  refuse.clamp = false;
  auto strict = bridge_to(emulator, nullptr, refuse);
  strict->reset(9);
  strict->command({25, 0, 0, 0});
  EXPECT_THROW(strict->command({31, 0, 0, 0}), Error);
  EXPECT_EQ(strict->log().count("refuse"), 1);
  EXPECT_EQ(strict->log().count("safe_command"), 1);
  EXPECT_EQ(strict->max_pwm(), 30);
  strict.reset();

  // Past the host: a raw frame above the firmware's own limit (128) is refused by the robot,
  // which switches its coils off and says why.
  FramedLink raw(std::make_unique<SerialTransport>(emulator.port(), 115200));
  raw.send(MessageType::kPwmCommand, PwmCommand{{40, 0, 0, 0}}.encode());
  const uint16_t seq = raw.send(MessageType::kPwmCommand, PwmCommand{{200, 0, 0, 0}}.encode());
  bool refused = false;
  const auto deadline = FramedLink::Clock::now() + std::chrono::seconds(2);
  while (auto frame = raw.next(deadline)) {
    if (frame->type != static_cast<uint8_t>(MessageType::kRefused)) continue;
    const Refused r = Refused::decode(frame->payload);
    EXPECT_EQ(r.seq, seq);
    EXPECT_EQ(r.reason, static_cast<uint8_t>(RefuseReason::kLimit));
    refused = true;
    break;
  }
  EXPECT_TRUE(refused);
  EXPECT_TRUE(coils_go_off(emulator));
  emulator.stop();
}

TEST(LimbFaults, TheEmergencyStopHoldsTheCoilsOffUntilCleared) {
  LimbEmulator emulator(emulator_settings());
  emulator.start();
  auto bridge = bridge_to(emulator);
  bridge->reset(9);
  bridge->command({35, 0, 0, 0});
  bridge->emergency_stop("operator");
  EXPECT_THROW(bridge->command({35, 0, 0, 0}), Error);
  EXPECT_TRUE(coils_go_off(emulator));
  bridge->clear_emergency_stop();
  const LimbBridgeSample s = bridge->command({0, 0, 35, 0});
  EXPECT_EQ(s.pwm[2], 35);
  emulator.stop();
  EXPECT_EQ(bridge->log().count("estop"), 1);
}

// The host process dies with the coils on: the firmware's watchdog (250 ms) switches them off.
TEST(LimbFaults, TheFirmwareWatchdogSwitchesTheCoilsOffWhenTheHostIsKilled) {
  LimbEmulator emulator(emulator_settings(/*host_wait_s=*/0.05));
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t host = fork();
  ASSERT_GE(host, 0);
  if (host == 0) {
    // The host: drive +x at 60 until killed.
    close(ready[0]);
    try {
      auto bridge = std::make_unique<LimbBridge>(
          std::make_unique<SerialTransport>(emulator.port(), 115200), LimbBridgeSettings{});
      bridge->reset(9);
      for (int k = 0;; ++k) {
        bridge->command({60, 0, 0, 0});
        if (k == 5) {
          const char byte = 1;
          if (write(ready[1], &byte, 1) != 1) _exit(2);
        }
      }
    } catch (...) {
      _exit(3);
    }
  }
  close(ready[1]);
  // Run the robot until the host has driven the coil for a few readings.
  bool host_ready = false;
  ASSERT_TRUE(emulator.run_until(
      [&] {
        pollfd p{ready[0], POLLIN, 0};
        host_ready = poll(&p, 1, 0) > 0;
        return host_ready;
      },
      20.0));
  ASSERT_EQ(emulator.pwm()[0], 60);
  kill(host, SIGKILL);
  waitpid(host, nullptr, 0);
  close(ready[0]);
  const double killed_at = emulator.time_s();
  ASSERT_TRUE(emulator.run_until([&] { return coils_off(emulator); }, 5.0));
  const double last_command = emulator.last_host_frame_s();
  double off_at = -1.0;
  for (const auto& change : emulator.pwm_history()) {
    if (change.time_s >= last_command && change.pwm == std::array<int, 4>{}) {
      off_at = change.time_s;
      break;
    }
  }
  ASSERT_GE(off_at, 0.0);
  // Within T = 250 ms of the last command's arrival at the port: + 1.5 ms for its 18 bytes to
  // cross the 115200-baud line, + 1 ms of the firmware's tick, + 0.1 ms of pin sampling.
  EXPECT_LE(off_at - last_command, 0.250 + 0.0015 + 0.001 + 0.0001);
  EXPECT_GE(off_at - last_command, 0.250);
  EXPECT_GE(off_at, killed_at - 0.25);
}

}  // namespace
}  // namespace tendril::hardware
