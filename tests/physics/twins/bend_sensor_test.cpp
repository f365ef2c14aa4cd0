// The bend sensor: its angle definition, sampling clock, error bound, resolution and offsets.
#include "tendril/physics/twins/sma/bend_sensor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/error_message.hpp"
#include "tendril/physics/rod/rod.hpp"
#include "tendril/physics/twins/sma/sma_limb.hpp"

namespace tendril::physics {
namespace {

Eigen::Matrix3d rotation(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// A tip turned by β about an axis perpendicular to the rod reads β along the direction it bent
// to: (θx, θy) = β (cos φ, sin φ) — beyond 90° too.
TEST(BendSensor, ReadsTheBendAngleAlongItsDirection) {
  RodSpec spec;
  spec.n_elements = 4;
  spec.direction = -Eigen::Vector3d::UnitZ();
  spec.normal = Eigen::Vector3d::UnitX();
  Rod rod(spec);
  auto& sensor = rod.add<BendSensor>(BendSensorSpec{}, 1);
  const Eigen::Matrix3d base = rod.state().director(0);  // rows d1, d2, d3 (lab)
  for (double beta_deg : {10.0, 60.0, 120.0, 170.0}) {
    for (double phi_deg : {0.0, 30.0, 90.0, 200.0}) {
      const double beta = beta_deg * std::numbers::pi / 180.0;
      const double phi = phi_deg * std::numbers::pi / 180.0;
      // Bending towards (cos φ d1 + sin φ d2) turns d3 about d3 × that direction.
      const Eigen::Vector3d towards =
          std::cos(phi) * base.row(0).transpose() + std::sin(phi) * base.row(1).transpose();
      const Eigen::Vector3d axis = base.row(2).transpose().cross(towards);
      const Eigen::Matrix3d tip = base * rotation(axis, beta).transpose();
      rod.mutable_state().set_director(3, tip);
      const Eigen::Vector2d angles = sensor.true_angles_deg(rod.state());
      EXPECT_NEAR(angles.x(), beta_deg * std::cos(phi), 1e-9) << beta_deg << "°, " << phi_deg;
      EXPECT_NEAR(angles.y(), beta_deg * std::sin(phi), 1e-9) << beta_deg << "°, " << phi_deg;
    }
  }
}

// At rest, over 2000 readings: periods of 55–75 whole milliseconds (mean 65), readings on the
// 0.1° grid, never more than 0.5° from the true angle plus offset, spread like σ = 0.2° noise
// truncated at 0.45°, centred on the offset.
TEST(BendSensor, SamplesEvery55To75MillisecondsWithBoundedQuantisedError) {
  SmaLimbSpec spec = SmaLimbSpec::stiff();
  spec.sensor.zero_offset = Eigen::Vector2d(-10.0, -12.0);
  SmaLimb limb(spec, 7);
  int64_t previous_ms = limb.last_reading().time_ms;
  EXPECT_EQ(previous_ms, 0);
  double sum_period = 0.0, sum = 0.0, sum_squares = 0.0, worst = 0.0;
  int shortest = 1000, longest = 0;
  const int count = 2000;
  for (int k = 0; k < count; ++k) {
    const BendReading reading = limb.next_reading();
    const int period = static_cast<int>(reading.time_ms - previous_ms);
    previous_ms = reading.time_ms;
    shortest = std::min(shortest, period);
    longest = std::max(longest, period);
    sum_period += period;
    EXPECT_DOUBLE_EQ(limb.time(), reading.time());
    const Eigen::Vector2d truth = limb.true_angles_deg() + spec.sensor.zero_offset;
    for (int axis = 0; axis < 2; ++axis) {
      const double value = reading.angles_deg[axis];
      EXPECT_NEAR(value * 10.0, std::round(value * 10.0), 1e-9) << "0.1° resolution";
      const double error = value - truth[axis];
      worst = std::max(worst, std::abs(error));
      sum += error;
      sum_squares += error * error;
    }
  }
  EXPECT_EQ(shortest, 55);
  EXPECT_EQ(longest, 75);
  EXPECT_NEAR(sum_period / count, 65.0, 0.5);
  EXPECT_LE(worst, 0.5 + 1e-9);
  EXPECT_GT(worst, 0.4) << "the bound is reached, not avoided";
  const double mean = sum / (2 * count);
  const double deviation = std::sqrt(sum_squares / (2 * count) - mean * mean);
  EXPECT_NEAR(mean, 0.0, 0.02);
  EXPECT_NEAR(deviation, 0.2, 0.02);
}

TEST(BendSensor, TheSameSeedGivesTheSameReadings) {
  SmaLimb a(SmaLimbSpec::soft(), 3), b(SmaLimbSpec::soft(), 3), c(SmaLimbSpec::soft(), 4);
  bool differs = false;
  for (int k = 0; k < 50; ++k) {
    const BendReading ra = a.next_reading(), rb = b.next_reading(), rc = c.next_reading();
    EXPECT_EQ(ra.time_ms, rb.time_ms);
    EXPECT_EQ(ra.angles_deg, rb.angles_deg);
    differs = differs || ra.time_ms != rc.time_ms || ra.angles_deg != rc.angles_deg;
  }
  EXPECT_TRUE(differs);
}

TEST(BendSensor, InvalidSpecsAreRejected) {
  BendSensorSpec spec;
  spec.max_period_ms = 50;
  EXPECT_NE(testing::error_message([&] { spec.validate(); }), "no error");
  spec = BendSensorSpec{};
  spec.max_error = 0.01;
  EXPECT_NE(testing::error_message([&] { spec.validate(); }).find("max_error"), std::string::npos);
}

}  // namespace
}  // namespace tendril::physics
