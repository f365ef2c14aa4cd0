#include "tendril/hardware/limb_bridge.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

namespace tendril::hardware {

namespace {

double seconds(LimbBridge::Clock::duration d) { return std::chrono::duration<double>(d).count(); }

LimbBridge::Clock::duration span_of(double s) {
  return std::chrono::duration_cast<LimbBridge::Clock::duration>(std::chrono::duration<double>(s));
}

std::string pwm_text(const std::array<int, 4>& pwm) {
  return std::to_string(pwm[0]) + "/" + std::to_string(pwm[1]) + "/" + std::to_string(pwm[2]) +
         "/" + std::to_string(pwm[3]);
}

}  // namespace

LimbBridgeSettings LimbBridgeSettings::from(const Config& bridge, const std::string& where) {
  LimbBridgeSettings s;
  s.robot = bridge.get_or<std::string>("robot", s.robot);
  s.max_pwm = bridge.get_or<int>("max_pwm", s.max_pwm);
  const std::string on_limit = bridge.get_or<std::string>("on_limit", "clamp");
  if (on_limit != "clamp" && on_limit != "refuse") {
    throw Error("on_limit must be clamp or refuse, got '" + on_limit + "'",
                bridge.where("on_limit"));
  }
  s.clamp = on_limit == "clamp";
  s.max_rate_hz = bridge.get_or<double>("max_rate_hz", s.max_rate_hz);
  s.ack_timeout_s = bridge.get_or<double>("ack_timeout_s", s.ack_timeout_s);
  s.command_retries = bridge.get_or<int>("command_retries", s.command_retries);
  s.reading_timeout_s = bridge.get_or<double>("reading_timeout_s", s.reading_timeout_s);
  s.frozen_readings = bridge.get_or<int>("frozen_readings", s.frozen_readings);
  s.max_latency_s = bridge.get_or<double>("max_latency_s", s.max_latency_s);
  s.reconnect_attempts = bridge.get_or<int>("reconnect_attempts", s.reconnect_attempts);
  s.reconnect_wait_s = bridge.get_or<double>("reconnect_wait_s", s.reconnect_wait_s);
  s.handshake_timeout_s = bridge.get_or<double>("handshake_timeout_s", s.handshake_timeout_s);
  s.log_file = bridge.get_or<std::string>("log", s.log_file);
  const auto positive = [&](double value, const char* key) {
    if (!(std::isfinite(value) && value > 0.0)) {
      throw Error(std::string(key) + " must be positive, got " + std::to_string(value),
                  bridge.where(key));
    }
  };
  require(std::isfinite(s.max_rate_hz) && s.max_rate_hz >= 0.0, "max_rate_hz must be >= 0",
          bridge.where("max_rate_hz"));
  positive(s.ack_timeout_s, "ack_timeout_s");
  positive(s.reading_timeout_s, "reading_timeout_s");
  positive(s.max_latency_s, "max_latency_s");
  positive(s.reconnect_wait_s, "reconnect_wait_s");
  positive(s.handshake_timeout_s, "handshake_timeout_s");
  require(s.max_pwm == -1 || (s.max_pwm >= 0 && s.max_pwm <= 255),
          "max_pwm must be -1 (the firmware's) or 0–255", bridge.where("max_pwm"));
  require(s.command_retries >= 0 && s.reconnect_attempts >= 0 && s.frozen_readings >= 0,
          "command_retries, reconnect_attempts and frozen_readings must be >= 0", where);
  return s;
}

LimbBridge::LimbBridge(std::unique_ptr<Transport> transport, LimbBridgeSettings settings)
    : settings_(std::move(settings)), link_(std::move(transport)) {
  port_name_ = link_.transport().name();
  if (!settings_.log_file.empty()) log_.write_to(settings_.log_file);
  handshake();
}

void LimbBridge::handshake() {
  // HELLO again every 200 ms: a board that resets when its port opens (the Uno's DTR) misses
  // what arrives before its firmware runs.
  const auto deadline = Clock::now() + span_of(settings_.handshake_timeout_s);
  auto next_hello = Clock::now();
  for (;;) {
    if (Clock::now() >= next_hello) {
      link_.send(MessageType::kHello);
      next_hello = Clock::now() + std::chrono::milliseconds(200);
    }
    if (Clock::now() >= deadline) break;
    auto frame = link_.next(std::min(deadline, next_hello));
    if (!frame || frame->type != static_cast<uint8_t>(MessageType::kIdentity)) continue;
    Identity identity = Identity::decode(frame->payload);
    if (identity.robot != settings_.robot) {
      throw Error(
          "the robot on this port is '" + identity.robot + "', expected '" + settings_.robot + "'",
          port_name_);
    }
    if (identity.protocol != Frame::kVersion) {
      throw Error("the robot speaks wire protocol " + std::to_string(identity.protocol) +
                      ", this host " + std::to_string(Frame::kVersion),
                  port_name_);
    }
    const auto resolution = identity.limit("resolution_mdeg");
    const auto max_pwm = identity.limit("max_pwm");
    if (!resolution || *resolution <= 0 || !max_pwm) {
      throw Error("the robot's identity lacks resolution_mdeg or max_pwm", port_name_);
    }
    resolution_deg_ = *resolution / 1000.0;  // exact: counts · (r / 1000) as the sensor rounds
    max_pwm_ = *max_pwm;
    if (settings_.max_pwm >= 0) max_pwm_ = std::min(max_pwm_, settings_.max_pwm);
    watchdog_ms_ = identity.limit("watchdog_ms").value_or(0);
    identity_ = std::move(identity);
    return;
  }
  throw LinkDown("no IDENTITY within " + std::to_string(settings_.handshake_timeout_s) +
                     " s of HELLO (is the robot's firmware running and the baud rate right?)",
                 port_name_);
}

void LimbBridge::fail(const std::string& action, const std::string& cause) {
  log_.record(action, cause);
  safe_command(action);
  throw Error(cause, port_name_);
}

void LimbBridge::lost_link(const std::string& cause) {
  log_.record("link_lost", cause);
  in_epoch_ = false;
  needs_reset_ = true;
  for (int attempt = 1; attempt <= settings_.reconnect_attempts; ++attempt) {
    std::this_thread::sleep_for(span_of(settings_.reconnect_wait_s));
    try {
      link_.reopen();
      handshake();
      log_.record("reconnect", "attempt " + std::to_string(attempt) + " succeeded");
      safe_command("reconnected mid-episode");
      throw Error("the link was lost mid-episode (" + cause +
                      "); it is back, the coils are off, and the episode must be reset",
                  port_name_);
    } catch (const LinkDown& again) {
      log_.record("reconnect",
                  "attempt " + std::to_string(attempt) + " failed: " + again.what_wrong());
    }
  }
  throw LinkDown("the link was lost (" + cause + ") and did not come back after " +
                     std::to_string(settings_.reconnect_attempts) +
                     " attempts; the robot's watchdog switches its coils off after " +
                     std::to_string(watchdog_ms_) + " ms",
                 port_name_);
}

void LimbBridge::safe_command(const std::string& cause) {
  log_.record("safe_command", "all coils off: " + cause);
  try {
    link_.send(MessageType::kPwmCommand, PwmCommand{}.encode());
  } catch (const LinkDown&) {
    // The robot's watchdog turns the coils off when nothing arrives.
  }
}

void LimbBridge::emergency_stop(const std::string& cause) {
  log_.record("estop", cause);
  estopped_ = true;
  try {
    link_.send(MessageType::kEstop);
  } catch (const LinkDown&) {
    log_.record("estop", "link down: the robot's watchdog switches the coils off");
  }
}

void LimbBridge::clear_emergency_stop() {
  link_.send(MessageType::kClear);
  estopped_ = false;
  log_.record("estop_cleared", "by the host");
}

double LimbBridge::ping() {
  return link_.ping(
      settings_.handshake_timeout_s, [this](const Frame& frame) { handle_other(frame); },
      port_name_);
}

void LimbBridge::handle_other(const Frame& frame) {
  switch (static_cast<MessageType>(frame.type)) {
    case MessageType::kStatus: {
      const Status status = Status::decode(frame.payload);
      switch (static_cast<StatusCode>(status.code)) {
        case StatusCode::kWatchdog:
          log_.record("firmware_watchdog", "no valid command for " + std::to_string(status.detail) +
                                               " ms: the robot switched its coils off");
          break;
        case StatusCode::kFrameError:
          log_.record("firmware_frame_error", "the robot dropped a bad frame (" +
                                                  std::to_string(status.detail) + " so far)");
          break;
        case StatusCode::kSensorFault:
          log_.record("firmware_sensor_fault", "the robot cannot read its sensor; coils off");
          break;
        case StatusCode::kBoot:
          log_.record("firmware_boot", "the robot restarted; coils off");
          in_epoch_ = false;
          break;
        default:
          break;
      }
      break;
    }
    case MessageType::kRefused: {
      const Refused refused = Refused::decode(frame.payload);
      log_.record("firmware_refused", std::string("command #") + std::to_string(refused.seq) +
                                          ": " + refuse_name(refused.reason) +
                                          "; the robot switched its coils off");
      refused_seq_ = refused.seq;
      refused_reason_ = refused.reason;
      break;
    }
    default:
      break;
  }
}

LimbBridgeSample LimbBridge::sample_of(const LimbReading& reading, const Frame& frame) {
  LimbBridgeSample sample;
  sample.time_s = 1e-3 * static_cast<double>(frame.stamp_ms);
  sample.angles_deg =
      Eigen::Vector2d(reading.counts[0] * resolution_deg_, reading.counts[1] * resolution_deg_);
  for (int i = 0; i < 4; ++i) sample.pwm[i] = reading.pwm[i];
  sample.flags = reading.flags;
  sample.index = reading.index;
  sample.elapsed_s = seconds(Clock::now() - epoch_wall_);
  if (reading.index > last_index_ + 1) {
    sample.readings_missed = static_cast<int>(reading.index - last_index_ - 1);
    log_.record("reading_lost", std::to_string(sample.readings_missed) +
                                    " reading(s) lost on the wire before reading #" +
                                    std::to_string(reading.index));
  }
  last_index_ = reading.index;
  if (reading.counts == last_counts_) {
    ++identical_;
  } else {
    identical_ = 0;
    last_counts_ = reading.counts;
  }
  if (settings_.frozen_readings > 0 && identical_ + 1 >= settings_.frozen_readings) {
    fail("frozen_sensor", "the sensor is frozen: " + std::to_string(identical_ + 1) +
                              " identical readings in a row");
  }
  return sample;
}

LimbBridgeSample LimbBridge::reset(uint64_t seed) {
  try {
    if (!in_epoch_ && needs_reset_) log_.record("reset", "new episode after a fault");
    ResetRequest request{seed};
    const uint16_t seq = link_.send(MessageType::kReset, request.encode());
    const auto deadline =
        Clock::now() + span_of(settings_.reading_timeout_s + settings_.handshake_timeout_s);
    while (auto frame = link_.next(deadline)) {
      if (frame->type != static_cast<uint8_t>(MessageType::kLimbReading)) {
        handle_other(*frame);
        continue;
      }
      const LimbReading reading = LimbReading::decode(frame->payload);
      if (reading.reset_seq != seq || reading.index != 0) continue;  // an older epoch's
      epoch_seq_ = seq;
      in_epoch_ = true;
      needs_reset_ = false;
      epoch_wall_ = Clock::now();
      last_index_ = 0;
      identical_ = 0;
      last_counts_ = reading.counts;
      acks_.clear();
      LimbBridgeSample sample = sample_of(reading, *frame);
      sample.elapsed_s = 0.0;
      return sample;
    }
  } catch (const LinkDown& down) {
    lost_link(down.what_wrong());
  }
  fail("stale_sensor",
       "no first reading within " + std::to_string(settings_.reading_timeout_s) + " s of RESET");
}

std::array<int, 4> LimbBridge::limit(const std::array<int, 4>& pwm) {
  for (int i = 0; i < 4; ++i) {
    if (pwm[i] < 0 || pwm[i] > 255) {
      fail("refuse", "PWM " + pwm_text(pwm) + " outside 0–255");
    }
  }
  if ((pwm[0] > 0 && pwm[1] > 0) || (pwm[2] > 0 && pwm[3] > 0)) {
    fail("refuse", "PWM " + pwm_text(pwm) + " drives both coils of an antagonistic pair");
  }
  std::array<int, 4> limited = pwm;
  for (int& duty : limited) duty = std::min(duty, max_pwm_);
  if (limited != pwm) {
    if (!settings_.clamp) {
      fail("refuse", "PWM " + pwm_text(pwm) + " above the limit " + std::to_string(max_pwm_));
    }
    log_.record("clamp", "PWM " + pwm_text(pwm) + " clamped to " + pwm_text(limited) + " (limit " +
                             std::to_string(max_pwm_) + ")");
  }
  return limited;
}

LimbBridgeSample LimbBridge::command(const std::array<int, 4>& pwm) {
  if (estopped_) throw Error("the emergency stop is active; clear it first", port_name_);
  if (!in_epoch_) {
    throw Error(needs_reset_ ? "the episode was interrupted by a fault; reset the robot first"
                             : "reset the robot before commanding it",
                port_name_);
  }
  const std::array<int, 4> limited = limit(pwm);
  const auto min_gap = span_of(settings_.max_rate_hz > 0.0 ? 1.0 / settings_.max_rate_hz : 0.0);
  const auto now = Clock::now();
  if (settings_.max_rate_hz > 0.0 && last_command_ != Clock::time_point{} &&
      now - last_command_ < min_gap) {
    log_.record("rate_limit", "command " + std::to_string(1e3 * seconds(now - last_command_)) +
                                  " ms after the previous one; held back");
    std::this_thread::sleep_until(last_command_ + min_gap);
  }
  PwmCommand message;
  for (int i = 0; i < 4; ++i) message.pwm[i] = static_cast<uint8_t>(limited[i]);
  try {
    acks_.clear();
    auto sent = Clock::now();
    last_command_ = sent;
    acks_.push_back(link_.send(MessageType::kPwmCommand, message.encode()));
    const auto reading_deadline = sent + span_of(settings_.reading_timeout_s);
    bool acked = false;
    double latency = 0.0;
    int retries = 0;
    auto ack_deadline = sent + span_of(settings_.ack_timeout_s);
    for (;;) {
      const auto deadline = acked ? reading_deadline : std::min(ack_deadline, reading_deadline);
      auto frame = link_.next(deadline);
      if (!frame) {
        if (Clock::now() >= reading_deadline) {
          fail("stale_sensor", "no new reading within " +
                                   std::to_string(settings_.reading_timeout_s) +
                                   " s of a command: sensor or link stalled");
        }
        if (retries >= settings_.command_retries) {
          ack_deadline = reading_deadline;
          continue;
        }
        ++retries;
        log_.record("command_resent", "no acknowledgement of PWM " + pwm_text(limited) +
                                          " within " + std::to_string(settings_.ack_timeout_s) +
                                          " s");
        sent = Clock::now();
        acks_.push_back(link_.send(MessageType::kPwmCommand, message.encode()));
        ack_deadline = sent + span_of(settings_.ack_timeout_s);
        continue;
      }
      const auto type = static_cast<MessageType>(frame->type);
      if (type == MessageType::kCommandAck) {
        const uint16_t seq = CommandAck::decode(frame->payload).seq;
        if (!acked && std::find(acks_.begin(), acks_.end(), seq) != acks_.end()) {
          acked = true;
          latency = seconds(Clock::now() - sent);
          latency_.add(latency);
          if (latency > settings_.max_latency_s) {
            log_.record("latency", "command round trip " + std::to_string(1e3 * latency) +
                                       " ms above " +
                                       std::to_string(1e3 * settings_.max_latency_s) + " ms");
          }
        }
        continue;
      }
      if (type != MessageType::kLimbReading) {
        handle_other(*frame);
        if (std::find(acks_.begin(), acks_.end(), refused_seq_) != acks_.end()) {
          const uint8_t reason = refused_reason_;
          refused_seq_ = kNoSeq;
          fail("refuse", std::string("the robot refused PWM ") + pwm_text(limited) + ": " +
                             refuse_name(reason));
        }
        if (!in_epoch_) {
          needs_reset_ = true;
          fail("firmware_boot", "the robot restarted mid-episode");
        }
        continue;
      }
      const LimbReading reading = LimbReading::decode(frame->payload);
      if (reading.reset_seq != epoch_seq_ || reading.index <= last_index_) continue;
      LimbBridgeSample sample = sample_of(reading, *frame);
      // A reading taken before the command reached the robot says nothing about the command:
      // wait for the next (the step then spans more than one sensor period).
      if (std::find(acks_.begin(), acks_.end(), reading.acked_seq) == acks_.end()) {
        log_.record("command_late", "reading #" + std::to_string(reading.index) +
                                        " was taken before PWM " + pwm_text(limited) +
                                        " reached the robot; waiting for the next");
        continue;
      }
      sample.command_acked = acked;
      sample.latency_s = latency;
      return sample;
    }
  } catch (const LinkDown& down) {
    lost_link(down.what_wrong());
  }
}

}  // namespace tendril::hardware
