#include "tendril/envs/sma_limb/limb_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/config.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/file_kind.hpp"

namespace tendril::envs::sma_limb {

LimbCalibration LimbCalibration::nominal(const std::string& limb) {
  LimbCalibration calibration;
  calibration.limb = limb;
  int lower = 0, upper = 0;
  if (limb == "stiff") {
    lower = 18;  // 7 % of 255
    upper = 38;  // 15 %
  } else if (limb == "soft") {
    lower = 18;  // 7 %
    upper = 28;  // 11 %
  } else {
    throw Error("no nominal calibration for limb '" + limb + "' (expected stiff or soft)",
                "LimbCalibration");
  }
  calibration.lower_pwm.fill(lower);
  calibration.upper_pwm.fill(upper);
  return calibration;
}

int LimbCalibration::pwm_for_level(int coil, int level) const {
  if (level <= 0) return 0;
  const int lower = lower_pwm[coil], upper = upper_pwm[coil];
  return static_cast<int>(
      std::lround(lower + (std::min(level, kLevels) - 1) * (upper - lower) / 9.0));
}

std::array<int, 4> LimbCalibration::pwm_for(double throttle_x, double throttle_y) const {
  std::array<int, 4> pwm{0, 0, 0, 0};
  const long ux = std::clamp(std::lround(throttle_x), -10L, 10L);
  const long uy = std::clamp(std::lround(throttle_y), -10L, 10L);
  if (ux > 0) pwm[0] = pwm_for_level(0, static_cast<int>(ux));
  if (ux < 0) pwm[1] = pwm_for_level(1, static_cast<int>(-ux));
  if (uy > 0) pwm[2] = pwm_for_level(2, static_cast<int>(uy));
  if (uy < 0) pwm[3] = pwm_for_level(3, static_cast<int>(-uy));
  return pwm;
}

void LimbCalibration::validate(const std::string& where) const {
  for (int coil = 0; coil < 4; ++coil) {
    if (!(lower_pwm[coil] >= 1 && lower_pwm[coil] <= upper_pwm[coil] && upper_pwm[coil] <= 255)) {
      throw Error("coil " + std::string(kCoilKeys[coil]) + " needs 1 <= lower_pwm (" +
                      std::to_string(lower_pwm[coil]) + ") <= upper_pwm (" +
                      std::to_string(upper_pwm[coil]) + ") <= 255",
                  where);
    }
  }
  require(zero_offset_deg.allFinite(), "zero_offset_deg must be finite", where);
  require(std::isfinite(noise_floor_deg_s) && noise_floor_deg_s >= 0.0,
          "noise_floor_deg_per_s must be finite and non-negative", where);
}

LimbCalibration LimbCalibration::load(const std::filesystem::path& file) {
  const Config config = Config::load_file(file);
  expect_kind(config, file_kind::kCalibration);
  LimbCalibration calibration;
  calibration.limb = config.get<std::string>("limb");
  const std::vector<double> offset = config.get<std::vector<double>>("zero_offset_deg");
  if (offset.size() != 2) {
    throw Error("zero_offset_deg must list 2 angles, got " + std::to_string(offset.size()),
                file.string() + ": zero_offset_deg");
  }
  calibration.zero_offset_deg = Eigen::Vector2d(offset[0], offset[1]);
  calibration.noise_floor_deg_s = config.get<double>("noise_floor_deg_per_s");
  const Config coils = config.child("coils");
  for (int coil = 0; coil < 4; ++coil) {
    const Config entry = coils.child(kCoilKeys[coil]);
    calibration.lower_pwm[coil] = entry.get<int>("lower_pwm");
    calibration.upper_pwm[coil] = entry.get<int>("upper_pwm");
  }
  config.reject_unknown();
  calibration.validate(file.string());
  return calibration;
}

std::string LimbCalibration::to_yaml() const {
  std::string text =
      "# Calibration of an SMA limb (tendril; seed 001, section 4.2.1): per coil the first PWM\n"
      "# (of 255, at 11.1 V) that moved the limb faster than the sensor's velocity noise floor\n"
      "# (lower_pwm, throttle 1) and the first that bent it to 100 degrees within a hold\n"
      "# (upper_pwm, throttle 10); the sensor's zero offsets (degrees, subtracted from its\n"
      "# readings) and the noise floor (degrees per second).\n"
      "kind: calibration\n";
  char line[160];
  std::snprintf(line, sizeof line, "limb: %s\nzero_offset_deg: [%.2f, %.2f]\n", limb.c_str(),
                zero_offset_deg.x(), zero_offset_deg.y());
  text += line;
  std::snprintf(line, sizeof line, "noise_floor_deg_per_s: %.2f\ncoils:\n", noise_floor_deg_s);
  text += line;
  for (int coil = 0; coil < 4; ++coil) {
    std::snprintf(line, sizeof line, "  %s: {lower_pwm: %d, upper_pwm: %d}\n", kCoilKeys[coil],
                  lower_pwm[coil], upper_pwm[coil]);
    text += line;
  }
  return text;
}

void LimbCalibration::save(const std::filesystem::path& file) const {
  validate(file.string());
  write_new_file_atomically(file, to_yaml(), "calibration");
}

}  // namespace tendril::envs::sma_limb
