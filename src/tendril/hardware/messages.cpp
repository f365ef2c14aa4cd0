#include "tendril/hardware/messages.hpp"

#include "tendril/core/error.hpp"
#include "tendril/hardware/wire_bytes.hpp"

namespace tendril::hardware {

const char* message_name(uint8_t type) {
  switch (static_cast<MessageType>(type)) {
    case MessageType::kHello:
      return "HELLO";
    case MessageType::kReset:
      return "RESET";
    case MessageType::kPwmCommand:
      return "PWM_COMMAND";
    case MessageType::kEstop:
      return "ESTOP";
    case MessageType::kPing:
      return "PING";
    case MessageType::kClear:
      return "CLEAR";
    case MessageType::kPressureCommand:
      return "PRESSURE_COMMAND";
    case MessageType::kIdentity:
      return "IDENTITY";
    case MessageType::kLimbReading:
      return "LIMB_READING";
    case MessageType::kStatus:
      return "STATUS";
    case MessageType::kRefused:
      return "REFUSED";
    case MessageType::kPong:
      return "PONG";
    case MessageType::kMocapFrame:
      return "MOCAP_FRAME";
    case MessageType::kPressureReport:
      return "PRESSURE_REPORT";
    case MessageType::kCommandAck:
      return "COMMAND_ACK";
  }
  return "unknown";
}

const char* status_name(uint8_t code) {
  switch (static_cast<StatusCode>(code)) {
    case StatusCode::kBoot:
      return "boot";
    case StatusCode::kWatchdog:
      return "watchdog";
    case StatusCode::kEstop:
      return "estop";
    case StatusCode::kCleared:
      return "cleared";
    case StatusCode::kFrameError:
      return "frame_error";
    case StatusCode::kSensorFault:
      return "sensor_fault";
    case StatusCode::kReset:
      return "reset";
  }
  return "unknown";
}

const char* refuse_name(uint8_t reason) {
  switch (static_cast<RefuseReason>(reason)) {
    case RefuseReason::kLength:
      return "wrong payload length";
    case RefuseReason::kPair:
      return "both coils of a pair on";
    case RefuseReason::kLimit:
      return "duty above the firmware's max_pwm";
    case RefuseReason::kEstop:
      return "emergency stop active";
    case RefuseReason::kUnknown:
      return "unknown message type";
  }
  return "unknown reason";
}

std::optional<int32_t> Identity::limit(const std::string& key) const {
  for (const auto& [name, value] : limits) {
    if (name == key) return value;
  }
  return std::nullopt;
}

std::string Identity::firmware_version() const {
  return std::to_string(firmware[0]) + "." + std::to_string(firmware[1]) + "." +
         std::to_string(firmware[2]);
}

std::vector<uint8_t> Identity::encode() const {
  WireWriter out;
  out.text(robot);
  for (const int part : firmware) out.u8(static_cast<uint8_t>(part));
  out.u8(static_cast<uint8_t>(protocol));
  require(limits.size() <= 255, "too many limits", "Identity::encode");
  out.u8(static_cast<uint8_t>(limits.size()));
  for (const auto& [key, value] : limits) {
    out.text(key);
    out.i32(value);
  }
  return out.take();
}

Identity Identity::decode(std::span<const uint8_t> payload) {
  WireReader in(payload, "IDENTITY");
  Identity identity;
  identity.robot = in.text();
  for (int& part : identity.firmware) part = in.u8();
  identity.protocol = in.u8();
  const int count = in.u8();
  for (int i = 0; i < count; ++i) {
    std::string key = in.text();
    identity.limits.emplace_back(std::move(key), in.i32());
  }
  in.finish();
  return identity;
}

std::vector<uint8_t> ResetRequest::encode() const {
  WireWriter out;
  out.u8(seed ? 1 : 0);
  out.u64(seed.value_or(0));
  return out.take();
}

ResetRequest ResetRequest::decode(std::span<const uint8_t> payload) {
  WireReader in(payload, "RESET");
  ResetRequest reset;
  const uint8_t has_seed = in.u8();
  const uint64_t seed = in.u64();
  in.finish();
  if (has_seed > 1) throw Error("RESET's seed flag must be 0 or 1", "wire");
  if (has_seed) reset.seed = seed;
  return reset;
}

std::vector<uint8_t> PwmCommand::encode() const { return {pwm.begin(), pwm.end()}; }

PwmCommand PwmCommand::decode(std::span<const uint8_t> payload) {
  WireReader in(payload, "PWM_COMMAND");
  PwmCommand command;
  for (uint8_t& duty : command.pwm) duty = in.u8();
  in.finish();
  return command;
}

std::vector<uint8_t> LimbReading::encode() const {
  WireWriter out;
  out.u16(reset_seq);
  out.u32(index);
  out.u16(acked_seq);
  for (const int16_t count : counts) out.i16(count);
  for (const uint8_t duty : pwm) out.u8(duty);
  out.u8(flags);
  return out.take();
}

LimbReading LimbReading::decode(std::span<const uint8_t> payload) {
  WireReader in(payload, "LIMB_READING");
  LimbReading reading;
  reading.reset_seq = in.u16();
  reading.index = in.u32();
  reading.acked_seq = in.u16();
  for (int16_t& count : reading.counts) count = in.i16();
  for (uint8_t& duty : reading.pwm) duty = in.u8();
  reading.flags = in.u8();
  in.finish();
  return reading;
}

std::vector<uint8_t> Status::encode() const {
  WireWriter out;
  out.u8(code);
  out.u16(detail);
  out.u16(frame_errors);
  return out.take();
}

Status Status::decode(std::span<const uint8_t> payload) {
  WireReader in(payload, "STATUS");
  Status status;
  status.code = in.u8();
  status.detail = in.u16();
  status.frame_errors = in.u16();
  in.finish();
  return status;
}

std::vector<uint8_t> Refused::encode() const {
  WireWriter out;
  out.u16(seq);
  out.u8(reason);
  return out.take();
}

Refused Refused::decode(std::span<const uint8_t> payload) {
  WireReader in(payload, "REFUSED");
  Refused refused;
  refused.seq = in.u16();
  refused.reason = in.u8();
  in.finish();
  return refused;
}

std::vector<uint8_t> Pong::encode() const {
  WireWriter out;
  out.u16(ping_seq);
  return out.take();
}

Pong Pong::decode(std::span<const uint8_t> payload) {
  WireReader in(payload, "PONG");
  Pong pong;
  pong.ping_seq = in.u16();
  in.finish();
  return pong;
}

std::vector<uint8_t> CommandAck::encode() const {
  WireWriter out;
  out.u16(seq);
  return out.take();
}

CommandAck CommandAck::decode(std::span<const uint8_t> payload) {
  WireReader in(payload, "COMMAND_ACK");
  CommandAck ack;
  ack.seq = in.u16();
  in.finish();
  return ack;
}

std::vector<uint8_t> PressureCommand::encode() const {
  WireWriter out;
  for (int k = 0; k < 9; ++k) out.f64(bar[k]);
  return out.take();
}

PressureCommand PressureCommand::decode(std::span<const uint8_t> payload) {
  WireReader in(payload, "PRESSURE_COMMAND");
  PressureCommand command;
  for (int k = 0; k < 9; ++k) command.bar[k] = in.f64();
  in.finish();
  return command;
}

std::vector<uint8_t> PressureReport::encode() const {
  WireWriter out;
  out.u16(reset_seq);
  out.u16(acked_seq);
  out.u32(sample);
  for (int k = 0; k < 9; ++k) out.f64(bar[k]);
  return out.take();
}

PressureReport PressureReport::decode(std::span<const uint8_t> payload) {
  WireReader in(payload, "PRESSURE_REPORT");
  PressureReport report;
  report.reset_seq = in.u16();
  report.acked_seq = in.u16();
  report.sample = in.u32();
  for (int k = 0; k < 9; ++k) report.bar[k] = in.f64();
  in.finish();
  return report;
}

std::vector<uint8_t> MocapFrame::encode() const {
  WireWriter out;
  out.u16(reset_seq);
  out.u32(sample);
  out.f64(time_s);
  require(markers.size() <= 7, "at most 7 markers fit a frame", "MocapFrame::encode");
  out.u8(static_cast<uint8_t>(markers.size()));
  for (const Eigen::Vector3d& marker : markers) {
    for (int r = 0; r < 3; ++r) out.f64(marker[r]);
  }
  return out.take();
}

MocapFrame MocapFrame::decode(std::span<const uint8_t> payload) {
  WireReader in(payload, "MOCAP_FRAME");
  MocapFrame frame;
  frame.reset_seq = in.u16();
  frame.sample = in.u32();
  frame.time_s = in.f64();
  const int count = in.u8();
  for (int m = 0; m < count; ++m) {
    Eigen::Vector3d marker;
    for (int r = 0; r < 3; ++r) marker[r] = in.f64();
    frame.markers.push_back(marker);
  }
  in.finish();
  return frame;
}

}  // namespace tendril::hardware
