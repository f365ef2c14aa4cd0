#include "tendril/hardware/arm_bridge.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

namespace tendril::hardware {

namespace {

using physics::pneumatic::ChamberVector;
using physics::pneumatic::kChambers;
using physics::pneumatic::kModules;

double seconds(ArmBridge::Clock::duration d) { return std::chrono::duration<double>(d).count(); }

ArmBridge::Clock::duration span_of(double s) {
  return std::chrono::duration_cast<ArmBridge::Clock::duration>(std::chrono::duration<double>(s));
}

}  // namespace

ArmBridgeSettings ArmBridgeSettings::from(const Config& bridge) {
  ArmBridgeSettings s;
  s.robot = bridge.get_or<std::string>("robot", s.robot);
  s.max_bar = bridge.get_or<double>("max_bar", s.max_bar);
  const std::string on_limit = bridge.get_or<std::string>("on_limit", "clamp");
  if (on_limit != "clamp" && on_limit != "refuse") {
    throw Error("on_limit must be clamp or refuse, got '" + on_limit + "'",
                bridge.where("on_limit"));
  }
  s.clamp = on_limit == "clamp";
  s.max_rate_hz = bridge.get_or<double>("max_rate_hz", s.max_rate_hz);
  s.ack_timeout_s = bridge.get_or<double>("ack_timeout_s", s.ack_timeout_s);
  s.command_retries = bridge.get_or<int>("command_retries", s.command_retries);
  s.frame_timeout_s = bridge.get_or<double>("frame_timeout_s", s.frame_timeout_s);
  s.frozen_frames = bridge.get_or<int>("frozen_frames", 0);
  s.max_latency_s = bridge.get_or<double>("max_latency_s", s.max_latency_s);
  s.reconnect_attempts = bridge.get_or<int>("reconnect_attempts", s.reconnect_attempts);
  s.reconnect_wait_s = bridge.get_or<double>("reconnect_wait_s", s.reconnect_wait_s);
  s.handshake_timeout_s = bridge.get_or<double>("handshake_timeout_s", s.handshake_timeout_s);
  s.log_file = bridge.get_or<std::string>("log", s.log_file);
  require(std::isfinite(s.max_rate_hz) && s.max_rate_hz >= 0.0, "max_rate_hz must be >= 0",
          bridge.where("max_rate_hz"));
  const std::pair<const char*, double> positive[] = {
      {"ack_timeout_s", s.ack_timeout_s},
      {"frame_timeout_s", s.frame_timeout_s},
      {"max_latency_s", s.max_latency_s},
      {"reconnect_wait_s", s.reconnect_wait_s},
      {"handshake_timeout_s", s.handshake_timeout_s}};
  for (const auto& [key, value] : positive) {
    require(std::isfinite(value) && value > 0.0, "must be positive", bridge.where(key));
  }
  require(s.command_retries >= 0 && s.reconnect_attempts >= 0 && s.frozen_frames >= 0,
          "command_retries, reconnect_attempts and frozen_frames must be >= 0",
          bridge.where("command_retries"));
  return s;
}

ArmBridge::ArmBridge(std::unique_ptr<Transport> commands, std::unique_ptr<Transport> mocap,
                     ArmBridgeSettings settings, int samples_per_step)
    : settings_(std::move(settings)),
      samples_per_step_(samples_per_step),
      commands_(std::move(commands)),
      mocap_(std::move(mocap)) {
  require(samples_per_step_ >= 1, "a step must hold at least one capture sample", "ArmBridge");
  name_ = commands_.transport().name();
  if (!settings_.log_file.empty()) log_.write_to(settings_.log_file);
  handshake();
}

void ArmBridge::handshake() {
  // HELLO again every 200 ms: UDP loses datagrams, and the lab's side may start after us.
  const auto deadline = Clock::now() + span_of(settings_.handshake_timeout_s);
  auto next_hello = Clock::now();
  for (;;) {
    if (Clock::now() >= next_hello) {
      commands_.send(MessageType::kHello);
      next_hello = Clock::now() + std::chrono::milliseconds(200);
    }
    if (Clock::now() >= deadline) break;
    auto frame = commands_.next(std::min(deadline, next_hello));
    if (!frame || frame->type != static_cast<uint8_t>(MessageType::kIdentity)) continue;
    Identity identity = Identity::decode(frame->payload);
    if (identity.robot != settings_.robot) {
      throw Error("the robot at this address is '" + identity.robot + "', expected '" +
                      settings_.robot + "'",
                  name_);
    }
    if (identity.protocol != Frame::kVersion) {
      throw Error("the robot speaks wire protocol " + std::to_string(identity.protocol), name_);
    }
    const auto ceiling = identity.limit("ceiling_mbar");
    if (!ceiling || identity.limit("chambers").value_or(0) != kChambers ||
        identity.limit("markers").value_or(0) != kModules) {
      throw Error(
          "the robot's identity lacks ceiling_mbar or has other than 9 chambers and 3 "
          "markers",
          name_);
    }
    max_bar_ = *ceiling / 1000.0;
    if (settings_.max_bar >= 0.0) max_bar_ = std::min(max_bar_, settings_.max_bar);
    identity_ = std::move(identity);
    return;
  }
  throw LinkDown("no IDENTITY within " + std::to_string(settings_.handshake_timeout_s) +
                     " s of HELLO (is the lab's emulator or gateway running?)",
                 name_);
}

void ArmBridge::fail(const std::string& action, const std::string& cause) {
  log_.record(action, cause);
  safe_command(action);
  throw Error(cause, name_);
}

void ArmBridge::safe_command(const std::string& cause) {
  log_.record("safe_command", "all chambers vented: " + cause);
  try {
    commands_.send(MessageType::kPressureCommand, PressureCommand{}.encode());
  } catch (const LinkDown&) {
  }
}

void ArmBridge::emergency_stop(const std::string& cause) {
  log_.record("estop", cause);
  estopped_ = true;
  try {
    commands_.send(MessageType::kEstop);
  } catch (const LinkDown&) {
    log_.record("estop", "link down: the ESTOP did not go out");
  }
}

void ArmBridge::clear_emergency_stop() {
  commands_.send(MessageType::kClear);
  estopped_ = false;
  log_.record("estop_cleared", "by the host");
}

double ArmBridge::ping() {
  return commands_.ping(
      settings_.handshake_timeout_s, [this](const Frame& frame) { handle_other(frame); }, name_);
}

void ArmBridge::lost_link(const std::string& cause) {
  log_.record("link_lost", cause);
  in_trial_ = false;
  needs_reset_ = true;
  for (int attempt = 1; attempt <= settings_.reconnect_attempts; ++attempt) {
    std::this_thread::sleep_for(span_of(settings_.reconnect_wait_s));
    try {
      commands_.reopen();
      mocap_.reopen();
      handshake();
      log_.record("reconnect", "attempt " + std::to_string(attempt) + " succeeded");
      safe_command("reconnected mid-trial");
      throw Error("the link was lost mid-trial (" + cause +
                      "); it is back, the chambers are vented, and the trial must be reset",
                  name_);
    } catch (const LinkDown& again) {
      log_.record("reconnect",
                  "attempt " + std::to_string(attempt) + " failed: " + again.what_wrong());
    }
  }
  throw LinkDown("the link was lost (" + cause + ") and did not come back after " +
                     std::to_string(settings_.reconnect_attempts) + " attempts",
                 name_);
}

void ArmBridge::handle_other(const Frame& frame) {
  switch (static_cast<MessageType>(frame.type)) {
    case MessageType::kPressureReport: {
      PressureReport report = PressureReport::decode(frame.payload);
      if (report.reset_seq == epoch_seq_) reports_.emplace_back(report.sample, report);
      break;
    }
    case MessageType::kRefused: {
      const Refused refused = Refused::decode(frame.payload);
      log_.record("robot_refused",
                  "command #" + std::to_string(refused.seq) + ": " + refuse_name(refused.reason));
      refused_seq_ = refused.seq;
      refused_reason_ = refused.reason;
      break;
    }
    default:
      break;
  }
}

ArmBridgeSample ArmBridge::await_sample(uint32_t sample, Clock::time_point deadline) {
  // Any capture frame at or after `sample` will do (a lost one is replaced by the next).
  for (;;) {
    std::optional<MocapFrame> found;
    for (auto& [number, frame] : frames_) {
      if (number >= sample) {
        found = frame;
        break;
      }
    }
    if (found) {
      // The regulators report each sample on their own channel: wait briefly for its report.
      const auto report_deadline = std::min(deadline, Clock::now() + std::chrono::milliseconds(50));
      auto has_report = [&] {
        return std::any_of(reports_.begin(), reports_.end(),
                           [&](const auto& r) { return r.first == found->sample; });
      };
      while (!has_report()) {
        auto frame = commands_.next(report_deadline);
        if (!frame) break;
        handle_other(*frame);
      }
      ArmBridgeSample out;
      out.sample = found->sample;
      out.time_s = found->time_s;
      for (int m = 0; m < kModules; ++m) out.tips_m.col(m) = found->markers[m];
      const PressureReport* report = nullptr;
      for (const auto& [number, r] : reports_) {
        if (number <= found->sample) report = &r;
      }
      if (report != nullptr) {
        out.pressures_bar = report->bar;
        if (report->sample != found->sample) {
          log_.record("report_lost", "no pressure report of sample " +
                                         std::to_string(found->sample) + "; sample " +
                                         std::to_string(report->sample) + "'s used");
        }
      }
      out.elapsed_s = seconds(Clock::now() - epoch_wall_);
      std::erase_if(frames_, [&](const auto& f) { return f.first <= found->sample; });
      std::erase_if(reports_, [&](const auto& r) { return r.first < found->sample; });
      if (found->sample > sample) {
        out.frames_missed = static_cast<int>(found->sample - sample);
        log_.record("frame_lost", "capture frame " + std::to_string(sample) + " lost; frame " +
                                      std::to_string(found->sample) + " used");
      }
      const bool same = out.tips_m == last_tips_;
      identical_ = same ? identical_ + static_cast<int>(found->sample - sample_) : 0;
      last_tips_ = out.tips_m;
      sample_ = found->sample;
      if (settings_.frozen_frames > 0 && identical_ >= settings_.frozen_frames) {
        fail("frozen_sensor", "the motion capture is frozen: markers identical for " +
                                  std::to_string(identical_) + " frames");
      }
      return out;
    }
    // Wait on both devices; the capture stream carries the sample.
    const auto now = Clock::now();
    if (now >= deadline) {
      fail("stale_sensor", "no motion-capture frame of sample " + std::to_string(sample) +
                               " within " + std::to_string(settings_.frame_timeout_s) + " s");
    }
    const auto slice = std::min(deadline, now + std::chrono::milliseconds(2));
    if (auto frame = mocap_.next(slice)) {
      if (frame->type == static_cast<uint8_t>(MessageType::kMocapFrame)) {
        MocapFrame mocap = MocapFrame::decode(frame->payload);
        if (mocap.reset_seq == epoch_seq_ && mocap.markers.size() == kModules) {
          if (!frames_.empty() && mocap.sample > frames_.back().first + 1) {
            log_.record("frame_lost", std::to_string(mocap.sample - frames_.back().first - 1) +
                                          " capture frame(s) lost before " +
                                          std::to_string(mocap.sample));
          }
          frames_.emplace_back(mocap.sample, std::move(mocap));
        }
      }
    }
    while (auto frame = commands_.next(Clock::now())) handle_other(*frame);
  }
}

ArmBridgeSample ArmBridge::reset(std::optional<uint64_t> seed) {
  try {
    const uint16_t seq = commands_.send(MessageType::kReset, ResetRequest{seed}.encode());
    epoch_seq_ = seq;
    frames_.clear();
    reports_.clear();
    epoch_wall_ = Clock::now();
    sample_ = 0;
    identical_ = 0;
    last_tips_.setConstant(std::nan(""));
    ArmBridgeSample first = await_sample(
        0, Clock::now() + span_of(settings_.frame_timeout_s + settings_.handshake_timeout_s));
    first.elapsed_s = 0.0;
    in_trial_ = true;
    needs_reset_ = false;
    return first;
  } catch (const LinkDown& down) {
    lost_link(down.what_wrong());
  }
}

ArmBridgeSample ArmBridge::command(const ChamberVector& bar) {
  if (estopped_) throw Error("the emergency stop is active; clear it first", name_);
  if (!in_trial_) {
    throw Error(needs_reset_ ? "the trial was interrupted by a fault; reset the arm first"
                             : "reset the arm before commanding it",
                name_);
  }
  if (!bar.allFinite()) fail("refuse", "a pressure command is not finite");
  ChamberVector limited = bar.cwiseMax(0.0).cwiseMin(max_bar_);
  if (limited != bar) {
    if (!settings_.clamp) {
      fail("refuse", "pressure command outside [0, " + std::to_string(max_bar_) + "] bar");
    }
    log_.record("clamp", "pressure command clamped to [0, " + std::to_string(max_bar_) + "] bar");
  }
  const auto min_gap = span_of(settings_.max_rate_hz > 0.0 ? 1.0 / settings_.max_rate_hz : 0.0);
  if (settings_.max_rate_hz > 0.0 && last_command_ != Clock::time_point{} &&
      Clock::now() - last_command_ < min_gap) {
    log_.record("rate_limit", "command " +
                                  std::to_string(1e3 * seconds(Clock::now() - last_command_)) +
                                  " ms after the previous one; held back");
    std::this_thread::sleep_until(last_command_ + min_gap);
  }
  PressureCommand message;
  message.bar = limited;
  try {
    acks_.clear();
    auto sent = Clock::now();
    last_command_ = sent;
    acks_.push_back(commands_.send(MessageType::kPressureCommand, message.encode()));
    double latency = 0.0;
    int retries = 0;
    auto ack_deadline = sent + span_of(settings_.ack_timeout_s);
    // The first pressure report under this command names the sample it began with.
    std::optional<uint32_t> first;
    while (!first) {
      auto frame = commands_.next(ack_deadline);
      if (!frame) {
        if (retries >= settings_.command_retries) {
          fail("stale_sensor", "the regulators did not acknowledge the command after " +
                                   std::to_string(retries + 1) + " tries");
        }
        ++retries;
        log_.record("command_resent",
                    "no acknowledgement within " + std::to_string(settings_.ack_timeout_s) + " s");
        sent = Clock::now();
        acks_.push_back(commands_.send(MessageType::kPressureCommand, message.encode()));
        ack_deadline = sent + span_of(settings_.ack_timeout_s);
        continue;
      }
      if (frame->type == static_cast<uint8_t>(MessageType::kCommandAck)) {
        if (std::find(acks_.begin(), acks_.end(), CommandAck::decode(frame->payload).seq) !=
                acks_.end() &&
            latency == 0.0) {
          latency = seconds(Clock::now() - sent);
          latency_.add(latency);
          if (latency > settings_.max_latency_s) {
            log_.record("latency", "command round trip " + std::to_string(1e3 * latency) +
                                       " ms above " +
                                       std::to_string(1e3 * settings_.max_latency_s) + " ms");
          }
          ack_deadline = Clock::now() + span_of(settings_.frame_timeout_s);
        }
        continue;
      }
      handle_other(*frame);
      if (std::find(acks_.begin(), acks_.end(), refused_seq_) != acks_.end()) {
        refused_seq_ = kNoSeq;
        fail("refuse",
             std::string("the regulators refused the command: ") + refuse_name(refused_reason_));
      }
      for (const auto& [number, report] : reports_) {
        if (std::find(acks_.begin(), acks_.end(), report.acked_seq) != acks_.end()) {
          first = number;
          break;
        }
      }
    }
    ArmBridgeSample out = await_sample(*first + samples_per_step_ - 1,
                                       Clock::now() + span_of(settings_.frame_timeout_s));
    out.latency_s = latency;
    return out;
  } catch (const LinkDown& down) {
    lost_link(down.what_wrong());
  }
}

}  // namespace tendril::hardware
