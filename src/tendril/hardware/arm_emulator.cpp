#include "tendril/hardware/arm_emulator.hpp"

#include <chrono>
#include <cmath>
#include <mutex>

#include "tendril/core/error.hpp"
#include "tendril/hardware/framed_link.hpp"
#include "tendril/hardware/messages.hpp"
#include "tendril/hardware/udp_transport.hpp"
#include "tendril/physics/twins/pneumatic/pneumatic_arm.hpp"

namespace tendril::hardware {

namespace {

using physics::pneumatic::ChamberVector;
using physics::pneumatic::kModules;
using Clock = std::chrono::steady_clock;

constexpr const char* kRobot = "pneumatic-arm";

}  // namespace

EmulatorPace pace_from(const std::string& name, const std::string& where) {
  if (name == "lockstep") return EmulatorPace::kLockstep;
  if (name == "realtime") return EmulatorPace::kRealtime;
  throw Error("pace must be lockstep or realtime, got '" + name + "'", where);
}

struct ArmEmulator::Impl {
  ArmEmulatorSettings settings;
  physics::pneumatic::PneumaticArm arm;
  UdpTransport* commands_udp = nullptr;
  FramedLink commands;
  FramedLink mocap;
  uint16_t reset_seq = kNoSeq;
  uint16_t command_seq = kNoSeq;
  bool estopped = false;
  bool in_trial = false;
  int budget = 0;  // lockstep: samples left before the robot waits for its host
  Clock::time_point wait_began = Clock::now();
  Clock::time_point next_sample = Clock::now();
  physics::pneumatic::TipPositions frozen_tips;
  std::atomic<bool> frozen{false}, silent{false};
  mutable std::mutex mutex;
  int samples = 0, command_count = 0;

  Impl(ArmEmulatorSettings s, std::unique_ptr<UdpTransport> command_link,
       std::unique_ptr<UdpTransport> mocap_link)
      : settings(std::move(s)),
        arm(settings.spec),
        commands_udp(command_link.get()),
        commands(std::move(command_link)),
        mocap(std::move(mocap_link)) {}

  Identity identity() const {
    Identity id;
    id.robot = kRobot;
    id.firmware = {1, 0, 0};
    id.protocol = Frame::kVersion;
    id.limits = {{"chambers", physics::pneumatic::kChambers},
                 {"markers", kModules},
                 {"ceiling_mbar",
                  static_cast<int32_t>(std::lround(1000 * settings.spec.regulators.ceiling_bar))},
                 {"sample_period_us", static_cast<int32_t>(std::lround(1e6 * arm.sample_period()))},
                 {"command_rate_hz", 10}};
    return id;
  }

  void report() {
    PressureReport pressures;
    pressures.reset_seq = reset_seq;
    pressures.acked_seq = command_seq;
    pressures.sample = static_cast<uint32_t>(samples);
    pressures.bar = arm.pressures();
    const physics::pneumatic::TipPositions tips =
        frozen ? frozen_tips : arm.measured_tip_positions();
    if (!frozen) frozen_tips = tips;
    MocapFrame frame;
    frame.reset_seq = reset_seq;
    frame.sample = static_cast<uint32_t>(samples);
    frame.time_s = arm.time();
    for (int m = 0; m < kModules; ++m) frame.markers.push_back(tips.col(m));
    try {
      commands.send(MessageType::kPressureReport, pressures.encode());
    } catch (const LinkDown&) {
    }
    if (!silent) mocap.send(MessageType::kMocapFrame, frame.encode());
  }

  void handle(const Frame& frame) {
    auto reply = [&](MessageType type, const std::vector<uint8_t>& payload) {
      try {
        commands.send(type, payload);
      } catch (const LinkDown&) {
      }
    };
    switch (static_cast<MessageType>(frame.type)) {
      case MessageType::kHello:
        reply(MessageType::kIdentity, identity().encode());
        break;
      case MessageType::kReset: {
        std::optional<uint64_t> seed;
        try {
          seed = ResetRequest::decode(frame.payload).seed;
        } catch (const Error&) {
          reply(MessageType::kRefused, Refused{frame.seq, 1}.encode());
          break;
        }
        arm.set_commands(ChamberVector::Zero());
        arm.begin_trial(seed);
        reset_seq = frame.seq;
        command_seq = kNoSeq;
        samples = 0;
        in_trial = true;
        budget = 0;
        wait_began = Clock::now();
        next_sample = Clock::now() + std::chrono::milliseconds(10);
        reply(MessageType::kStatus, Status{7, frame.seq, 0}.encode());
        report();
        break;
      }
      case MessageType::kPressureCommand: {
        PressureCommand command;
        try {
          command = PressureCommand::decode(frame.payload);
        } catch (const Error&) {
          reply(MessageType::kRefused, Refused{frame.seq, 1}.encode());
          break;
        }
        if (estopped) {
          reply(MessageType::kRefused, Refused{frame.seq, 4}.encode());
          break;
        }
        if (!command.bar.allFinite()) {
          reply(MessageType::kRefused, Refused{frame.seq, 3}.encode());
          break;
        }
        arm.set_commands(command.bar);
        command_seq = frame.seq;
        budget = settings.samples_per_command;
        {
          std::lock_guard lock(mutex);
          ++command_count;
        }
        reply(MessageType::kCommandAck, CommandAck{frame.seq}.encode());
        break;
      }
      case MessageType::kEstop:
        estopped = true;
        arm.set_commands(ChamberVector::Zero());
        reply(MessageType::kStatus, Status{3, frame.seq, 0}.encode());
        break;
      case MessageType::kClear:
        estopped = false;
        reply(MessageType::kStatus, Status{4, frame.seq, 0}.encode());
        break;
      case MessageType::kPing:
        reply(MessageType::kPong, Pong{frame.seq}.encode());
        break;
      default:
        reply(MessageType::kRefused, Refused{frame.seq, 5}.encode());
    }
  }

  void advance() {
    if (!arm.advance_samples(1)) in_trial = false;  // non-finite: the stream stops
    {
      std::lock_guard lock(mutex);
      ++samples;
    }
    report();
  }

  void step() {
    // Listen for the host: briefly while the robot runs, longer while it waits.
    const bool lockstep = settings.pace == EmulatorPace::kLockstep;
    const bool holding =
        lockstep && in_trial && budget == 0 &&
        Clock::now() - wait_began < std::chrono::duration<double>(settings.host_wait_s);
    const auto now = Clock::now();
    Clock::time_point deadline = now;
    if (holding) {
      deadline = now + std::chrono::milliseconds(5);
    } else if (!lockstep || budget == 0 || !in_trial) {
      deadline = std::max(now, next_sample);
    }
    if (auto frame = commands.next(deadline)) {
      handle(*frame);
      return;
    }
    if (!in_trial) {
      next_sample = Clock::now() + std::chrono::milliseconds(10);
      return;
    }
    if (lockstep && budget > 0) {
      advance();
      if (--budget == 0) wait_began = Clock::now();
      next_sample = Clock::now() + std::chrono::milliseconds(10);
      return;
    }
    if (holding) return;
    if (Clock::now() >= next_sample) {
      advance();
      next_sample += std::chrono::milliseconds(10);
      if (next_sample < Clock::now()) next_sample = Clock::now();
    }
  }
};

ArmEmulator::ArmEmulator(ArmEmulatorSettings settings) {
  auto command_link = std::make_unique<UdpTransport>("127.0.0.1", settings.command_port, "", 0);
  require(settings.mocap_port > 0, "the motion capture needs the host's UDP port", "ArmEmulator");
  auto mocap_link =
      std::make_unique<UdpTransport>("127.0.0.1", 0, settings.mocap_host, settings.mocap_port);
  require(settings.samples_per_command >= 1, "samples_per_command must be >= 1", "ArmEmulator");
  impl_ =
      std::make_unique<Impl>(std::move(settings), std::move(command_link), std::move(mocap_link));
}

ArmEmulator::~ArmEmulator() { stop(); }

int ArmEmulator::command_port() const { return impl_->commands_udp->local_port(); }

void ArmEmulator::start() {
  require(!thread_.joinable(), "the emulator is already running", "ArmEmulator::start");
  stop_ = false;
  thread_ = std::thread([this] {
    while (!stop_) impl_->step();
  });
}

void ArmEmulator::stop() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

bool ArmEmulator::run_until(const std::function<bool()>& done, double wall_timeout_s) {
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(wall_timeout_s));
  while (Clock::now() < deadline) {
    if (done()) return true;
    impl_->step();
  }
  return done();
}

int ArmEmulator::samples() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->samples;
}

int ArmEmulator::commands() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->command_count;
}

void ArmEmulator::freeze_capture(bool frozen) { impl_->frozen = frozen; }
void ArmEmulator::silence_capture(bool silent) { impl_->silent = silent; }

}  // namespace tendril::hardware
