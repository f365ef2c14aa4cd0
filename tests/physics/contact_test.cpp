// Soft-wall contact with planes and cylinders.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "rod_test_support.hpp"
#include "tendril/core/error.hpp"
#include "tendril/physics/contact/cylinder_contact.hpp"
#include "tendril/physics/contact/segment_distance.hpp"
#include "tendril/physics/forcing/loads.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::physics {
namespace {

using testing::add_uniform_damping;
using testing::settle;

constexpr double kGravity = 9.81;

// A free horizontal rod along x whose lowest line starts just touching z = 0.
RodSpec lying_rod() {
  RodSpec spec;
  spec.n_elements = 10;
  spec.length = 1.0;
  spec.radius = 0.05;
  spec.density = 1000.0;
  spec.youngs_modulus = 1.0e6;
  spec.direction = Eigen::Vector3d::UnitX();
  spec.normal = Eigen::Vector3d::UnitZ();
  spec.base_position = Eigen::Vector3d(0.0, 0.0, spec.radius);
  spec.time_step = 1.0e-4;
  return spec;
}

double expected_penalty_penetration(const RodSpec& spec, double stiffness) {
  const double element_weight = spec.density * std::numbers::pi * spec.radius * spec.radius *
                                spec.length / spec.n_elements * kGravity;
  return element_weight / stiffness;  // k ε = weight carried by each element
}

// Lowest height of the centreline above z = 0 seen while settling.
double settle_tracking_height(Rod& rod, double max_time) {
  double lowest = INFINITY;
  const int chunk = 20;
  while (rod.time() < max_time) {
    EXPECT_TRUE(rod.advance(chunk));
    lowest = std::min(lowest, rod.state().positions.row(2).minCoeff());
    if (rod.state().velocities.colwise().norm().maxCoeff() < 1e-7 && rod.time() > 0.5) break;
  }
  return lowest;
}

TEST(Contact, PenaltyPlaneSettlesWhereStiffnessBalancesWeight) {
  const RodSpec spec = lying_rod();
  Rod rod(spec);
  rod.add<Gravity>(Eigen::Vector3d(0, 0, -kGravity));
  const SoftWall wall{1.0e3, 2.0, false};
  rod.add<PlaneContact>(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), wall);
  add_uniform_damping(rod, 20.0);
  const double lowest = settle_tracking_height(rod, 10.0);
  const double expected = expected_penalty_penetration(spec, wall.stiffness);
  for (int j = 0; j <= spec.n_elements; ++j) {
    const double penetration =
        rod.state().radii[std::min(j, spec.n_elements - 1)] - rod.state().positions(2, j);
    EXPECT_NEAR(penetration, expected, 0.02 * expected) << "node " << j;
  }
  EXPECT_GT(lowest, 0.0) << "the centreline passed through the plane";
}

TEST(Contact, SeedWallCancelsThePushAndHoldsTheRodAtTheSurface) {
  const RodSpec spec = lying_rod();
  Rod rod(spec);
  rod.add<Gravity>(Eigen::Vector3d(0, 0, -kGravity));
  rod.add<PlaneContact>(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                        SoftWall{8.0e4, 4.0, true});
  add_uniform_damping(rod, 20.0);
  const double lowest = settle_tracking_height(rod, 2.0);
  // With −F_push the wall balances the weight itself; the rod rests on the surface.
  EXPECT_NEAR(rod.state().positions.row(2).mean(), spec.radius, 1e-3 * spec.radius);
  EXPECT_GT(lowest, 0.9 * spec.radius);
}

TEST(Contact, PenaltyCylinderBeneathParallelRod) {
  RodSpec spec = lying_rod();
  const double cylinder_radius = 0.1;
  spec.base_position = Eigen::Vector3d(0.0, 0.0, cylinder_radius + spec.radius);
  Rod rod(spec);
  rod.add<Gravity>(Eigen::Vector3d(0, 0, -kGravity));
  const SoftWall wall{1.0e3, 2.0, false};
  // Axis along x under the rod, longer than it: a parallel-segment contact on every element.
  rod.add<CylinderContact>(std::vector<Cylinder>{{Eigen::Vector3d(-0.5, 0, 0),
                                                  Eigen::Vector3d::UnitX(), 2.0, cylinder_radius}},
                           wall);
  add_uniform_damping(rod, 20.0);
  ASSERT_TRUE(settle(rod, 10.0, 1e-7));
  const double expected = expected_penalty_penetration(spec, wall.stiffness);
  for (int j = 0; j <= spec.n_elements; ++j) {
    const double penetration = spec.radius + cylinder_radius - rod.state().positions(2, j);
    EXPECT_NEAR(penetration, expected, 0.02 * expected) << "node " << j;
    EXPECT_NEAR(rod.state().positions(1, j), 0.0, 1e-12);
  }
}

TEST(Contact, FastRodDoesNotPassThroughThinCylinder) {
  RodSpec spec = lying_rod();
  spec.base_position = Eigen::Vector3d(-0.5, 0.0, 0.2);
  Rod rod(spec);
  const Cylinder pole{Eigen::Vector3d(0.0, -0.5, 0.0), Eigen::Vector3d::UnitY(), 1.0, 0.03};
  rod.add<CylinderContact>(std::vector<Cylinder>{pole}, SoftWall{8.0e4, 4.0, true});
  rod.mutable_state().velocities.row(2).setConstant(-2.0);  // thrown down onto the pole
  rod.state_changed();
  double closest = INFINITY;
  for (int step = 0; step < 3000; ++step) {
    ASSERT_TRUE(rod.advance(1));
    for (int i = 0; i < spec.n_elements; ++i) {
      const ClosestPoints points = closest_points_between_segments(
          rod.state().positions.col(i), rod.state().positions.col(i + 1), pole.start, pole.end());
      closest = std::min(closest, (points.on_first - points.on_second).norm());
    }
  }
  // The surfaces touch when the centrelines are pole + rod radius (8 cm) apart; the soft wall
  // lets the rod sink in by less than a centimetre.
  std::printf("closest centreline distance %.5f m\n", closest);
  EXPECT_GT(closest, pole.radius + spec.radius - 0.01) << "the rod sank deep into the cylinder";
  EXPECT_GT(rod.state().velocities.row(2).mean(), 0.0) << "the rod should bounce back up";
}

TEST(Contact, ClosestPointsBetweenSegments) {
  // Crossing segments at right angles, one above the other.
  ClosestPoints p =
      closest_points_between_segments(Eigen::Vector3d(-1, 0, 1), Eigen::Vector3d(1, 0, 1),
                                      Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(0, 1, 0));
  EXPECT_LT((p.on_first - Eigen::Vector3d(0, 0, 1)).norm(), 1e-15);
  EXPECT_LT((p.on_second - Eigen::Vector3d(0, 0, 0)).norm(), 1e-15);
  // Beyond the end of the second segment: clamped to its end point.
  p = closest_points_between_segments(Eigen::Vector3d(2, -1, 0), Eigen::Vector3d(2, 1, 0),
                                      Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0));
  EXPECT_LT((p.on_first - Eigen::Vector3d(2, 0, 0)).norm(), 1e-15);
  EXPECT_LT((p.on_second - Eigen::Vector3d(1, 0, 0)).norm(), 1e-15);
  // Parallel, overlapping: distance is the offset.
  p = closest_points_between_segments(Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 1),
                                      Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(2, 0, 0));
  EXPECT_NEAR((p.on_first - p.on_second).norm(), 1.0, 1e-15);
}

TEST(Contact, InvalidWallsAndCylindersAreRejected) {
  EXPECT_THROW(PlaneContact(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 2)), Error);
  EXPECT_THROW(
      PlaneContact(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), SoftWall{-1.0, 4.0, true}),
      Error);
  EXPECT_THROW(CylinderContact({{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY(), 1.0, 0.0}}),
               Error);
}

}  // namespace
}  // namespace tendril::physics
