// Read-outs and boundary parts.
#include <gtest/gtest.h>

#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/physics/forcing/loads.hpp"
#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::physics {
namespace {

TEST(RodReadout, SampledNodesAndTipFrame) {
  RodSpec spec;
  spec.n_elements = 20;
  spec.direction = Eigen::Vector3d::UnitZ();
  spec.normal = Eigen::Vector3d::UnitX();
  Rod rod(spec);
  const Eigen::Matrix3Xd samples = rod.sampled_node_positions(11);
  ASSERT_EQ(samples.cols(), 11);
  for (int k = 0; k < 11; ++k) {
    EXPECT_NEAR(samples(2, k), 0.1 * k, 1e-15);  // every second node of 20
  }
  // Rows d1 d2 d3 = x, y, z: the identity frame, quaternion (1, 0, 0, 0).
  EXPECT_LT((rod.tip_directors() - Eigen::Matrix3d::Identity()).norm(), 1e-15);
  EXPECT_NEAR(rod.tip_quaternion().w(), 1.0, 1e-15);

  RodSpec turned = spec;
  turned.direction = Eigen::Vector3d::UnitY();
  turned.normal = Eigen::Vector3d::UnitZ();  // d2 = y × z = x
  Rod arm(turned);
  // The frame with columns d1 d2 d3 = (z, x, y) maps x → z → y → x: a rotation by −120° about
  // (1, 1, 1)/√3, so q = (cos 60°, −sin 60° (1, 1, 1)/√3) = (½, −½, −½, −½).
  const Eigen::Quaterniond q = arm.tip_quaternion();
  EXPECT_NEAR(q.w(), 0.5, 1e-15);
  EXPECT_NEAR(q.x(), -0.5, 1e-15);
  EXPECT_NEAR(q.y(), -0.5, 1e-15);
  EXPECT_NEAR(q.z(), -0.5, 1e-15);
  EXPECT_THROW(rod.sampled_node_positions(1), Error);
}

TEST(RodReadout, StrainsAndEnergiesOfABentRod) {
  RodSpec spec;
  spec.n_elements = 10;
  spec.rest_curvature = Eigen::Vector3d(2.0, 0.0, 0.0);  // intrinsically curved
  Rod rod(spec);
  // Straight but intrinsically curved: κ = 0 ≠ κ̂, so bend energy ½ Σ D̂ B (κ̂)² is stored.
  const RodEnergies energy = rod.energies();
  const double bend = rod.model().bend_stiffness(0, 0);
  EXPECT_NEAR(energy.bend_twist, 0.5 * 9 * 0.1 * bend * 4.0, 1e-12 * bend);
  EXPECT_NEAR(energy.shear_stretch, 0.0, 1e-20);
  EXPECT_EQ(rod.curvatures().cols(), 9);
  EXPECT_EQ(rod.shear_strains().cols(), 10);
}

TEST(Boundary, GeneralConstraintHoldsChosenTranslations) {
  RodSpec spec;
  spec.n_elements = 10;
  spec.direction = Eigen::Vector3d::UnitX();
  spec.normal = Eigen::Vector3d::UnitZ();
  spec.youngs_modulus = 1e6;
  spec.time_step = 1e-4;
  Rod rod(spec);
  // Pin both ends' heights only: the rod sags between them but its ends stay at z = 0, while
  // it slides freely along x and y (launched at 0.1 m/s along x and −0.05 m/s along y).
  rod.add<GeneralConstraint>(0, std::array<bool, 3>{false, false, true}, 0, std::array<bool, 3>{});
  rod.add<GeneralConstraint>(10, std::array<bool, 3>{false, false, true}, 9, std::array<bool, 3>{});
  rod.add<Gravity>(Eigen::Vector3d(0, 0, -9.81));
  rod.mutable_state().velocities.row(0).setConstant(0.1);
  rod.mutable_state().velocities.row(1).setConstant(-0.05);
  rod.state_changed();
  ASSERT_TRUE(rod.advance(2000));  // 0.2 s: 2 cm along x, −1 cm along y
  EXPECT_EQ(rod.state().positions(2, 0), 0.0);
  EXPECT_EQ(rod.state().positions(2, 10), 0.0);
  EXPECT_LT(rod.state().positions(2, 5), -1e-4);
  // The sag also draws the ends inwards by equal amounts; their mean x moves with the launch.
  const double start_x = rod.state().positions(0, 0);
  const double end_x = rod.state().positions(0, 10) - rod.model().rest_lengths.sum();
  EXPECT_NEAR(0.5 * (start_x + end_x), 0.02, 2e-3);
  EXPECT_GT(start_x, 0.02);  // inwards, on top of the launch
  EXPECT_LT(end_x, 0.02);
  for (int j : {0, 10}) EXPECT_NEAR(rod.state().positions(1, j), -0.01, 1e-3) << "node " << j;
}

TEST(Boundary, FixedEndWithGivenFrameClampsIt) {
  RodSpec spec;
  spec.n_elements = 8;
  spec.time_step = 1e-4;
  Rod rod(spec);
  const Eigen::Matrix3d frame = rod.state().director(0);
  rod.add<FixedEnd>(Eigen::Vector3d(0, 0, 0), frame);
  rod.add<Gravity>(Eigen::Vector3d(0, 0, -9.81));
  ASSERT_TRUE(rod.advance(1000));
  EXPECT_EQ(rod.state().positions.col(0), Eigen::Vector3d::Zero());
  EXPECT_LT((rod.state().director(0) - frame).norm(), 1e-15);
  EXPECT_LT(rod.tip_position().z(), -1e-4) << "the free end sags";
}

}  // namespace
}  // namespace tendril::physics
