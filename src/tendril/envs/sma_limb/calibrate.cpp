#include "tendril/envs/sma_limb/calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs::sma_limb {

namespace {

// +x, −x, +y, −y: the axis each coil bends and the sign of its direction.
constexpr int kAxis[4] = {0, 0, 1, 1};
constexpr double kSign[4] = {1.0, -1.0, 1.0, -1.0};

std::array<int, 4> only(int coil, int pwm) {
  std::array<int, 4> command{0, 0, 0, 0};
  command[coil] = pwm;
  return command;
}

void check(const CalibrationSettings& settings) {
  const char* who = "calibrate";
  require(settings.rest_s > 0.0 && settings.hold_s > 0.0 && settings.cooldown_s >= 0.0,
          "rest, hold and cool-down times must be positive", who);
  require(settings.velocity_window >= 1 && settings.noise_margin > 0.0,
          "velocity_window must be at least 1 and noise_margin positive", who);
  require(
      settings.start_pwm >= 1 && settings.start_pwm <= settings.max_pwm && settings.max_pwm <= 255,
      "PWM sweep needs 1 <= start_pwm <= max_pwm <= 255", who);
}

}  // namespace

void measure_rest(LimbRobot& robot, const CalibrationSettings& settings, uint64_t seed,
                  LimbCalibration& calibration, LimbSample& sample) {
  check(settings);
  const std::array<int, 4> off{0, 0, 0, 0};
  sample = robot.reset(seed);
  std::vector<LimbSample> rest{sample};
  while (sample.time_s < settings.rest_s) rest.push_back(sample = robot.command(off));
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const LimbSample& s : rest) sum += s.angles_deg;
  require(sum.allFinite(), "the robot failed during calibration", "calibrate");
  // Kept at 0.01°, a tenth of the sensor's resolution.
  calibration.zero_offset_deg =
      (sum / static_cast<double>(rest.size()) * 100.0).array().round() / 100.0;
  const std::size_t window = static_cast<std::size_t>(settings.velocity_window);
  double floor = 0.0;
  for (std::size_t k = window; k < rest.size(); ++k) {
    const Eigen::Vector2d velocity = (rest[k].angles_deg - rest[k - window].angles_deg) /
                                     (rest[k].time_s - rest[k - window].time_s);
    floor = std::max(floor, velocity.cwiseAbs().maxCoeff());
  }
  calibration.noise_floor_deg_s = floor;
}

std::array<int, 2> sweep_coil(LimbRobot& robot, int coil, const CalibrationSettings& settings,
                              const LimbCalibration& calibration, LimbSample& sample,
                              std::vector<CalibrationHold>& holds) {
  check(settings);
  const char* who = "calibrate";
  require(coil >= 0 && coil < 4, "coil must be 0-3", who);
  const std::array<int, 4> off{0, 0, 0, 0};
  const int axis = kAxis[coil];
  const double sign = kSign[coil];
  const std::size_t window = static_cast<std::size_t>(settings.velocity_window);
  const double moving = settings.noise_margin * calibration.noise_floor_deg_s;
  int lower = 0, upper = 0;
  for (int pwm = settings.start_pwm; pwm <= settings.max_pwm && upper == 0; ++pwm) {
    CalibrationHold hold;
    hold.coil = coil;
    hold.pwm = pwm;
    const double start = sample.time_s;
    std::vector<double> times{start};  // absolute, for the velocities
    hold.time_s.push_back(0.0);
    hold.angle_deg.push_back(sign * (sample.angles_deg[axis] - calibration.zero_offset_deg[axis]));
    while (sample.time_s - start < settings.hold_s) {
      sample = robot.command(only(coil, pwm));
      const Eigen::Vector2d angles = sample.angles_deg - calibration.zero_offset_deg;
      require(angles.allFinite(), "the robot failed during calibration", who);
      const double angle = sign * angles[axis];
      hold.time_s.push_back(sample.time_s - start);
      hold.angle_deg.push_back(angle);
      times.push_back(sample.time_s);
      const std::size_t k = times.size() - 1;
      if (k >= window) {
        hold.peak_velocity_deg_s =
            std::max(hold.peak_velocity_deg_s,
                     (angle - hold.angle_deg[k - window]) / (times[k] - times[k - window]));
      }
      // The firmware's cut-off ends the hold.
      if (angles.cwiseAbs().maxCoeff() >= settings.threshold_deg) {
        hold.reached_threshold = true;
        break;
      }
    }
    if (lower == 0 && hold.peak_velocity_deg_s > moving) lower = pwm;
    if (hold.reached_threshold) upper = pwm;
    holds.push_back(std::move(hold));
    const double cooled = sample.time_s + settings.cooldown_s;
    while (sample.time_s < cooled) sample = robot.command(off);
  }
  if (upper == 0) {
    throw Error("coil " + std::string(LimbCalibration::kCoilKeys[coil]) +
                    " did not bend the limb to " + std::to_string(settings.threshold_deg) +
                    " degrees up to PWM " + std::to_string(settings.max_pwm),
                who);
  }
  return {lower > 0 ? lower : upper, upper};
}

CalibrationResult calibrate(
    LimbRobot& robot, const CalibrationSettings& settings, const std::string& limb, uint64_t seed,
    const std::function<void(int coil, const LimbCalibration& calibration)>& on_stage) {
  CalibrationResult result;
  result.calibration.limb = limb;
  LimbSample sample;
  measure_rest(robot, settings, seed, result.calibration, sample);
  if (on_stage) on_stage(-1, result.calibration);
  for (int coil = 0; coil < 4; ++coil) {
    const std::array<int, 2> bounds =
        sweep_coil(robot, coil, settings, result.calibration, sample, result.holds);
    result.calibration.lower_pwm[coil] = bounds[0];
    result.calibration.upper_pwm[coil] = bounds[1];
    if (on_stage) on_stage(coil, result.calibration);
  }
  result.robot_time_s = sample.time_s;
  result.calibration.validate("calibrate");
  return result;
}

}  // namespace tendril::envs::sma_limb
