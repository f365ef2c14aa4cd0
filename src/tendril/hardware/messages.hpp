#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace tendril::hardware {

// The message types of wire protocol version 1 and their payloads (docs/protocol.md). Each
// payload type encodes to bytes and decodes from them; decode raises Error on a payload of the
// wrong size.
enum class MessageType : uint8_t {
  // host → robot
  kHello = 0x01,
  kReset = 0x02,
  kPwmCommand = 0x03,
  kEstop = 0x04,
  kPing = 0x05,
  kClear = 0x06,
  kPressureCommand = 0x07,
  // robot → host
  kIdentity = 0x81,
  kLimbReading = 0x82,
  kStatus = 0x83,
  kRefused = 0x84,
  kPong = 0x85,
  kMocapFrame = 0x86,
  kPressureReport = 0x87,
  kCommandAck = 0x88,
};

const char* message_name(uint8_t type);

inline constexpr uint16_t kNoSeq = 0xFFFF;  // "no frame" in a sequence-number field

// The handshake's answer: which robot, which firmware, and its limits (integers with their
// units in the key: "max_pwm", "watchdog_ms", "cutoff_mdeg", …).
struct Identity {
  std::string robot;
  std::array<int, 3> firmware{0, 0, 0};
  int protocol = 0;
  std::vector<std::pair<std::string, int32_t>> limits;

  std::optional<int32_t> limit(const std::string& key) const;
  std::string firmware_version() const;  // "1.0.0"
  std::vector<uint8_t> encode() const;
  static Identity decode(std::span<const uint8_t> payload);
};

// RESET: begin an episode. The seed only matters to a simulated robot (the emulators rebuild
// their twin with it; without one the twin's random streams continue); firmware ignores it.
struct ResetRequest {
  std::optional<uint64_t> seed;
  std::vector<uint8_t> encode() const;
  static ResetRequest decode(std::span<const uint8_t> payload);
};

// PWM_COMMAND: the limb's four coil duties (0–255 of 11.1 V; +x, −x, +y, −y).
struct PwmCommand {
  std::array<uint8_t, 4> pwm{0, 0, 0, 0};
  std::vector<uint8_t> encode() const;
  static PwmCommand decode(std::span<const uint8_t> payload);
};

// LIMB_READING: one bend-sensor reading (frame stamp = its time, ms since the epoch began).
struct LimbReading {
  static constexpr uint8_t kCutoff = 0x01, kWatchdog = 0x02, kEstop = 0x04, kSensorFault = 0x08;
  uint16_t reset_seq = kNoSeq;             // the host's RESET frame that began this epoch
  uint32_t index = 0;                      // 0 for the epoch's first reading
  uint16_t acked_seq = kNoSeq;             // the last PWM_COMMAND applied
  std::array<int16_t, 2> counts{0, 0};     // θx, θy in sensor counts (identity: resolution_mdeg)
  std::array<uint8_t, 4> pwm{0, 0, 0, 0};  // driven when the reading was sent
  uint8_t flags = 0;
  std::vector<uint8_t> encode() const;
  static LimbReading decode(std::span<const uint8_t> payload);
};

enum class StatusCode : uint8_t {
  kBoot = 1,
  kWatchdog = 2,
  kEstop = 3,
  kCleared = 4,
  kFrameError = 5,
  kSensorFault = 6,
  kReset = 7,
};
const char* status_name(uint8_t code);

struct Status {
  uint8_t code = 0;
  uint16_t detail = 0;
  uint16_t frame_errors = 0;  // the robot's count of bad frames received
  std::vector<uint8_t> encode() const;
  static Status decode(std::span<const uint8_t> payload);
};

enum class RefuseReason : uint8_t { kLength = 1, kPair = 2, kLimit = 3, kEstop = 4, kUnknown = 5 };
const char* refuse_name(uint8_t reason);

struct Refused {
  uint16_t seq = 0;
  uint8_t reason = 0;
  std::vector<uint8_t> encode() const;
  static Refused decode(std::span<const uint8_t> payload);
};

struct Pong {
  uint16_t ping_seq = 0;
  std::vector<uint8_t> encode() const;
  static Pong decode(std::span<const uint8_t> payload);
};

// COMMAND_ACK: a command was applied (PWM_COMMAND or PRESSURE_COMMAND, by its seq).
struct CommandAck {
  uint16_t seq = 0;
  std::vector<uint8_t> encode() const;
  static CommandAck decode(std::span<const uint8_t> payload);
};

// PRESSURE_COMMAND: the pneumatic arm's nine chamber pressures, bar (chamber 3 m + c).
struct PressureCommand {
  Eigen::Matrix<double, 9, 1> bar = Eigen::Matrix<double, 9, 1>::Zero();
  std::vector<uint8_t> encode() const;
  static PressureCommand decode(std::span<const uint8_t> payload);
};

// PRESSURE_REPORT: what the regulators measure after a sample (100 Hz).
struct PressureReport {
  uint16_t reset_seq = kNoSeq;
  uint16_t acked_seq = kNoSeq;  // the newest PRESSURE_COMMAND in force
  uint32_t sample = 0;          // motion-capture sample number since the trial began
  Eigen::Matrix<double, 9, 1> bar = Eigen::Matrix<double, 9, 1>::Zero();
  std::vector<uint8_t> encode() const;
  static PressureReport decode(std::span<const uint8_t> payload);
};

// MOCAP_FRAME: one motion-capture sample, the markers' positions (m, robot frame), in the
// manner of a Vicon or OptiTrack stream: frame number, time stamp, marker list.
struct MocapFrame {
  uint16_t reset_seq = kNoSeq;
  uint32_t sample = 0;
  double time_s = 0.0;  // since the trial began
  std::vector<Eigen::Vector3d> markers;
  std::vector<uint8_t> encode() const;
  static MocapFrame decode(std::span<const uint8_t> payload);
};

}  // namespace tendril::hardware
