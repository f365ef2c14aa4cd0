// The autonomous calibration of input bounds (seed 001, §4.2.1): against a robot whose
// thresholds are known by construction, and against the twin's true thresholds.
#include "tendril/envs/sma_limb/calibrate.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/error_message.hpp"

namespace tendril::envs::sma_limb {
namespace {

// A robot of straight lines: readings every 65 ms; while one coil is on at PWM p its axis turns
// at v(p) = max(0, p − 17) °/s in the coil's direction; all coils off, it is straight at once.
// Zero offsets (−10, −12) and a noise repeating 0.3, 0.3, −0.3, −0.3 on both axes.
class LineRobot final : public LimbRobot {
 public:
  LimbSample reset(uint64_t) override {
    time_ = 0.0;
    angles_.setZero();
    count_ = 0;
    return read();
  }
  LimbSample command(const std::array<int, 4>& pwm) override {
    time_ += kPeriod;
    bool any = false;
    for (int coil = 0; coil < 4; ++coil) {
      if (pwm[coil] == 0) continue;
      any = true;
      const double sign = coil % 2 == 0 ? 1.0 : -1.0;
      angles_[coil / 2] += sign * std::max(0, pwm[coil] - 17) * kPeriod;
    }
    if (!any) angles_.setZero();
    return read();
  }
  std::string description() const override { return "line robot"; }
  static constexpr double kPeriod = 0.065;

 private:
  LimbSample read() {
    const double noise[4] = {0.3, 0.3, -0.3, -0.3};
    const double e = noise[count_++ % 4];
    return {time_, angles_ + Eigen::Vector2d(-10.0 + e, -12.0 + e)};
  }
  double time_ = 0.0;
  Eigen::Vector2d angles_ = Eigen::Vector2d::Zero();
  int count_ = 0;
};

// By hand: over two readings (130 ms) the noise changes by ±0.6° exactly, so the floor is
// 0.6 / 0.13 = 4.62 °/s and a hold moves when its two-reading velocity beats 1.5 × that,
// 6.92 °/s. Within a hold the noise adds at most +4.62 °/s, so v(p) = p − 17 > 2.31 first at
// p = 20 (v = 3: 3 + 4.62 > 6.92; p = 19: 2 + 4.62 < 6.92). The hold's readings run to 2.535 s
// (39 periods, the first at or past 2.5 s), so 100° needs v · 2.535 + noise ≥ 100: p = 57
// (40 °/s → 101.4°; p = 56 reaches 98.9 + 0.3).
TEST(Calibrate, FindsTheBoundsOfARobotWithKnownThresholds) {
  LineRobot robot;
  CalibrationSettings settings;
  settings.cooldown_s = 1.0;
  settings.start_pwm = 15;
  const CalibrationResult result = calibrate(robot, settings, "line", 1);
  const LimbCalibration& calibration = result.calibration;
  EXPECT_EQ(calibration.limb, "line");
  EXPECT_NEAR(calibration.zero_offset_deg.x(), -10.0, 0.021);
  EXPECT_NEAR(calibration.zero_offset_deg.y(), -12.0, 0.021);
  EXPECT_NEAR(calibration.noise_floor_deg_s, 0.6 / 0.13, 1e-9);
  for (int coil = 0; coil < 4; ++coil) {
    EXPECT_EQ(calibration.lower_pwm[coil], 20) << "coil " << coil;
    EXPECT_EQ(calibration.upper_pwm[coil], 57) << "coil " << coil;
  }
  // Every hold from start_pwm to the upper bound, per coil, curves along the coil's direction.
  ASSERT_EQ(result.holds.size(), 4u * (57 - 15 + 1));
  const CalibrationHold& last_minus_x = result.holds[2 * 43 - 1];
  EXPECT_EQ(last_minus_x.coil, 1);
  EXPECT_EQ(last_minus_x.pwm, 57);
  EXPECT_TRUE(last_minus_x.reached_threshold);
  EXPECT_GE(last_minus_x.angle_deg.back(), 100.0);
  EXPECT_NEAR(last_minus_x.time_s.back(), 39 * LineRobot::kPeriod, 1e-9);
}

TEST(Calibrate, ACoilTooWeakToReachTheThresholdIsAnError) {
  LineRobot robot;
  CalibrationSettings settings;
  settings.cooldown_s = 0.5;
  settings.start_pwm = 30;
  settings.max_pwm = 40;
  EXPECT_NE(
      tendril::testing::error_message([&] { calibrate(robot, settings, "line", 1); }).find("pos_x"),
      std::string::npos);
}

}  // namespace
}  // namespace tendril::envs::sma_limb
