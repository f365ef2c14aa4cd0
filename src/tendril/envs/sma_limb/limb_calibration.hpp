#pragma once

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <string>

namespace tendril::envs::sma_limb {

// The input bounds of each coil and the sensor's zero offsets, as the thesis' autonomous
// calibration finds them (seed 001, §4.2.1), and the throttle table built from them (§4.1.2,
// eq. 4.4): an integer throttle u ∈ [−10, 10] per axis, its sign choosing the coil of the
// antagonistic pair (+ → the + coil), its magnitude j the PWM
//   PWM(j) = lower + (j − 1)(upper − lower)/9  (j = 1 … 10, rounded),  PWM(0) = 0,
// so that |u| = 1 is the lower bound (the first PWM that moves the limb) and |u| = 10 the upper
// (the first that bends it to 100° within a hold) — 21 levels, as in the thesis' firmware.
// Worked example of §4.2.1: +x bounds 20/35, −x 19/36 give u = +1 → 20, +10 → 35, −1 → 19,
// −10 → 36.
struct LimbCalibration {
  static constexpr int kLevels = 10;  // non-zero throttle magnitudes
  // Coil order of the firmware: +x, −x, +y, −y.
  static constexpr const char* kCoilKeys[4] = {"pos_x", "neg_x", "pos_y", "neg_y"};

  std::string limb;                          // which limb it was made on
  std::array<int, 4> lower_pwm{0, 0, 0, 0};  // per coil
  std::array<int, 4> upper_pwm{0, 0, 0, 0};
  Eigen::Vector2d zero_offset_deg = Eigen::Vector2d::Zero();  // subtracted from the readings
  double noise_floor_deg_s = 0.0;  // the velocity noise the lower bounds rose above

  // The thesis' bounds for its two limbs (stiff 40A: 7 % / 15 % of 255 in every direction;
  // soft 30A: 7 % / 11 %), without zero offsets: what a robot runs on before its own calibration.
  static LimbCalibration nominal(const std::string& limb);

  // The four PWM values for throttles (u_x, u_y), each rounded to the nearest integer and
  // saturated at ±10 (the table has 21 levels).
  std::array<int, 4> pwm_for(double throttle_x, double throttle_y) const;
  int pwm_for_level(int coil, int level) const;  // level 0 … 10

  // Raises tendril::Error unless 1 <= lower <= upper <= 255 for every coil and all is finite.
  void validate(const std::string& where) const;

  // A YAML file (documented in its header comment). load raises Error naming the file and key;
  // save never overwrites an existing file (Error naming it).
  static LimbCalibration load(const std::filesystem::path& file);
  void save(const std::filesystem::path& file) const;
  std::string to_yaml() const;
};

}  // namespace tendril::envs::sma_limb
