#pragma once

#include <Eigen/Core>
#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/hardware/framed_link.hpp"
#include "tendril/hardware/latency_stats.hpp"
#include "tendril/hardware/messages.hpp"
#include "tendril/hardware/safety_log.hpp"

namespace tendril::hardware {

// What the host bridge enforces between a learner and the SMA limb's firmware
// (docs/hardware.md, "Safety"). Read from the `bridge:` map of SmaLimb/Robot-v0.
struct LimbBridgeSettings {
  std::string robot = "sma-limb";  // the identity the handshake must report
  int max_pwm = -1;                // host limit per coil; -1: the firmware's max_pwm
  bool clamp = true;               // above max_pwm: clamp (logged) or refuse (Error)
  // Commands closer together than 1 / max_rate_hz (wall clock) wait, logged; 0: no limit
  // (the sensor paces the limb anyway: one command per reading).
  double max_rate_hz = 0.0;
  double ack_timeout_s = 0.1;  // no COMMAND_ACK by then: the command is sent again
  int command_retries = 2;
  double reading_timeout_s = 0.5;  // no new reading by then: stale — safe command and Error
  int frozen_readings = 25;        // this many identical readings in a row: frozen (0: off)
  double max_latency_s = 0.05;     // a slower command round trip is logged
  int reconnect_attempts = 3;
  double reconnect_wait_s = 0.2;
  double handshake_timeout_s = 1.0;
  std::string log_file;  // the safety log's CSV file; empty: kept in memory only

  static LimbBridgeSettings from(const Config& bridge, const std::string& where);
};

// One reading through the bridge, with what the bridge measured on the way.
struct LimbBridgeSample {
  double time_s = 0.0;                                   // the firmware's stamp, since reset
  Eigen::Vector2d angles_deg = Eigen::Vector2d::Zero();  // raw, as the sensor reports them
  std::array<int, 4> pwm{0, 0, 0, 0};                    // driven when the reading was sent
  uint8_t flags = 0;                                     // LimbReading::kCutoff, …
  uint32_t index = 0;
  int readings_missed = 0;  // lost on the wire before this one
  bool command_acked = true;
  double latency_s = 0.0;  // the command's round trip (send → COMMAND_ACK)
  double elapsed_s = 0.0;  // wall-clock time since reset
};

// The host side of the SMA limb's link (wire protocol v1): handshake, reset, one command per
// reading, with command limits, a rate limit, retransmission of unacknowledged commands, a
// staleness and a frozen-sensor check, an emergency stop and reconnection. Every safety action
// goes to the SafetyLog with its cause; the bridge never returns old data as new: a stale
// sensor, a refused command or a lost link raise Error after the coils were commanded off.
class LimbBridge {
 public:
  using Clock = std::chrono::steady_clock;

  // Connects and shakes hands (HELLO → IDENTITY); Error if the robot is not `settings.robot`,
  // speaks another protocol version, or does not answer.
  LimbBridge(std::unique_ptr<Transport> transport, LimbBridgeSettings settings);

  const Identity& identity() const { return identity_; }
  double resolution_deg() const { return resolution_deg_; }
  int max_pwm() const { return max_pwm_; }

  // Coils off, a new epoch on the robot; returns its first reading (time 0).
  LimbBridgeSample reset(uint64_t seed);
  // Drives the coils with `pwm` (+x, −x, +y, −y) until the next reading and returns it.
  LimbBridgeSample command(const std::array<int, 4>& pwm);
  // All coils off (best effort, logged with `cause`).
  void safe_command(const std::string& cause);
  // Latches the robot's emergency stop: coils off until clear_emergency_stop().
  void emergency_stop(const std::string& cause);
  void clear_emergency_stop();
  bool emergency_stopped() const { return estopped_; }
  // One PING's round trip (s); Error if no PONG within the handshake timeout.
  double ping();

  SafetyLog& log() { return log_; }
  const LatencyStats& latency() const { return latency_; }
  const FramedLink& link() const { return link_; }
  const std::string& port_name() const { return port_name_; }

 private:
  void handshake();
  [[noreturn]] void lost_link(const std::string& cause);
  [[noreturn]] void fail(const std::string& action, const std::string& cause);
  std::array<int, 4> limit(const std::array<int, 4>& pwm);
  void handle_other(const Frame& frame);
  LimbBridgeSample sample_of(const LimbReading& reading, const Frame& frame);

  LimbBridgeSettings settings_;
  FramedLink link_;
  std::string port_name_;
  Identity identity_;
  SafetyLog log_;
  LatencyStats latency_;
  double resolution_deg_ = 0.1;
  int max_pwm_ = 255;
  int32_t watchdog_ms_ = 0;
  uint16_t epoch_seq_ = kNoSeq;
  bool in_epoch_ = false;
  uint32_t last_index_ = 0;
  std::array<int16_t, 2> last_counts_{0, 0};
  int identical_ = 0;
  bool estopped_ = false;
  bool needs_reset_ = false;
  uint16_t refused_seq_ = kNoSeq;
  uint8_t refused_reason_ = 0;
  std::vector<uint16_t> acks_;
  Clock::time_point epoch_wall_{};
  Clock::time_point last_command_{};
};

}  // namespace tendril::hardware
