#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "tendril/envs/sma_limb/limb_calibration.hpp"
#include "tendril/envs/sma_limb/limb_robot.hpp"

namespace tendril::envs::sma_limb {

// The thesis' autonomous calibration of input bounds (seed 001, §4.2.1, Fig. 4.1). First the limb
// rests with every coil off for `rest_s`: the mean reading is the sensor's zero offset and the
// fastest apparent motion, |Δθ| / Δt between consecutive readings, its velocity noise floor.
// Then for each coil, PWM values are swept upwards from `start_pwm`; each is held for `hold_s`
// (ended early when a reading passes the 100° cut-off, as the firmware does), then every coil is
// off for `cooldown_s` so that no heat carries over ("hysteresis effects should be disregarded").
//   lower bound = the first PWM during whose hold the limb moves, along the coil's direction,
//                 faster than noise_margin × the noise floor;
//   upper bound = the first PWM whose hold bends the limb to 100°.
// The sweep of a coil stops at its upper bound (or at max_pwm: an Error, the coil is too weak).
// The thesis held ≈ 2.5 s, cooled ≈ 2 min and took the velocity as the change of angle over one
// sampling period. Its sensor's error reaches 0.5°, so one period's apparent velocity at rest
// reaches 1° / 55 ms ≈ 18 °/s, and a hold's noise would beat the rest's maximum about as often
// as not: velocities here span `velocity_window` periods and must beat the floor by
// `noise_margin` (both our choice) — the thesis' "noticeable velocity".
struct CalibrationSettings {
  double rest_s = 5.0;
  double hold_s = 2.5;
  double cooldown_s = 120.0;
  int start_pwm = 5;
  int max_pwm = 80;
  double threshold_deg = 100.0;
  int velocity_window = 2;  // readings
  double noise_margin = 1.5;
};

// One hold of the sweep: the readings (offsets removed) along the coil's axis, signed so that the
// coil's own direction is positive. The curves of Fig. 4.1.
struct CalibrationHold {
  int coil = 0;
  int pwm = 0;
  std::vector<double> time_s;        // since the hold began
  std::vector<double> angle_deg;     // along the coil's direction
  double peak_velocity_deg_s = 0.0;  // over velocity_window readings, along the coil
  bool reached_threshold = false;
};

struct CalibrationResult {
  LimbCalibration calibration;
  std::vector<CalibrationHold> holds;  // every hold, in sweep order
  double robot_time_s = 0.0;           // how long the robot was busy
};

// Calibrates `robot` (reset with `seed` first): measure_rest, then sweep_coil for each coil.
// Raises Error if a coil never reaches the threshold below max_pwm. `limb` names the limb in the
// result. `on_stage`, if given, sees the calibration after each stage (coil −1: the rest
// measured; 0–3: that coil swept), as the stages take a while on a robot or its twin.
CalibrationResult calibrate(
    LimbRobot& robot, const CalibrationSettings& settings, const std::string& limb, uint64_t seed,
    const std::function<void(int coil, const LimbCalibration& calibration)>& on_stage = {});

// The two stages of calibrate. measure_rest resets the robot and fills the zero offsets and the
// noise floor of `calibration`; sweep_coil sweeps one coil from the robot's state after `sample`
// (its latest reading, updated), appends its holds and returns {lower, upper}.
void measure_rest(LimbRobot& robot, const CalibrationSettings& settings, uint64_t seed,
                  LimbCalibration& calibration, LimbSample& sample);
std::array<int, 2> sweep_coil(LimbRobot& robot, int coil, const CalibrationSettings& settings,
                              const LimbCalibration& calibration, LimbSample& sample,
                              std::vector<CalibrationHold>& holds);

}  // namespace tendril::envs::sma_limb
