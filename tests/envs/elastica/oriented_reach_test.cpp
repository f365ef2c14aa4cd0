#include "tendril/envs/elastica/oriented_reach.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "elastica_test_support.hpp"
#include "tendril/envs/elastica/rewards.hpp"

namespace tendril::envs::elastica {
namespace {

constexpr double kPi = std::numbers::pi;

// Seed 000 case 2: tangent up, normal and binormal turned from the initial tip frame by
// θ ∈ [−90°, 90°]. The arm starts along +y with d1 = +z, d2 = +x.
TEST(OrientedReach, TargetFrameIsUprightAndTurnedByAtMostNinetyDegrees) {
  OrientedReach env;
  int negative = 0, positive = 0;
  for (uint64_t seed = 0; seed < 200; ++seed) {
    env.reset(seed);
    const Eigen::Matrix3d frame = env.target_orientation().toRotationMatrix();  // columns d1 d2 d3
    ASSERT_TRUE(frame.col(2).isApprox(Eigen::Vector3d::UnitY(), 1e-12)) << seed;
    const double theta = env.target_angle();
    ASSERT_GE(theta, -kPi / 2);
    ASSERT_LT(theta, kPi / 2);
    // d1 = R_y(θ) z = (sin θ, 0, cos θ); d2 = R_y(θ) x = (cos θ, 0, −sin θ).
    ASSERT_TRUE(
        frame.col(0).isApprox(Eigen::Vector3d(std::sin(theta), 0.0, std::cos(theta)), 1e-12));
    ASSERT_TRUE(
        frame.col(1).isApprox(Eigen::Vector3d(std::cos(theta), 0.0, -std::sin(theta)), 1e-12));
    const Eigen::Vector3d target = env.target_position();
    ASSERT_TRUE((target.array() >= Eigen::Array3d(-0.6, 0.3, -0.6)).all());
    ASSERT_TRUE((target.array() <= Eigen::Array3d(0.6, 0.9, 0.6)).all());
    (theta < 0 ? negative : positive) += 1;
  }
  EXPECT_GT(negative, 60);
  EXPECT_GT(positive, 60);
  // θ = 0 is the arm's own initial frame.
  const Eigen::Quaterniond initial = env.arm().rod.tip_quaternion();
  EXPECT_NEAR(orientation_penalty(OrientedReach::target_frame(initial, 0.0), initial), 0.0, 1e-15);
}

// The orientation terms of the reward, aligned vs perpendicular frames, at 3 cm and 7 cm.
TEST(OrientedReach, OrientationTermsForAlignedAndPerpendicularFrames) {
  OrientedReach env;
  env.reset(0);
  const Eigen::Vector3d tip = env.arm().rod.tip_position();
  const Eigen::Quaterniond tip_frame = env.arm().rod.tip_quaternion();
  const Eigen::Vector3d sideways = Eigen::Vector3d(2.0, -1.0, 2.0) / 3.0;
  struct Row {
    double offset;
    Eigen::Quaterniond target;
    double penalty;
    double bonus;
  };
  const Eigen::Quaterniond about_vertical(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitY()));
  const Eigen::Quaterniond tilted(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()));
  const Row rows[] = {
      {0.03, tip_frame, 0.0, 6.0},                          // aligned, under 5 cm
      {0.03, about_vertical * tip_frame, 0.5, 4.0 - 1.0},   // perpendicular normal/binormal
      {0.03, tilted * tip_frame, 0.5, 4.0 - 1.0},           // tangent no longer up
      {0.07, tip_frame, 0.0, 1.5},                          // aligned, 5–10 cm
      {0.07, about_vertical * tip_frame, 0.5, 1.0 - 0.25},  // perpendicular, 5–10 cm
      {0.2, about_vertical * tip_frame, 0.5, 0.0},          // far: continuous terms only
  };
  for (const Row& row : rows) {
    env.set_target(tip + row.offset * sideways);
    env.set_target_orientation(row.target);
    const Step step = env.step(Action::Zero(18));
    const double d = *step.info.get("distance");
    const double p = *step.info.get("orientation");
    EXPECT_NEAR(d, row.offset, 1e-9);
    EXPECT_NEAR(p, row.penalty, 1e-12);
    EXPECT_NEAR(step.reward, -d * d - 0.5 * p * p + row.bonus, 1e-9)
        << row.offset << " " << row.penalty;
    EXPECT_EQ(*step.info.get("is_success"), row.offset < 0.05 && row.penalty < 0.05 ? 1.0 : 0.0);
  }
}

TEST(OrientedReach, ObservationHoldsBothQuaternionsAndAStillTarget) {
  OrientedReach env;
  env.reset(5);
  const Eigen::Quaterniond initial = env.arm().rod.tip_quaternion();
  Step step;
  for (int i = 0; i < 15; ++i) step = env.step(Action::Constant(18, 0.4f));
  const Observation& obs = step.observation;
  ASSERT_EQ(obs.size(), 52);
  testing::expect_rod_block(obs, env.arm().rod);
  const Eigen::Quaterniond tip = env.arm().rod.tip_quaternion();
  const Eigen::Quaterniond& target = env.target_orientation();
  EXPECT_FLOAT_EQ(obs[37], static_cast<float>(tip.w()));
  EXPECT_FLOAT_EQ(obs[38], static_cast<float>(tip.x()));
  EXPECT_FLOAT_EQ(obs[39], static_cast<float>(tip.y()));
  EXPECT_FLOAT_EQ(obs[40], static_cast<float>(tip.z()));
  for (int c = 0; c < 3; ++c) {
    EXPECT_FLOAT_EQ(obs[41 + c], static_cast<float>(env.target_position()[c]));
  }
  EXPECT_EQ(obs.segment(44, 4), Eigen::Vector4f::Zero());  // target speed and direction
  EXPECT_FLOAT_EQ(obs[48], static_cast<float>(target.w()));
  EXPECT_FLOAT_EQ(obs[49], static_cast<float>(target.x()));
  EXPECT_FLOAT_EQ(obs[50], static_cast<float>(target.y()));
  EXPECT_FLOAT_EQ(obs[51], static_cast<float>(target.z()));
  // The arm (bending and twisting) turned the tip frame.
  EXPECT_GT(orientation_penalty(tip, initial), 1e-6);
  EXPECT_NEAR(*step.info.get("orientation"), orientation_penalty(tip, target), 1e-12);
}

}  // namespace
}  // namespace tendril::envs::elastica
