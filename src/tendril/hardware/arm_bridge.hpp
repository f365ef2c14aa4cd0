#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/hardware/framed_link.hpp"
#include "tendril/hardware/latency_stats.hpp"
#include "tendril/hardware/messages.hpp"
#include "tendril/hardware/safety_log.hpp"
#include "tendril/physics/twins/pneumatic/chambers.hpp"

namespace tendril::hardware {

// What the host bridge enforces between a learner and the pneumatic arm's lab (read from the
// `bridge:` map of PneumaticArm/Robot-v0; docs/hardware.md).
struct ArmBridgeSettings {
  std::string robot = "pneumatic-arm";
  double max_bar = -1.0;  // host limit per chamber; < 0: the regulators' ceiling
  bool clamp = true;      // above it or below 0: clamp (logged) or refuse (Error)
  // Commands closer together than 1 / max_rate_hz (wall clock) wait, logged; 0: no limit
  // (each step waits for its capture samples anyway).
  double max_rate_hz = 0.0;
  double ack_timeout_s = 0.2;
  int command_retries = 2;
  double frame_timeout_s = 0.5;  // no motion-capture frame for this long: stale
  int frozen_frames = 50;        // identical marker positions this often in a row (0: off)
  double max_latency_s = 0.05;
  int reconnect_attempts = 3;
  double reconnect_wait_s = 0.2;
  double handshake_timeout_s = 1.0;
  std::string log_file;

  static ArmBridgeSettings from(const Config& bridge);
};

struct ArmBridgeSample {
  double time_s = 0.0;  // the capture's time stamp, since the trial began
  physics::pneumatic::TipPositions tips_m = physics::pneumatic::TipPositions::Zero();
  physics::pneumatic::ChamberVector pressures_bar = physics::pneumatic::ChamberVector::Zero();
  uint32_t sample = 0;
  int frames_missed = 0;
  double latency_s = 0.0;
  double elapsed_s = 0.0;
};

// The host side of the pneumatic arm's two devices: the regulators' command channel and the
// motion-capture stream. A command holds for `samples_per_step` capture samples; the step
// returns the capture frame (and pressure report) that ends them. Limits, rate limit,
// retransmission, staleness and frozen-capture checks, emergency stop (vent and latch) and
// reconnection as LimbBridge; every safety action is logged with its cause.
class ArmBridge {
 public:
  using Clock = std::chrono::steady_clock;

  ArmBridge(std::unique_ptr<Transport> commands, std::unique_ptr<Transport> mocap,
            ArmBridgeSettings settings, int samples_per_step);

  const Identity& identity() const { return identity_; }
  double max_bar() const { return max_bar_; }
  ArmBridgeSample reset(std::optional<uint64_t> seed);
  ArmBridgeSample command(const physics::pneumatic::ChamberVector& bar);
  void safe_command(const std::string& cause);  // vent: all pressures 0
  void emergency_stop(const std::string& cause);
  void clear_emergency_stop();
  double ping();

  SafetyLog& log() { return log_; }
  const LatencyStats& latency() const { return latency_; }

 private:
  void handshake();
  [[noreturn]] void fail(const std::string& action, const std::string& cause);
  [[noreturn]] void lost_link(const std::string& cause);
  void handle_other(const Frame& frame);
  // Waits for the capture frame and pressure report of `sample`; Error when stale.
  ArmBridgeSample await_sample(uint32_t sample, Clock::time_point deadline);

  ArmBridgeSettings settings_;
  int samples_per_step_;
  FramedLink commands_;
  FramedLink mocap_;
  std::string name_;
  Identity identity_;
  SafetyLog log_;
  LatencyStats latency_;
  double max_bar_ = 1.5;
  uint16_t epoch_seq_ = kNoSeq;
  bool in_trial_ = false;
  bool needs_reset_ = false;
  bool estopped_ = false;
  uint32_t sample_ = 0;  // the newest sample returned
  uint32_t last_frame_ = 0;
  int identical_ = 0;
  physics::pneumatic::TipPositions last_tips_ = physics::pneumatic::TipPositions::Zero();
  std::vector<uint16_t> acks_;
  uint16_t refused_seq_ = kNoSeq;
  uint8_t refused_reason_ = 0;
  Clock::time_point epoch_wall_{};
  Clock::time_point last_command_{};
  // Frames already received, by sample (the two devices' streams interleave).
  std::vector<std::pair<uint32_t, MocapFrame>> frames_;
  std::vector<std::pair<uint32_t, PressureReport>> reports_;
};

}  // namespace tendril::hardware
