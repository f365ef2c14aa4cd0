#include "tendril/envs/elastica/rewards.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace tendril::envs::elastica {
namespace {

// Seed 000, cases 1, 3, 4: R = −d² + {2.0 if d ≤ 5 cm, 0.5 if 5 cm < d ≤ 10 cm, 0 beyond}.
TEST(Rewards, ReachRewardTable) {
  EXPECT_DOUBLE_EQ(reach_reward(0.0), 2.0);
  EXPECT_DOUBLE_EQ(reach_reward(0.03), 2.0 - 0.0009);
  EXPECT_DOUBLE_EQ(reach_reward(0.05), 2.0 - 0.0025);
  EXPECT_DOUBLE_EQ(reach_reward(0.0500001), 0.5 - 0.0500001 * 0.0500001);
  EXPECT_DOUBLE_EQ(reach_reward(0.07), 0.5 - 0.0049);
  EXPECT_DOUBLE_EQ(reach_reward(0.1), 0.5 - 0.01);
  EXPECT_DOUBLE_EQ(reach_reward(0.1000001), -0.1000001 * 0.1000001);
  EXPECT_DOUBLE_EQ(reach_reward(0.5), -0.25);
}

Eigen::Quaterniond turned(double angle, const Eigen::Vector3d& axis) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

TEST(Rewards, OrientationPenaltyIsOneMinusSquaredQuaternionDot) {
  const Eigen::Quaterniond frame = turned(0.7, Eigen::Vector3d(1, 2, 3));
  EXPECT_NEAR(orientation_penalty(frame, frame), 0.0, 1e-15);
  // q and −q are the same frame.
  Eigen::Quaterniond flipped = frame;
  flipped.coeffs() *= -1.0;
  EXPECT_NEAR(orientation_penalty(frame, flipped), 0.0, 1e-15);
  // A quarter turn apart: (q·q')² = cos²(45°) = ½; half a turn: 0.
  EXPECT_NEAR(
      orientation_penalty(frame, turned(std::numbers::pi / 2, Eigen::Vector3d::UnitX()) * frame),
      0.5, 1e-15);
  EXPECT_NEAR(
      orientation_penalty(frame, frame * turned(std::numbers::pi, Eigen::Vector3d::UnitZ())), 1.0,
      1e-15);
  EXPECT_NEAR(orientation_penalty(frame, turned(0.3, Eigen::Vector3d(0, 1, 1)) * frame),
              std::pow(std::sin(0.15), 2), 1e-15);
}

// Seed 000, case 2: R = −n² − 0.5 p² + the graded bonus of its table.
TEST(Rewards, OrientedReachTiers) {
  const double d_near = 0.03, d_mid = 0.07, d_far = 0.3;
  const auto base = [](double d, double p) { return -d * d - 0.5 * p * p; };
  // Under 5 cm.
  EXPECT_DOUBLE_EQ(oriented_reach_reward(d_near, 0.0), base(d_near, 0.0) + 6.0);
  EXPECT_DOUBLE_EQ(oriented_reach_reward(d_near, 0.04), base(d_near, 0.04) + 6.0 - 0.08);
  EXPECT_DOUBLE_EQ(oriented_reach_reward(d_near, 0.05), base(d_near, 0.05) + 6.0 - 0.1);
  EXPECT_DOUBLE_EQ(oriented_reach_reward(d_near, 0.08), base(d_near, 0.08) + 4.5 - 0.16);
  EXPECT_DOUBLE_EQ(oriented_reach_reward(d_near, 0.1), base(d_near, 0.1) + 4.5 - 0.2);
  EXPECT_DOUBLE_EQ(oriented_reach_reward(d_near, 0.5), base(d_near, 0.5) + 4.0 - 1.0);
  // 5–10 cm.
  EXPECT_DOUBLE_EQ(oriented_reach_reward(d_mid, 0.02), base(d_mid, 0.02) + 1.5 - 0.01);
  EXPECT_DOUBLE_EQ(oriented_reach_reward(d_mid, 0.1), base(d_mid, 0.1) + 1.5 - 0.05);
  EXPECT_DOUBLE_EQ(oriented_reach_reward(d_mid, 0.5), base(d_mid, 0.5) + 1.0 - 0.25);
  // Beyond 10 cm: the continuous terms only.
  EXPECT_DOUBLE_EQ(oriented_reach_reward(d_far, 0.0), -0.09);
  EXPECT_DOUBLE_EQ(oriented_reach_reward(d_far, 1.0), -0.09 - 0.5);
}

}  // namespace
}  // namespace tendril::envs::elastica
