#include "tendril/envs/sma_limb/collect.hpp"

#include <array>
#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::envs::sma_limb {

namespace {

constexpr const char* kPwmKeys[4] = {"pwm_0", "pwm_1", "pwm_2", "pwm_3"};
constexpr double kCutoffDeg = 100.0;

double info_value(const Info& info, const char* key) {
  const std::optional<double> value = info.get(key);
  if (!value) throw Error(std::string("the environment reports no '") + key + "'", "collect");
  return *value;
}

std::array<int, 4> pwm_of(const Info& info) {
  std::array<int, 4> pwm{};
  for (int coil = 0; coil < 4; ++coil) {
    pwm[coil] = static_cast<int>(info_value(info, kPwmKeys[coil]));
  }
  return pwm;
}

}  // namespace

LimbLog collect(Env& env, ThrottleSource& source, const CollectSettings& settings, uint64_t seed,
                const std::function<void(double robot_time_s)>& on_reading) {
  require(
      settings.duration_s > 0.0 && settings.hold_readings >= 1 && settings.cutoff_cooldown_s >= 0.0,
      "collection needs a positive duration, holds of at least one reading and a "
      "non-negative cool-down",
      "collect");
  Rng rng(seed, 1);
  LimbLog log;
  Observation observation = env.reset(seed);
  Eigen::Vector2d angles = observation.head<2>().cast<double>();
  double time = 0.0;
  source.observe(angles);
  Action action(2);
  while (time < settings.duration_s) {
    const bool past_cutoff = angles.cwiseAbs().maxCoeff() >= kCutoffDeg;
    Eigen::Vector2i throttles = Eigen::Vector2i::Zero();
    int readings = 1;
    double cool_until = -1.0;
    if (past_cutoff) {
      ++log.cutoffs;
      cool_until = time + settings.cutoff_cooldown_s;
    } else {
      throttles = source.next(angles, rng);
      readings = settings.hold_readings;
    }
    for (int k = 0; time < settings.duration_s && (k < readings || time < cool_until); ++k) {
      action << static_cast<float>(throttles.x()), static_cast<float>(throttles.y());
      const Step step = env.step(action);
      log.add(time, angles, throttles, pwm_of(step.info));
      if (step.terminated) throw Error("the robot failed during collection", "collect");
      angles = step.observation.head<2>().cast<double>();
      time = info_value(step.info, "time_s");
      source.observe(angles);
      if (on_reading) on_reading(time);
      if (cool_until < 0.0 && angles.cwiseAbs().maxCoeff() >= kCutoffDeg) break;
    }
  }
  return log;
}

LimbLog drive_open_loop(Env& env, const ThrottleSequence& inputs, uint64_t seed) {
  LimbLog log;
  Observation observation = env.reset(seed);
  double time = 0.0;
  Action action(2);
  for (Eigen::Index k = 0; k < inputs.rows(); ++k) {
    const Eigen::Vector2i throttles = inputs.row(k).array().round().cast<int>().transpose();
    action << static_cast<float>(throttles.x()), static_cast<float>(throttles.y());
    const Step step = env.step(action);
    log.add(time, observation.head<2>().cast<double>(), throttles, pwm_of(step.info));
    if (step.terminated) throw Error("the robot failed during the open-loop drive", "collect");
    observation = step.observation;
    time = info_value(step.info, "time_s");
  }
  log.add(time, observation.head<2>().cast<double>(), Eigen::Vector2i::Zero(), {});
  return log;
}

}  // namespace tendril::envs::sma_limb
