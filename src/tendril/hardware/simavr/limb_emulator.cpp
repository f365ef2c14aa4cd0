#include "tendril/hardware/simavr/limb_emulator.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>

#include "tendril/core/error.hpp"
#include "tendril/hardware/frame_parser.hpp"
#include "tendril/hardware/messages.hpp"
#include "tendril/physics/twins/sma/sma_limb.hpp"

extern "C" {
#include <simavr/avr_ioport.h>
#include <simavr/avr_twi.h>
#include <simavr/avr_uart.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_elf.h>
#include <simavr/sim_irq.h>
}

namespace tendril::hardware {

namespace {

constexpr uint32_t kFrequency = 16'000'000;  // the Uno's crystal
constexpr avr_cycle_count_t kCyclesPerMs = kFrequency / 1000;
constexpr avr_cycle_count_t kPwmSampleCycles = kFrequency / 10'000;  // 100 µs
constexpr uint8_t kSensorAddress = 0x12;  // 7-bit; simavr's messages carry it shifted, R/W in bit 0
constexpr double kSensorResolutionDeg = 0.1;  // one count of the sensor's int16 output
// ATmega328P data-space addresses of the timers' control and compare registers (datasheet
// §14.9, §17.11): the duty a coil sees is OCRnx while its COMnx1 bit connects the pin.
constexpr int kTccr0a = 0x44, kOcr0a = 0x47, kOcr0b = 0x48;
constexpr int kTccr2a = 0xB0, kOcr2a = 0xB3, kOcr2b = 0xB4;
constexpr uint8_t kComA1 = 1u << 7, kComB1 = 1u << 5;
// The epoch's first reading comes this long after the host's RESET was seen on the wire (the
// frame must first cross the 115200-baud line and be handled).
constexpr avr_cycle_count_t kResetToFirstReading = 10 * kCyclesPerMs;

void no_sleep(avr_t*, avr_cycle_count_t) {}  // run as fast as the pacing allows

}  // namespace

struct LimbEmulator::Impl {
  LimbEmulatorSettings settings;
  avr_t* avr = nullptr;
  int master = -1;
  std::string port;
  avr_irq_t* uart_input = nullptr;
  avr_irq_t* drdy = nullptr;
  avr_irq_t* twi_irqs = nullptr;
  bool xon = true;
  std::deque<uint8_t> to_robot;  // from the pty, not yet in the UART
  std::vector<uint8_t> to_host;  // from the UART, not yet in the pty
  FrameParser host_frames, robot_frames;

  // The twin and its sensor.
  physics::SmaLimbSpec spec;
  std::unique_ptr<physics::SmaLimb> limb;
  avr_cycle_count_t epoch_cycle = 0;  // the epoch's first reading
  bool epoch_started = false;
  std::array<uint8_t, 4> latched{0, 0, 0, 0};
  int read_byte = 0;
  bool selected = false;
  bool sensor_nack = false;  // a non-finite twin: the sensor stops answering
  std::atomic<bool> frozen{false}, silent{false};

  // Pacing.
  uint16_t host_epoch = kNoSeq;  // the host's last RESET
  bool waiting_for_host = false;
  std::chrono::steady_clock::time_point wait_began;
  bool host_present = false;
  std::chrono::steady_clock::time_point pace_wall;
  avr_cycle_count_t pace_cycle = 0;

  // Shared with other threads.
  mutable std::mutex mutex;
  std::array<int, 4> pwm{0, 0, 0, 0};
  std::vector<PwmChange> history;
  double cycle_s = 0.0;
  double last_host_frame_s = -1.0;
  int readings = 0;
  int host_frame_count = 0;

  double seconds(avr_cycle_count_t cycles) const {
    return static_cast<double>(cycles) / kFrequency;
  }

  std::array<int, 4> driven() const {
    const uint8_t* data = avr->data;
    const uint8_t t0 = data[kTccr0a], t2 = data[kTccr2a];
    return {(t2 & kComB1) ? data[kOcr2b] : 0, (t0 & kComB1) ? data[kOcr0b] : 0,
            (t0 & kComA1) ? data[kOcr0a] : 0, (t2 & kComA1) ? data[kOcr2a] : 0};
  }

  // The sensor: latch a reading and pull data-ready low (the firmware's INT0 falling edge).
  void present(const physics::BendReading& reading) {
    if (!reading.angles_deg.allFinite()) {
      sensor_nack = true;
      return;
    }
    if (!frozen) {
      for (int axis = 0; axis < 2; ++axis) {
        const long counts = std::lround(reading.angles_deg[axis] / kSensorResolutionDeg);
        const int16_t value = static_cast<int16_t>(std::clamp(counts, -32768L, 32767L));
        latched[2 * axis] = static_cast<uint8_t>(value);
        latched[2 * axis + 1] = static_cast<uint8_t>(static_cast<uint16_t>(value) >> 8);
      }
    }
    if (silent) return;
    avr_raise_irq(drdy, 1);
    avr_raise_irq(drdy, 0);
    std::lock_guard lock(mutex);
    ++readings;
  }

  static avr_cycle_count_t reading_due(avr_t* avr, avr_cycle_count_t when, void* param) {
    auto* self = static_cast<Impl*>(param);
    (void)avr;
    if (!self->epoch_started) {
      self->epoch_started = true;
      self->epoch_cycle = when;
      self->present(self->limb->last_reading());
    } else {
      // The interval that ends now ran with the duties driven now (class comment).
      self->limb->set_pwm(self->driven());
      self->present(self->limb->next_reading());
    }
    return self->epoch_cycle +
           static_cast<avr_cycle_count_t>(self->limb->next_reading_ms()) * kCyclesPerMs;
  }

  static avr_cycle_count_t sample_pwm(avr_t* avr, avr_cycle_count_t when, void* param) {
    auto* self = static_cast<Impl*>(param);
    const std::array<int, 4> now = self->driven();
    std::lock_guard lock(self->mutex);
    self->cycle_s = self->seconds(when);
    if (now != self->pwm) {
      self->pwm = now;
      self->history.push_back({self->seconds(when), now});
    }
    (void)avr;
    return when + kPwmSampleCycles;
  }

  // simavr's TWI messages from the firmware (the bus master) to the sensor.
  static void twi_from_avr(avr_irq_t*, uint32_t value, void* param) {
    auto* self = static_cast<Impl*>(param);
    avr_twi_msg_irq_t message;
    message.u.v = value;
    const uint8_t msg = message.u.twi.msg;
    if (msg & TWI_COND_STOP) self->selected = false;
    if (msg & TWI_COND_START) {
      self->selected = false;
      if ((message.u.twi.addr >> 1) == kSensorAddress && !self->sensor_nack) {
        self->selected = true;
        self->read_byte = 0;
        avr_raise_irq(self->drdy, 1);  // the read clears data-ready
        avr_raise_irq(self->twi_irqs + TWI_IRQ_INPUT,
                      avr_twi_irq_msg(TWI_COND_ACK, message.u.twi.addr, 1));
      }
    }
    if (self->selected && (msg & TWI_COND_READ)) {
      const uint8_t byte = self->latched[self->read_byte % 4];
      ++self->read_byte;
      avr_raise_irq(self->twi_irqs + TWI_IRQ_INPUT,
                    avr_twi_irq_msg(TWI_COND_READ, message.u.twi.addr, byte));
    }
  }

  static void uart_from_avr(avr_irq_t*, uint32_t value, void* param) {
    auto* self = static_cast<Impl*>(param);
    const uint8_t byte = static_cast<uint8_t>(value);
    self->to_host.push_back(byte);
    self->robot_frames.push(byte);
    while (auto frame = self->robot_frames.next()) {
      if (frame->type != static_cast<uint8_t>(MessageType::kLimbReading) || !self->host_present ||
          self->settings.pace != EmulatorPace::kLockstep) {
        continue;
      }
      // Only a reading of the host's own epoch awaits an answer (an older epoch's, sent while
      // the host's RESET was on its way, does not).
      try {
        const LimbReading reading = LimbReading::decode(frame->payload);
        if (reading.reset_seq == kNoSeq || reading.reset_seq != self->host_epoch) continue;
      } catch (const Error&) {
        continue;
      }
      self->waiting_for_host = true;
      self->wait_began = std::chrono::steady_clock::now();
    }
  }

  static void uart_xon(avr_irq_t*, uint32_t, void* param) { static_cast<Impl*>(param)->xon = true; }
  static void uart_xoff(avr_irq_t*, uint32_t, void* param) {
    static_cast<Impl*>(param)->xon = false;
  }

  void rebuild_twin(uint64_t seed) {
    physics::SmaLimbSpec rested = spec;
    if (limb) {
      for (int i = 0; i < physics::SmaActuator::kCoils; ++i) {
        rested.actuator.initial_degradation[i] = limb->coil(i).degradation;
      }
    }
    limb = std::make_unique<physics::SmaLimb>(rested, seed);
    sensor_nack = false;
    epoch_started = false;
    avr_cycle_timer_cancel(avr, &Impl::reading_due, this);
    avr_raise_irq(drdy, 1);
    avr_cycle_timer_register(avr, kResetToFirstReading, &Impl::reading_due, this);
  }

  void host_frame(const Frame& frame) {
    waiting_for_host = false;
    {
      std::lock_guard lock(mutex);
      last_host_frame_s = seconds(avr->cycle);
      ++host_frame_count;
    }
    if (frame.type == static_cast<uint8_t>(MessageType::kReset)) {
      host_epoch = frame.seq;
      try {
        rebuild_twin(ResetRequest::decode(frame.payload).seed.value_or(0));
      } catch (const Error&) {
        // A malformed RESET: the firmware will answer it; the twin carries on.
      }
    }
  }

  // Moves bytes between the pty and the UART; waits up to `timeout_ms` for the host.
  void service_pty(int timeout_ms) {
    if (!to_host.empty()) {
      const ssize_t n = ::write(master, to_host.data(), to_host.size());
      // Without a reader the pty's buffer fills: bytes nobody reads are dropped, as on a
      // serial line with nothing attached.
      if (!host_present) {
        to_host.clear();
      } else if (n > 0) {
        to_host.erase(to_host.begin(), to_host.begin() + n);
      }
    }
    pollfd p{master, POLLIN, 0};
    const int ready = ::poll(&p, 1, timeout_ms);
    const bool present = ready >= 0 && !(p.revents & POLLHUP);
    if (present != host_present) {
      host_present = present;
      if (!present) waiting_for_host = false;
      repace();
    }
    if (ready > 0 && (p.revents & POLLIN)) {
      uint8_t buffer[512];
      const ssize_t n = ::read(master, buffer, sizeof buffer);
      for (ssize_t i = 0; i < n; ++i) {
        to_robot.push_back(buffer[i]);
        host_frames.push(buffer[i]);
        while (auto frame = host_frames.next()) host_frame(*frame);
      }
    }
    while (xon && !to_robot.empty()) {
      avr_raise_irq(uart_input, to_robot.front());
      to_robot.pop_front();
    }
  }

  void repace() {
    pace_wall = std::chrono::steady_clock::now();
    pace_cycle = avr->cycle;
  }

  bool lockstep_holding() {
    if (!waiting_for_host || !host_present) return false;
    const double waited =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wait_began).count();
    if (waited < settings.host_wait_s) return true;
    waiting_for_host = false;  // the host is slow or gone: on in real time
    repace();
    return false;
  }

  // One millisecond of robot time (less if a reading makes the robot wait for its host).
  void run_slice() {
    const avr_cycle_count_t end = avr->cycle + kCyclesPerMs;
    while (avr->cycle < end && !waiting_for_host) {
      const int state = avr_run(avr);
      if (state == cpu_Done || state == cpu_Crashed) {
        throw Error("the firmware stopped (simavr state " + std::to_string(state) + ")",
                    settings.firmware.string());
      }
    }
  }

  void step() {
    if (lockstep_holding()) {
      service_pty(5);
      repace();
      return;
    }
    service_pty(0);
    run_slice();
    service_pty(0);
    if (settings.pace == EmulatorPace::kRealtime || !host_present) {
      const auto due =
          pace_wall + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                          std::chrono::duration<double>(seconds(avr->cycle - pace_cycle)));
      const auto now = std::chrono::steady_clock::now();
      if (due > now + std::chrono::microseconds(200)) {
        // Wait for the wall clock, listening to the host meanwhile.
        const int ms = static_cast<int>(
            std::chrono::duration_cast<std::chrono::milliseconds>(due - now).count());
        service_pty(std::max(ms, 0));
        if (!host_present) std::this_thread::sleep_until(due);
      }
    }
  }
};

LimbEmulator::LimbEmulator(LimbEmulatorSettings settings) : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.settings = std::move(settings);
  s.spec = s.settings.spec;
  s.spec.validate();
  require(std::abs(s.spec.sensor.resolution - kSensorResolutionDeg) < 1e-12,
          "the emulated sensor reports counts of 0.1 degree; the twin's resolution must be 0.1",
          "LimbEmulator");
  require(std::isfinite(s.settings.host_wait_s) && s.settings.host_wait_s >= 0.0,
          "host_wait_s must be >= 0", "LimbEmulator");
  if (!std::filesystem::exists(s.settings.firmware)) {
    throw Error("no firmware ELF here (build the tendril_firmware target)",
                s.settings.firmware.string());
  }

  avr_global_logger_set([](avr_t*, int, const char*, va_list) {});
  s.avr = avr_make_mcu_by_name("atmega328p");
  require(s.avr != nullptr, "simavr has no atmega328p", "LimbEmulator");
  avr_init(s.avr);
  elf_firmware_t firmware;
  std::memset(&firmware, 0, sizeof firmware);
  if (elf_read_firmware(s.settings.firmware.c_str(), &firmware) != 0) {
    throw Error("simavr cannot read this ELF", s.settings.firmware.string());
  }
  std::strcpy(firmware.mmcu, "atmega328p");
  firmware.frequency = kFrequency;
  avr_load_firmware(s.avr, &firmware);
  s.avr->frequency = kFrequency;
  s.avr->sleep = &no_sleep;
  s.avr->log = 0;

  uint32_t flags = 0;
  avr_ioctl(s.avr, AVR_IOCTL_UART_GET_FLAGS('0'), &flags);
  flags &= ~AVR_UART_FLAG_STDIO;
  avr_ioctl(s.avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);
  s.uart_input = avr_io_getirq(s.avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_INPUT);
  avr_irq_register_notify(avr_io_getirq(s.avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT),
                          &Impl::uart_from_avr, &s);
  avr_irq_register_notify(avr_io_getirq(s.avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUT_XON),
                          &Impl::uart_xon, &s);
  avr_irq_register_notify(avr_io_getirq(s.avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUT_XOFF),
                          &Impl::uart_xoff, &s);

  static const char* twi_names[2] = {"sensor.twi.in", "sensor.twi.out"};
  s.twi_irqs = avr_alloc_irq(&s.avr->irq_pool, 0, 2, twi_names);
  avr_irq_register_notify(s.twi_irqs + TWI_IRQ_OUTPUT, &Impl::twi_from_avr, &s);
  avr_connect_irq(s.twi_irqs + TWI_IRQ_INPUT,
                  avr_io_getirq(s.avr, AVR_IOCTL_TWI_GETIRQ(0), TWI_IRQ_INPUT));
  avr_connect_irq(avr_io_getirq(s.avr, AVR_IOCTL_TWI_GETIRQ(0), TWI_IRQ_OUTPUT),
                  s.twi_irqs + TWI_IRQ_OUTPUT);
  s.drdy = avr_io_getirq(s.avr, AVR_IOCTL_IOPORT_GETIRQ('D'), 2);
  avr_raise_irq(s.drdy, 1);

  s.master = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (s.master < 0 || ::grantpt(s.master) != 0 || ::unlockpt(s.master) != 0) {
    throw Error(std::string("cannot open a pseudo-terminal: ") + std::strerror(errno),
                "LimbEmulator");
  }
  s.port = ::ptsname(s.master);
  if (!s.settings.link.empty()) {
    std::error_code ignored;
    std::filesystem::remove(s.settings.link, ignored);
    std::filesystem::create_symlink(s.port, s.settings.link);
  }

  s.limb = std::make_unique<physics::SmaLimb>(s.spec, s.settings.seed);
  avr_cycle_timer_register(s.avr, kResetToFirstReading, &Impl::reading_due, &s);
  avr_cycle_timer_register(s.avr, kPwmSampleCycles, &Impl::sample_pwm, &s);
  s.repace();
}

LimbEmulator::~LimbEmulator() {
  stop();
  if (!impl_->settings.link.empty()) {
    std::error_code ignored;
    std::filesystem::remove(impl_->settings.link, ignored);
  }
  if (impl_->master >= 0) ::close(impl_->master);
  if (impl_->avr != nullptr) avr_terminate(impl_->avr);
}

const std::string& LimbEmulator::port() const { return impl_->port; }

void LimbEmulator::start() {
  require(!thread_.joinable(), "the emulator is already running", "LimbEmulator::start");
  stop_ = false;
  thread_ = std::thread([this] {
    while (!stop_) impl_->step();
  });
}

void LimbEmulator::stop() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

bool LimbEmulator::run_until(const std::function<bool()>& done, double wall_timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(wall_timeout_s));
  while (std::chrono::steady_clock::now() < deadline) {
    if (done()) return true;
    impl_->step();
  }
  return done();
}

double LimbEmulator::time_s() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->cycle_s;
}

std::array<int, 4> LimbEmulator::pwm() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->pwm;
}

std::vector<LimbEmulator::PwmChange> LimbEmulator::pwm_history() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->history;
}

double LimbEmulator::last_host_frame_s() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->last_host_frame_s;
}

int LimbEmulator::readings() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->readings;
}

int LimbEmulator::host_frames() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->host_frame_count;
}

void LimbEmulator::freeze_sensor(bool frozen) { impl_->frozen = frozen; }
void LimbEmulator::silence_sensor(bool silent) { impl_->silent = silent; }

}  // namespace tendril::hardware
