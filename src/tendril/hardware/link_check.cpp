#include "tendril/hardware/link_check.hpp"

#include <chrono>
#include <cstdio>

namespace tendril::hardware {

namespace {

using Clock = std::chrono::steady_clock;

std::string milliseconds(const LatencyStats& stats) {
  char text[160];
  std::snprintf(text, sizeof text,
                "%d samples, mean %.2f ms, median %.2f ms, p95 %.2f ms, max %.2f ms, jitter "
                "(std) %.2f ms",
                stats.count(), 1e3 * stats.mean(), 1e3 * stats.percentile(50),
                1e3 * stats.percentile(95), 1e3 * stats.max(), 1e3 * stats.jitter());
  return text;
}

template <typename Bridge>
void ping_all(Bridge& bridge, int pings, LinkCheck& check) {
  for (int i = 0; i < pings; ++i) check.ping.add(bridge.ping());
}

void finish(LinkCheck& check, double robot_start, double robot_end, Clock::time_point start) {
  check.robot_time_s = robot_end - robot_start;
  check.wall_time_s = std::chrono::duration<double>(Clock::now() - start).count();
  if (check.robot_time_s > 0) check.sensor_rate_hz = check.steps / check.robot_time_s;
  if (check.wall_time_s > 0) check.control_rate_hz = check.steps / check.wall_time_s;
}

}  // namespace

std::string LinkCheck::report() const {
  std::string out = "robot " + robot + ", firmware " + firmware + "\nlimits:";
  for (const auto& [key, value] : limits) out += " " + key + "=" + std::to_string(value);
  char text[1024];
  std::snprintf(text, sizeof text,
                "\nround trip (PING): %s\ncommand round trip: %s\n"
                "%d steps: %.3f s of robot time, %.3f s of wall time; sensor %.2f Hz (robot "
                "clock), control %.2f Hz achieved (wall clock)\n"
                "readings lost: %d, safety actions: %d\n",
                milliseconds(ping).c_str(), milliseconds(command).c_str(), steps, robot_time_s,
                wall_time_s, sensor_rate_hz, control_rate_hz, readings_missed, safety_events);
  return out + text;
}

LinkCheck check_limb(LimbBridge& bridge, int pings, int steps) {
  LinkCheck check;
  check.robot = bridge.identity().robot;
  check.firmware = bridge.identity().firmware_version();
  check.limits = bridge.identity().limits;
  ping_all(bridge, pings, check);
  const size_t events = bridge.log().events().size();
  const LimbBridgeSample first = bridge.reset(0);
  const auto start = Clock::now();
  double last_time = first.time_s;
  for (int k = 0; k < steps; ++k) {
    const LimbBridgeSample sample = bridge.command({0, 0, 0, 0});
    check.command.add(sample.latency_s);
    check.readings_missed += sample.readings_missed;
    last_time = sample.time_s;
    ++check.steps;
  }
  finish(check, first.time_s, last_time, start);
  check.safety_events = static_cast<int>(bridge.log().events().size() - events);
  return check;
}

LinkCheck check_arm(ArmBridge& bridge, int pings, int steps) {
  LinkCheck check;
  check.robot = bridge.identity().robot;
  check.firmware = bridge.identity().firmware_version();
  check.limits = bridge.identity().limits;
  ping_all(bridge, pings, check);
  const size_t events = bridge.log().events().size();
  const ArmBridgeSample first = bridge.reset(std::nullopt);
  const auto start = Clock::now();
  double last_time = first.time_s;
  for (int k = 0; k < steps; ++k) {
    const ArmBridgeSample sample = bridge.command(physics::pneumatic::ChamberVector::Zero());
    check.command.add(sample.latency_s);
    check.readings_missed += sample.frames_missed;
    last_time = sample.time_s;
    ++check.steps;
  }
  finish(check, first.time_s, last_time, start);
  check.safety_events = static_cast<int>(bridge.log().events().size() - events);
  return check;
}

}  // namespace tendril::hardware
