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
  constexpr double kPi = std::numbers::pi;
  const Eigen::Vector3d target(-0.8, 0.5, 0.35);
  double alpha_min = kPi, alpha_max = 0.0, beta_min = kPi, beta_max = 0.0;
  for (uint64_t seed : {0ull, 1ull, 77ull}) {
    const auto nest = unstructured_nest(target, seed);
    ASSERT_EQ(nest.size(), 12u);
    for (const auto& rod : nest) {
      EXPECT_EQ(rod.radius, 0.03);
      EXPECT_EQ(rod.length, 1.0);
      EXPECT_NEAR(rod.axis.norm(), 1.0, 1e-14);
      // Recover α and β from the axis: sin β > 0 on [π/3, 2π/3], so cos α has the sign of
      // axis_z; then (axis_x, axis_z) / cos α = (cos β, sin β).
      const double cos_alpha = std::copysign(std::hypot(rod.axis.x(), rod.axis.z()), rod.axis.z());
      const double alpha = std::atan2(-rod.axis.y(), cos_alpha);
      const double beta = std::atan2(rod.axis.z() / cos_alpha, rod.axis.x() / cos_alpha);
      EXPECT_GE(alpha, kPi / 3 - 1e-12);
      EXPECT_LE(alpha, 2 * kPi / 3 + 1e-12);
      EXPECT_GE(beta, kPi / 3 - 1e-9);
      EXPECT_LE(beta, 2 * kPi / 3 + 1e-9);
      // The axis is rebuilt exactly from the recovered angles (the sign pattern of the rule).
      const Eigen::Vector3d rebuilt(std::cos(alpha) * std::cos(beta), -std::sin(alpha),
                                    std::cos(alpha) * std::sin(beta));
      EXPECT_LT((rebuilt - rod.axis).norm(), 1e-12);
      alpha_min = std::min(alpha_min, alpha);
      alpha_max = std::max(alpha_max, alpha);
      beta_min = std::min(beta_min, beta);
      beta_max = std::max(beta_max, beta);
      EXPECT_GE(rod.start.x(), -0.55);
      EXPECT_LT(rod.start.x(), -0.40);
      EXPECT_GE(rod.start.z(), target.z() - 0.5);
      EXPECT_LT(rod.start.z(), target.z() + 0.5);
      EXPECT_NEAR((rod.start + 0.5 * rod.length * rod.axis).y(), target.y(), 1e-14);
    }
  }
  // 36 uniform draws cover both angles' ranges: each extreme within 0.3 rad of its bound
  // (a miss has probability (1 − 0.3/(π/3))³⁶ ≈ 5·10⁻⁶ per bound).
  EXPECT_LT(alpha_min, kPi / 3 + 0.3);
  EXPECT_GT(alpha_max, 2 * kPi / 3 - 0.3);
  EXPECT_LT(beta_min, kPi / 3 + 0.3);
  EXPECT_GT(beta_max, 2 * kPi / 3 - 0.3);
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
