// Denavit–Hartenberg forward kinematics against hand-derived values.
#include "tendril/physics/rigid/dh_kinematics.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "tendril/core/error.hpp"
#include "tendril/physics/rigid/ur5_parameters.hpp"

namespace tendril::physics {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(DhKinematics, OneLinkMovesItsOriginToACosThetaASinThetaD) {
  // Rz(θ)·Tz(d)·Tx(a)·Rx(α) takes the origin to (a cos θ, a sin θ, d) and x to (cos θ, sin θ, 0).
  const DhLink link{0.3, 0.2, 0.7};
  const Eigen::Isometry3d transform = dh_transform(link, 0.5);
  EXPECT_NEAR(
      (transform.translation() - Eigen::Vector3d(0.3 * std::cos(0.5), 0.3 * std::sin(0.5), 0.2))
          .norm(),
      0.0, 1e-15);
  EXPECT_NEAR((transform.linear().col(0) - Eigen::Vector3d(std::cos(0.5), std::sin(0.5), 0)).norm(),
              0.0, 1e-15);
  // z turns by α about x: (0, −sin α, cos α) before the θ rotation.
  const Eigen::Vector3d z = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()) *
                            Eigen::Vector3d(0.0, -std::sin(0.7), std::cos(0.7));
  EXPECT_NEAR((transform.linear().col(2) - z).norm(), 0.0, 1e-15);
}

TEST(DhKinematics, Ur5AtZeroMatchesThePublishedFlangePosition) {
  // At q = 0 the arm lies along −x: x = a₂ + a₃, y = −(d₄ + d₆), z = d₁ − d₅, tool axis −y.
  const Eigen::Isometry3d flange =
      dh_forward_kinematics(ur5_dh_links(), Eigen::VectorXd::Zero(ur5::kJoints));
  EXPECT_NEAR((flange.translation() - Eigen::Vector3d(-0.81725, -0.19145, -0.005491)).norm(), 0.0,
              1e-12);
  EXPECT_NEAR((flange.linear().col(2) - Eigen::Vector3d(0, -1, 0)).norm(), 0.0, 1e-12);
}

TEST(DhKinematics, TheBaseJointTurnsTheWholeArmAboutZ) {
  Eigen::VectorXd q(6);
  q << 0.0, -0.8, 1.1, -0.4, 0.9, 0.3;
  const Eigen::Isometry3d before = dh_forward_kinematics(ur5_dh_links(), q);
  q[0] = kPi / 2;
  const Eigen::Isometry3d after = dh_forward_kinematics(ur5_dh_links(), q);
  const Eigen::Matrix3d quarter =
      Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_NEAR((after.translation() - quarter * before.translation()).norm(), 0.0, 1e-12);
  EXPECT_NEAR((after.linear() - quarter * before.linear()).norm(), 0.0, 1e-12);
}

TEST(DhKinematics, ShoulderUpPointsTheStraightArmVertically) {
  // q₂ = −π/2 turns the straight arm (and the d₅ offset, downwards at q = 0) a quarter turn up
  // about the shoulder: the flange at height d₁ − a₂ − a₃, at x = −d₅, y = −(d₄ + d₆), the tool
  // axis along −y as at q = 0.
  Eigen::VectorXd q = Eigen::VectorXd::Zero(6);
  q[1] = -kPi / 2;
  const Eigen::Isometry3d flange = dh_forward_kinematics(ur5_dh_links(), q);
  const double height = ur5::kDhD[0] - ur5::kDhA[1] - ur5::kDhA[2];
  const Eigen::Vector3d expected(-ur5::kDhD[4], -(ur5::kDhD[3] + ur5::kDhD[5]), height);
  EXPECT_NEAR((flange.translation() - expected).norm(), 0.0, 1e-12);
  EXPECT_NEAR((flange.linear().col(2) - Eigen::Vector3d(0, -1, 0)).norm(), 0.0, 1e-12);
}

TEST(DhKinematics, FramesEndAtTheFlangeAndWrongSizesAreRejected) {
  const Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(6, -1.0, 1.0);
  const auto frames = dh_frames(ur5_dh_links(), q);
  ASSERT_EQ(frames.size(), 6u);
  EXPECT_TRUE(frames.back().isApprox(dh_forward_kinematics(ur5_dh_links(), q)));
  EXPECT_THROW(dh_forward_kinematics(ur5_dh_links(), Eigen::VectorXd::Zero(5)), Error);
}

}  // namespace
}  // namespace tendril::physics
