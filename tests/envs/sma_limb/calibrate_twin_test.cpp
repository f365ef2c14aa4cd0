// The calibration of the twin against the twin's own true thresholds (seed 001, §4.2.1).
#include <gtest/gtest.h>

#include <cmath>

#include "tendril/envs/sma_limb/calibrate.hpp"
#include "tendril/envs/sma_limb/twin_limb_robot.hpp"
#include "tendril/physics/twins/sma/sma_limb.hpp"

namespace tendril::envs::sma_limb {
namespace {

// The twin's true thresholds for one coil, each hold from a limb at rest, read without noise
// (the same clock): the first PWM whose two-reading velocity beats `moving` and the first whose
// angle reaches 100°; and the dead zone's edge, the first PWM whose wire reaches As.
struct TrueThresholds {
  int lower = 0, upper = 0, dead_zone_edge = 0;
};

TrueThresholds true_thresholds(physics::SmaLimbSpec spec, int first, double moving) {
  spec.sensor.noise_std = 0.0;
  TrueThresholds truth;
  for (int pwm = first; truth.upper == 0; ++pwm) {
    physics::SmaLimb limb(spec, 1);
    limb.set_pwm({pwm, 0, 0, 0});
    std::vector<double> times{0.0}, angles{0.0};
    double peak_velocity = 0.0, peak_temperature = 0.0, peak_angle = 0.0;
    while (limb.time() < 2.5) {
      limb.next_reading();
      times.push_back(limb.time());
      angles.push_back(limb.true_angles_deg().x());
      const std::size_t k = times.size() - 1;
      if (k >= 2) {
        peak_velocity =
            std::max(peak_velocity, (angles[k] - angles[k - 2]) / (times[k] - times[k - 2]));
      }
      peak_temperature = std::max(peak_temperature, limb.coil(0).wire_temperature);
      peak_angle = std::max(peak_angle, angles[k]);
      if (peak_angle >= 100.0) break;
    }
    if (truth.dead_zone_edge == 0 &&
        peak_temperature > spec.actuator.coil.transformation.austenite_start) {
      truth.dead_zone_edge = pwm;
    }
    if (truth.lower == 0 && peak_velocity > moving) truth.lower = pwm;
    if (peak_angle >= 100.0) truth.upper = pwm;
  }
  return truth;
}

// The calibration of the twin's +x coil lands within one PWM step of the twin's true thresholds
// (the sensor's ±0.5° error can move either by one), above the dead zone, and near the thesis'
// bounds for its limbs (7 % and 15 % of 255 for the stiff limb, 7 % and 11 % for the soft one).
class CalibrateTwin : public ::testing::TestWithParam<std::string> {};

TEST_P(CalibrateTwin, FindsTheTwinsTrueThresholdsWithinOnePwmStep) {
  const physics::SmaLimbSpec spec = physics::SmaLimbSpec::variant(GetParam());
  TwinLimbRobot robot(spec);
  CalibrationSettings settings;
  settings.start_pwm = 16;
  LimbCalibration calibration;
  LimbSample sample;
  measure_rest(robot, settings, 7, calibration, sample);
  EXPECT_NEAR(calibration.zero_offset_deg.x(), spec.sensor.zero_offset.x(), 0.1);
  EXPECT_NEAR(calibration.zero_offset_deg.y(), spec.sensor.zero_offset.y(), 0.1);
  EXPECT_GT(calibration.noise_floor_deg_s, 2.0);
  EXPECT_LE(calibration.noise_floor_deg_s, 1.0 / 0.110 + 1e-9) << "≤ 1° over two periods";
  std::vector<CalibrationHold> holds;
  const std::array<int, 2> bounds = sweep_coil(robot, 0, settings, calibration, sample, holds);

  const TrueThresholds truth = true_thresholds(
      spec, settings.start_pwm, settings.noise_margin * calibration.noise_floor_deg_s);
  EXPECT_NEAR(bounds[0], truth.lower, 1) << GetParam();
  EXPECT_NEAR(bounds[1], truth.upper, 1) << GetParam();
  EXPECT_GT(bounds[0], truth.dead_zone_edge);
  const double thesis_upper = GetParam() == "stiff" ? 0.15 : 0.11;
  EXPECT_NEAR(bounds[0] / 255.0, 0.07, 0.015) << GetParam();
  EXPECT_NEAR(bounds[1] / 255.0, thesis_upper, 0.015) << GetParam();
}

// TWIN_LIMB is set by the build: the soft limb in the default suite (≈ 30 min of robot time),
// the stiff one under the `long` label (≈ 45 min).
INSTANTIATE_TEST_SUITE_P(Limb, CalibrateTwin, ::testing::Values(TWIN_LIMB));

}  // namespace
}  // namespace tendril::envs::sma_limb
