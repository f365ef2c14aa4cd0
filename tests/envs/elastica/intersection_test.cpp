#include "tendril/envs/elastica/intersection.hpp"

#include <gtest/gtest.h>

#include "tendril/physics/rod/rod_spec.hpp"

namespace tendril::envs::elastica {
namespace {

using physics::Cylinder;

// A post of radius 0.1 m along +y from the origin, 1 m long.
const Cylinder kPost{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY(), 1.0, 0.1};

TEST(Intersection, HandPlacedSegmentsAgainstAPost) {
  const double r = 0.05;  // the arm's radius: capsules meet at 0.15 m from the axis
  // Parallel to the axis at 14 cm: overlapping; at 16 cm: clear.
  EXPECT_TRUE(capsules_intersect({0.14, 0.2, 0.0}, {0.14, 0.4, 0.0}, r, kPost));
  EXPECT_FALSE(capsules_intersect({0.16, 0.2, 0.0}, {0.16, 0.4, 0.0}, r, kPost));
  // Crossing the axis, and crossing it with both ends far away.
  EXPECT_TRUE(capsules_intersect({-1.0, 0.5, 0.0}, {1.0, 0.5, 0.0}, r, kPost));
  EXPECT_TRUE(capsules_intersect({-1.0, 0.5, -1.0}, {1.0, 0.5, 1.0}, r, kPost));
  // Skew, passing 0.12 m in front of the axis (z = 0.12): inside; 0.2 m: clear.
  EXPECT_TRUE(capsules_intersect({-1.0, 0.3, 0.12}, {1.0, 0.7, 0.12}, r, kPost));
  EXPECT_FALSE(capsules_intersect({-1.0, 0.3, 0.2}, {1.0, 0.7, 0.2}, r, kPost));
  // Beyond the top end (y = 1): the end is rounded, so 0.1 m above it intersects, 0.2 m not.
  EXPECT_TRUE(capsules_intersect({-1.0, 1.1, 0.0}, {1.0, 1.1, 0.0}, r, kPost));
  EXPECT_FALSE(capsules_intersect({-1.0, 1.2, 0.0}, {1.0, 1.2, 0.0}, r, kPost));
  // A short segment ending just before the post's surface: 0.16 m from the axis, clear.
  EXPECT_FALSE(capsules_intersect({0.5, 0.5, 0.0}, {0.16, 0.5, 0.0}, r, kPost));
  EXPECT_TRUE(capsules_intersect({0.5, 0.5, 0.0}, {0.14, 0.5, 0.0}, r, kPost));
}

TEST(Intersection, CountsEachIntersectingElementOnce) {
  // Case 3's arm: 50 elements of 2 cm along +z from (0, 0.5, 0).
  physics::RodSpec spec;
  spec.n_elements = 50;
  spec.base_position = Eigen::Vector3d(0.0, 0.5, 0.0);
  spec.direction = Eigen::Vector3d::UnitZ();
  spec.normal = Eigen::Vector3d::UnitY();
  const physics::Rod rod(spec);
  EXPECT_EQ(intersecting_elements(rod, 0.05, {}), 0);

  // A post along y at x = 0.12, z = 0.5: an element [z, z + 0.02] intersects iff it comes
  // within √(0.15² − 0.12²) = 0.09 m of z = 0.5, i.e. elements 20 … 29 ([0.40, 0.60]).
  const Cylinder post{Eigen::Vector3d(0.12, 0.0, 0.5), Eigen::Vector3d::UnitY(), 1.0, 0.1};
  EXPECT_EQ(intersecting_elements(rod, 0.05, {post}), 10);
  // A second post overlapping the same elements adds nothing; one at the tip adds its own.
  const Cylinder twin{Eigen::Vector3d(-0.12, 0.0, 0.5), Eigen::Vector3d::UnitY(), 1.0, 0.1};
  EXPECT_EQ(intersecting_elements(rod, 0.05, {post, twin}), 10);
  const Cylinder tip_post{Eigen::Vector3d(0.0, 0.0, 1.06), Eigen::Vector3d::UnitY(), 1.0, 0.1};
  // Elements reaching within 0.15 m of z = 1.06, i.e. beyond z = 0.91: elements 45 … 49.
  EXPECT_EQ(intersecting_elements(rod, 0.05, {post, twin, tip_post}), 15);
  // A post clear of the rod.
  const Cylinder clear{Eigen::Vector3d(0.3, 0.0, 0.5), Eigen::Vector3d::UnitY(), 1.0, 0.1};
  EXPECT_EQ(intersecting_elements(rod, 0.05, {clear}), 0);
}

}  // namespace
}  // namespace tendril::envs::elastica
