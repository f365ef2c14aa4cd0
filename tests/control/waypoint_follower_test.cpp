#include "tendril/control/waypoint_follower.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"

namespace tendril::control {
namespace {

Eigen::Matrix2Xd line() {
  Eigen::Matrix2Xd points(2, 3);
  points << 0, 20, 40, 0, 0, 0;
  return points;
}

TEST(WaypointFollower, AdvancesWithinTenDegreesOneWaypointPerStep) {
  WaypointFollower follower(line());
  EXPECT_EQ(follower.goal(), Eigen::Vector2d(0, 0));
  // index_after tells where update would go without going there.
  EXPECT_EQ(follower.index_after(Eigen::Vector2d(5, 0)), 1);
  EXPECT_EQ(follower.index_after(Eigen::Vector2d(10, 0)), 0);
  EXPECT_EQ(follower.index(), 0);
  EXPECT_EQ(follower.update(Eigen::Vector2d(5, 0)), Eigen::Vector2d(20, 0));   // 5° < 10°
  EXPECT_EQ(follower.update(Eigen::Vector2d(5, 0)), Eigen::Vector2d(20, 0));   // 15° away
  EXPECT_EQ(follower.update(Eigen::Vector2d(10, 0)), Eigen::Vector2d(20, 0));  // 10° is not within
  EXPECT_EQ(follower.update(Eigen::Vector2d(12, 3)), Eigen::Vector2d(40, 0));
  EXPECT_EQ(follower.index(), 2);
  EXPECT_FALSE(follower.finished());
  EXPECT_EQ(follower.index_after(Eigen::Vector2d(39, 0)), 3);
  EXPECT_EQ(follower.update(Eigen::Vector2d(39, 0)), Eigen::Vector2d(40, 0));  // holds the end
  EXPECT_TRUE(follower.finished());
  EXPECT_EQ(follower.index_after(Eigen::Vector2d(40, 0)), 3);
  follower.restart();
  EXPECT_EQ(follower.index(), 0);
  EXPECT_EQ(follower.goal(), Eigen::Vector2d(0, 0));
}

TEST(WaypointFollower, RejectsEmptyPathsAndBadTolerances) {
  EXPECT_THROW(WaypointFollower(Eigen::Matrix2Xd(2, 0)), Error);
  EXPECT_THROW(WaypointFollower(line(), 0.0), Error);
}

}  // namespace
}  // namespace tendril::control
