#include "tendril/envs/pneumatic/bridge_robot_env.hpp"

#include <cmath>
#include <limits>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/envs/pneumatic/robot_env.hpp"
#include "tendril/hardware/transport_config.hpp"
#include "tendril/hardware/udp_transport.hpp"

namespace tendril::envs::pneumatic {

namespace {

using physics::pneumatic::kChambers;
using physics::pneumatic::kModules;

constexpr double kMillimetresPerMetre = 1000.0;
constexpr double kSamplePeriod = 0.01;  // the capture's 100 Hz (checked against the identity)

}  // namespace

std::unique_ptr<Env> BridgeRobotEnv::create(const Config& params) {
  const double period = params.get_or<double>("control_period_s", 0.1);
  const bool observe_pressures = params.get_or<bool>("observe_pressures", false);
  const double samples = period / kSamplePeriod;
  if (!(std::isfinite(period) && samples >= 1.0 - 1e-9 &&
        std::abs(samples - std::round(samples)) < 1e-6)) {
    throw Error(
        "must be a positive whole number of 10 ms capture samples, got " + std::to_string(period),
        params.where("control_period_s"));
  }
  const Config bridge = params.child("bridge");
  auto commands = std::make_unique<hardware::UdpTransport>(
      "127.0.0.1", bridge.get_or<int>("local_port", 0),
      bridge.get_or<std::string>("udp_host", "127.0.0.1"), bridge.get<int>("udp_port"));
  auto mocap =
      std::make_unique<hardware::UdpTransport>("127.0.0.1", bridge.get<int>("mocap_port"), "", 0);
  auto arm = std::make_unique<hardware::ArmBridge>(
      hardware::with_faults(std::move(commands), bridge.child("faults")),
      hardware::with_faults(std::move(mocap), bridge.child("mocap_faults")),
      hardware::ArmBridgeSettings::from(bridge), static_cast<int>(std::lround(samples)));
  const auto period_us = arm->identity().limit("sample_period_us");
  require(period_us && *period_us == 10000, "the motion capture must sample at 100 Hz",
          bridge.where("udp_port"));
  return std::make_unique<BridgeRobotEnv>(std::move(arm), observe_pressures);
}

BridgeRobotEnv::BridgeRobotEnv(std::unique_ptr<hardware::ArmBridge> bridge, bool observe_pressures)
    : bridge_(std::move(bridge)),
      observe_pressures_(observe_pressures),
      observation_space_(Space::box(observe_pressures ? 2 * kChambers : kChambers,
                                    -std::numeric_limits<float>::infinity(),
                                    std::numeric_limits<float>::infinity())),
      action_space_(Space::box(kChambers, 0.0f, static_cast<float>(bridge_->max_bar()))) {
  info_.set("time_s", 0.0);
  info_.set(info_keys::kNan, 0.0);
  info_.set("elapsed_s", 0.0);
  info_.set("latency_s", 0.0);
}

Observation BridgeRobotEnv::observe(const hardware::ArmBridgeSample& sample) const {
  Observation observation(observation_space_.size());
  for (int m = 0; m < kModules; ++m) {
    for (int r = 0; r < 3; ++r) {
      observation[3 * m + r] = static_cast<float>(kMillimetresPerMetre * sample.tips_m(r, m));
    }
  }
  if (observe_pressures_) {
    for (int k = 0; k < kChambers; ++k) {
      observation[kChambers + k] = static_cast<float>(sample.pressures_bar[k]);
    }
  }
  return observation;
}

Observation BridgeRobotEnv::reset(std::optional<uint64_t> seed) {
  const hardware::ArmBridgeSample sample = bridge_->reset(seed);
  info_.set("time_s", 0.0);
  info_.set(info_keys::kNan, 0.0);
  info_.set("elapsed_s", 0.0);
  info_.set("latency_s", 0.0);
  return observe(sample);
}

Step BridgeRobotEnv::step(const Action& action) {
  check_action(action_space_, action, RobotEnv::kId);
  const hardware::ArmBridgeSample sample = bridge_->command(action.cast<double>());
  Step result;
  result.observation = observe(sample);
  info_.set("time_s", sample.time_s);
  info_.set(info_keys::kNan, 0.0);
  info_.set("elapsed_s", sample.elapsed_s);
  info_.set("latency_s", sample.latency_s);
  result.info = info_;
  return result;
}

}  // namespace tendril::envs::pneumatic
