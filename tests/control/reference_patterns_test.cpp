#include "tendril/control/reference_patterns.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"

namespace tendril::control {
namespace {

double max_gap(const Eigen::Matrix2Xd& points) {
  double gap = 0.0;
  for (Eigen::Index i = 1; i < points.cols(); ++i)
    gap = std::max(gap, (points.col(i) - points.col(i - 1)).norm());
  return gap;
}

TEST(ReferencePatterns, EveryPatternIsDenseAndInsideTheGoalRange) {
  for (const std::string& name : reference_pattern_names()) {
    const Eigen::Matrix2Xd points = reference_pattern(name);
    EXPECT_GE(points.cols(), 20) << name;
    EXPECT_LE(max_gap(points), 5.0 + 1e-9) << name;
    EXPECT_LE(points.cwiseAbs().maxCoeff(), 75.0) << name;
  }
  EXPECT_THROW(reference_pattern("triangle"), Error);
}

TEST(ReferencePatterns, ShapesAreWhereTheDocumentationSays) {
  const Eigen::Matrix2Xd circle = reference_pattern("circle");
  for (Eigen::Index i = 0; i < circle.cols(); ++i)
    EXPECT_NEAR(circle.col(i).norm(), 40.0, 1e-12) << i;
  EXPECT_NEAR((circle.col(0) - circle.col(circle.cols() - 1)).norm(), 0.0, 1e-12);  // closed

  const Eigen::Matrix2Xd square = reference_pattern("square");
  EXPECT_EQ(square.col(0), Eigen::Vector2d(40, -40));
  EXPECT_EQ(square.col(square.cols() - 1), Eigen::Vector2d(40, -40));
  EXPECT_NEAR(square.cwiseAbs().colwise().maxCoeff().minCoeff(), 40.0, 1e-12);  // on the edges

  const Eigen::Matrix2Xd spiral = reference_pattern("spiral");
  EXPECT_EQ(spiral.col(0), Eigen::Vector2d(0, 0));
  EXPECT_NEAR(spiral.col(spiral.cols() - 1).norm(), 50.0, 1e-9);

  const Eigen::Matrix2Xd sml = reference_pattern("sml");
  EXPECT_EQ(sml.col(0), Eigen::Vector2d(-35, 20));               // S from its top right
  EXPECT_EQ(sml.col(sml.cols() - 1), Eigen::Vector2d(65, -20));  // L ends bottom right
}

TEST(ReferencePatterns, DensifyKeepsTheCorners) {
  Eigen::Matrix2Xd corners(2, 3);
  corners << 0, 12, 12, 0, 0, 3;
  const Eigen::Matrix2Xd points = densify(corners, 5.0);
  ASSERT_EQ(points.cols(), 5);  // 0, 4, 8, 12 on the first edge, then (12, 3)
  EXPECT_TRUE(points.col(1).isApprox(Eigen::Vector2d(4, 0)));
  EXPECT_EQ(points.col(3), Eigen::Vector2d(12, 0));
  EXPECT_EQ(points.col(4), Eigen::Vector2d(12, 3));
}

TEST(ReferencePatterns, DistanceToThePathAndItsRmse) {
  Eigen::Matrix2Xd path(2, 2);
  path << -10, 10, 0, 0;
  EXPECT_DOUBLE_EQ(distance_to_path(Eigen::Vector2d(0, 10), path), 10.0);
  EXPECT_DOUBLE_EQ(distance_to_path(Eigen::Vector2d(13, 4), path), 5.0);  // past the end
  Eigen::Matrix2Xd trajectory(2, 2);
  trajectory << 0, 5, 3, -4;  // 3° and 4° off: sqrt((9 + 16) / 2)
  EXPECT_DOUBLE_EQ(tracking_rmse(trajectory, path), std::sqrt(12.5));
}

}  // namespace
}  // namespace tendril::control
