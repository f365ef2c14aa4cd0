#include "tendril/envs/pneumatic/robot_env.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/envs/pneumatic/arm_params.hpp"
#include "tendril/envs/pneumatic/bridge_robot_env.hpp"

namespace tendril::envs::pneumatic {

namespace {

using physics::pneumatic::ChamberVector;
using physics::pneumatic::kChambers;
using physics::pneumatic::kModules;

constexpr double kMillimetresPerMetre = 1000.0;

}  // namespace

std::unique_ptr<Env> RobotEnv::create(const Config& params) {
  // The arm behind the interface: the twin, or the bridge to the lab's devices (`bridge:`).
  const std::string backend = params.get_or<std::string>("backend", "twin");
  if (backend == "bridge") return BridgeRobotEnv::create(params);
  if (backend != "twin") {
    throw Error("backend must be twin or bridge, got '" + backend + "'", params.where("backend"));
  }
  const physics::pneumatic::PneumaticArmSpec spec = arm_spec_from(params);
  const double period = params.get_or<double>("control_period_s", 0.1);
  const bool observe_pressures = params.get_or<bool>("observe_pressures", false);
  const double samples = period / spec.sensor.sample_period;
  if (!(std::isfinite(period) && samples >= 1.0 - 1e-9 &&
        std::abs(samples - std::round(samples)) < 1e-6)) {
    throw Error(
        "must be a positive whole number of 10 ms sensor samples, got " + std::to_string(period),
        key_where(params, "control_period_s"));
  }
  return std::make_unique<RobotEnv>(spec, period, observe_pressures);
}

RobotEnv::RobotEnv(const physics::pneumatic::PneumaticArmSpec& spec, double control_period,
                   bool observe_pressures)
    : arm_(spec),
      control_period_(control_period),
      samples_per_step_(static_cast<int>(std::lround(control_period / spec.sensor.sample_period))),
      observe_pressures_(observe_pressures),
      observation_space_(Space::box(observe_pressures ? 2 * kChambers : kChambers,
                                    -std::numeric_limits<float>::infinity(),
                                    std::numeric_limits<float>::infinity())),
      action_space_(Space::box(kChambers, 0.0f, static_cast<float>(spec.regulators.ceiling_bar))) {
  require(samples_per_step_ >= 1, "the control period must hold at least one sensor sample", kId);
  info_.set("time_s", 0.0);
  info_.set(info_keys::kNan, 0.0);
  last_observation_ = observe();
}

Observation RobotEnv::reset(std::optional<uint64_t> seed) {
  const bool finite = arm_.begin_trial(seed);
  require(finite, "the twin's state became non-finite while settling", kId);
  info_.set("time_s", 0.0);
  info_.set(info_keys::kNan, 0.0);
  last_observation_ = observe();
  return last_observation_;
}

Step RobotEnv::step(const Action& action) {
  check_action(action_space_, action, kId);
  arm_.set_commands(action.cast<double>());
  const bool finite = arm_.advance_samples(samples_per_step_);
  Step result;
  if (finite) {
    result.observation = observe();
    last_observation_ = result.observation;
    info_.set(info_keys::kNan, 0.0);
  } else {
    result.observation = last_observation_;
    result.terminated = true;
    info_.set(info_keys::kNan, 1.0);
  }
  info_.set("time_s", arm_.time());
  result.info = info_;
  return result;
}

Observation RobotEnv::observe() const {
  Observation observation(observation_space_.size());
  const physics::pneumatic::TipPositions& tips = arm_.measured_tip_positions();
  for (int m = 0; m < kModules; ++m) {
    for (int r = 0; r < 3; ++r) {
      observation[3 * m + r] = static_cast<float>(kMillimetresPerMetre * tips(r, m));
    }
  }
  if (observe_pressures_) {
    for (int k = 0; k < kChambers; ++k) {
      observation[kChambers + k] = static_cast<float>(arm_.pressures()[k]);
    }
  }
  return observation;
}

void RobotEnv::save_state(SnapshotWriter& out) const {
  out.section(kId);
  arm_.save_state(out);
  out.put_matrix(last_observation_);
  for (const auto& entry : info_.entries()) out.put(entry.second);
}

void RobotEnv::load_state(SnapshotReader& in) {
  in.section(kId);
  load_all_or_nothing(arm_, in, [&] {
    Observation last = last_observation_;
    in.get_matrix(last);
    Info info = info_;
    for (const auto& entry : info_.entries()) info.set(entry.first, in.get_double());
    last_observation_ = std::move(last);
    info_ = std::move(info);
  });
}

bool RobotEnv::describe_scene(Scene& scene) const {
  const physics::Rod& rod = arm_.rod();
  scene.time = arm_.time();
  scene.rods.push_back(
      {"arm", rod.sampled_node_positions(rod.n_elements() + 1), rod.state().radii});
  const physics::pneumatic::TipPositions tips = arm_.true_tip_positions();
  for (int m = 0; m < kModules; ++m) scene.spheres.push_back({"marker", tips.col(m), 0.008});
  const ChamberVector& pressures = arm_.pressures();
  for (int k = 0; k < kChambers; ++k) {
    scene.values.emplace_back(
        "pressure m" + std::to_string(k / 3 + 1) + " c" + std::to_string(k % 3 + 1) + " [bar]",
        pressures[k]);
  }
  return true;
}

EnvDescription RobotEnv::description() {
  std::vector<EnvDescription::Parameter> parameters = {
      {"backend", "", "twin, or bridge to the lab's devices"},
      {"bridge.*", "",
       "with backend: bridge, the links to the regulators and the motion capture "
       "(docs/hardware.md)",
       true},
      {"control_period_s", "s", "how long a step holds the commands (whole 10 ms samples)"},
      {"observe_pressures", "", "append the 9 measured pressures to the observation"}};
  const std::vector<EnvDescription::Parameter> arm = arm_parameters("");
  parameters.insert(parameters.end(), arm.begin(), arm.end());
  return {
      .observation = {{"tip of module 1 x y z (robot frame, z down from the base plane)", "mm", 3},
                      {"tip of module 2 x y z", "mm", 3},
                      {"tip of module 3 x y z", "mm", 3}},
      .action = {{"pressure commands of chambers 3m + c (module m, chamber c), clamped to the "
                  "ceiling",
                  "bar", kChambers}},
      .reward = "0 (the robot has no task)",
      .episode_end =
          "terminated only when the twin's state becomes non-finite; truncated by the "
          "time limit (150 steps, a trial of seed 002)",
      .parameters = std::move(parameters),
  };
}

}  // namespace tendril::envs::pneumatic
