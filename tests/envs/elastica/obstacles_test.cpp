#include "tendril/envs/elastica/obstacles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tendril::envs::elastica {
namespace {

// SPEC M2 case 3: eight posts of radius 0.1 m along +y, a wall at x = −0.4 with one opening.
TEST(Obstacles, StructuredWallHasOneGapOfSeventeenCentimetres) {
  const auto wall = structured_wall();
  ASSERT_EQ(wall.size(), 8u);
  std::vector<double> wall_z;
  for (const auto& post : wall) {
    EXPECT_EQ(post.radius, 0.1);
    EXPECT_EQ(post.length, 1.0);
    EXPECT_EQ(post.axis, Eigen::Vector3d::UnitY());
    EXPECT_EQ(post.start.y(), 0.0);
    if (post.start.x() == -0.4) wall_z.push_back(post.start.z());
  }
  ASSERT_EQ(wall_z.size(), 6u);
  std::sort(wall_z.begin(), wall_z.end());
  std::vector<double> openings;
  for (std::size_t i = 1; i < wall_z.size(); ++i) {
    const double opening = wall_z[i] - wall_z[i - 1] - 2 * 0.1;
    if (opening > 1e-9) openings.push_back(opening);
  }
  ASSERT_EQ(openings.size(), 1u);
  EXPECT_NEAR(openings[0], 0.17, 1e-12);
}

// SPEC M2 case 4: α, β ~ U(π/3, 2π/3), axis (cos α cos β, −sin α, cos α sin β), start
// x ~ U(−0.55, −0.40), z ~ U(t_z − 0.5, t_z + 0.5), midpoint at the target's height.
TEST(Obstacles, UnstructuredNestFollowsTheDrawingRule) {
  const Eigen::Vector3d target(-0.8, 0.5, 0.35);
  for (uint64_t seed : {0ull, 1ull, 77ull}) {
    const auto nest = unstructured_nest(target, seed);
    ASSERT_EQ(nest.size(), 12u);
    for (const auto& rod : nest) {
      EXPECT_EQ(rod.radius, 0.03);
      EXPECT_EQ(rod.length, 1.0);
      EXPECT_NEAR(rod.axis.norm(), 1.0, 1e-14);
      // Recover α and β from the axis and check their range.
      const double alpha = std::asin(-rod.axis.y());  // in [π/3, π/2]; cos α sign below
      EXPECT_GE(alpha, std::numbers::pi / 3 - 1e-12);
      const double cos_alpha = std::hypot(rod.axis.x(), rod.axis.z());
      EXPECT_NEAR(cos_alpha, std::cos(alpha), 1e-12);
      // β ∈ [π/3, 2π/3] ⇒ sin β ≥ sin 60°: |axis_z| ≥ sin 60° · |cos α|.
      EXPECT_GE(std::abs(rod.axis.z()), std::sin(std::numbers::pi / 3) * cos_alpha - 1e-12);
      EXPECT_GE(rod.start.x(), -0.55);
      EXPECT_LT(rod.start.x(), -0.40);
      EXPECT_GE(rod.start.z(), target.z() - 0.5);
      EXPECT_LT(rod.start.z(), target.z() + 0.5);
      EXPECT_NEAR((rod.start + 0.5 * rod.length * rod.axis).y(), target.y(), 1e-14);
    }
  }
}

TEST(Obstacles, UnstructuredNestIsFixedBySeed) {
  const Eigen::Vector3d target(-0.8, 0.5, 0.35);
  const auto first = unstructured_nest(target, 3), again = unstructured_nest(target, 3);
  const auto other = unstructured_nest(target, 4);
  for (std::size_t k = 0; k < first.size(); ++k) {
    EXPECT_EQ(first[k].start, again[k].start);
    EXPECT_EQ(first[k].axis, again[k].axis);
  }
  EXPECT_NE(first[0].start, other[0].start);
  // The axes are spread: not all the same direction.
  EXPECT_GT((first[0].axis - first[1].axis).norm(), 1e-3);
}

}  // namespace
}  // namespace tendril::envs::elastica
