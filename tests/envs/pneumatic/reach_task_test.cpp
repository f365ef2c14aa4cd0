#include "tendril/envs/pneumatic/reach_task.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::envs::pneumatic {
namespace {

// The paper's main setting (Sec. V-C1): goal [−30, −120, −620], plate x ∈ [−60, 60],
// y ∈ [−55, −50], z ∈ [−700, −570]; B x ∈ [−130, 90], y ∈ [−150, 50], z ∈ [−700, −570].
const ReachTaskSpec kMain = ReachTaskSpec::preset("main");

ReachOutcome at(const Eigen::Vector3d& tip) { return evaluate_reach_step(kMain, tip, tip); }

TEST(ReachTask, ClearOfEverythingOnlyTheStepAndGoalDistanceCount) {
  const ReachOutcome out = at({-100.0, 0.0, -620.0});
  // O_dist: 40 mm beyond the plate's x edge and 50 mm in front of its face.
  EXPECT_NEAR(out.obstacle_distance, std::hypot(40.0, 50.0), 1e-12);
  EXPECT_NEAR(out.goal_distance, std::hypot(70.0, 120.0), 1e-12);
  EXPECT_NEAR(out.reward, -2.0 - std::hypot(70.0, 120.0), 1e-12);
  EXPECT_FALSE(out.collision || out.warning || out.outside || out.success || out.ends_episode);
}

TEST(ReachTask, TheWarningBandCostsFiveTimesTheIntrusion) {
  const ReachOutcome out = at({-75.0, -52.0, -620.0});  // 15 mm beside the plate's edge
  EXPECT_NEAR(out.obstacle_distance, 15.0, 1e-12);
  EXPECT_TRUE(out.warning);
  EXPECT_FALSE(out.collision);
  const double goal = std::hypot(45.0, 68.0);
  EXPECT_NEAR(out.reward, -2.0 - 5.0 * (20.0 - 15.0) - goal, 1e-12);
  EXPECT_FALSE(out.ends_episode);
  // The band is 10 < O_dist ≤ 20: at 20 mm the penalty is 0, at 10 mm it is a collision.
  EXPECT_TRUE(at({-80.0, -52.0, -620.0}).warning);
  EXPECT_NEAR(at({-80.0, -52.0, -620.0}).reward, -2.0 - std::hypot(50.0, 68.0), 1e-12);
  EXPECT_FALSE(at({-80.5, -52.0, -620.0}).warning);
  EXPECT_TRUE(at({-70.0, -52.0, -620.0}).collision);
}

TEST(ReachTask, ACollisionIsWithinTenMillimetresOrACrossingOfThePlate) {
  const ReachOutcome near = at({-68.0, -52.0, -620.0});
  EXPECT_TRUE(near.collision);
  EXPECT_TRUE(near.ends_episode);
  EXPECT_NEAR(near.reward, -2.0 - 10000.0 - std::hypot(38.0, 68.0), 1e-9);
  // Straight through the plate in one step: both ends are 45 mm clear of it.
  const ReachOutcome through =
      evaluate_reach_step(kMain, {0.0, 0.0, -620.0}, {0.0, -100.0, -620.0});
  EXPECT_NEAR(through.obstacle_distance, 45.0, 1e-12);
  EXPECT_TRUE(through.collision);
  EXPECT_TRUE(through.ends_episode);
  // Past its edge, or over its top, is no collision.
  EXPECT_FALSE(
      evaluate_reach_step(kMain, {-100.0, 0.0, -620.0}, {-100.0, -100.0, -620.0}).collision);
  EXPECT_FALSE(evaluate_reach_step(kMain, {0.0, 0.0, -550.0}, {0.0, -100.0, -550.0}).collision);
  EXPECT_FALSE(
      evaluate_reach_step(ReachTaskSpec::preset("G1"), {0.0, 0.0, -600.0}, {0.0, -100.0, -600.0})
          .collision);  // G1's plate ends at z = −610
}

TEST(ReachTask, LeavingTheBoundaryCostsAHundredAndEndsTheEpisode) {
  const ReachOutcome out = at({100.0, 0.0, -620.0});
  EXPECT_TRUE(out.outside);
  EXPECT_TRUE(out.ends_episode);
  EXPECT_NEAR(out.reward, -2.0 - 100.0 - std::hypot(130.0, 120.0), 1e-12);
  for (const Eigen::Vector3d& tip :
       {Eigen::Vector3d(-131, 0, -620), Eigen::Vector3d(0, 51, -620),
        Eigen::Vector3d(0, -151, -620), Eigen::Vector3d(0, 0, -701), Eigen::Vector3d(0, 0, -569)}) {
    EXPECT_TRUE(at(tip).outside) << tip.transpose();
  }
  EXPECT_FALSE(at({90.0, 50.0, -570.0}).outside);  // B is closed
  ReachTaskSpec lenient = kMain;
  lenient.terminate_outside_boundary = false;
  const ReachOutcome kept = evaluate_reach_step(lenient, {100, 0, -620}, {100, 0, -620});
  EXPECT_TRUE(kept.outside);
  EXPECT_FALSE(kept.ends_episode);
}

TEST(ReachTask, WithinFiveMillimetresTheGoalIsReached) {
  const ReachOutcome out = at({-27.0, -124.0, -620.0});
  EXPECT_NEAR(out.goal_distance, 5.0, 1e-12);
  EXPECT_TRUE(out.success);
  EXPECT_TRUE(out.ends_episode);
  EXPECT_EQ(out.reward, -2.0);
  const ReachOutcome short_of = at({-27.0, -124.01, -620.0});
  EXPECT_FALSE(short_of.success);
  EXPECT_NEAR(short_of.reward, -2.0 - short_of.goal_distance, 1e-12);
}

// The paper's formula n·V/|n| measures to the plate's infinite plane: beside the plate, where
// the box distance is 40 mm, the plane distance is 0 and the tip collides.
TEST(ReachTask, ThePlaneDistanceIsTheSeedsFormula) {
  ReachTaskSpec plane = kMain;
  plane.obstacle_distance = ReachTaskSpec::ObstacleDistance::kPlane;
  EXPECT_NEAR(obstacle_distance(plane, {-100.0, -52.0, -620.0}), 0.0, 1e-12);
  EXPECT_NEAR(obstacle_distance(plane, {-100.0, -20.0, -620.0}), 30.0, 1e-12);
  EXPECT_NEAR(obstacle_distance(plane, {500.0, -75.0, -620.0}), 20.0, 1e-12);
  EXPECT_NEAR(obstacle_distance(kMain, {-100.0, -52.0, -620.0}), 40.0, 1e-12);
}

TEST(ReachTask, SegmentsMeetBoxesWhereTheyShould) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1));
  EXPECT_TRUE(segment_meets_box(box, {0.5, 0.5, 0.5}, {0.6, 0.6, 0.6}));   // inside
  EXPECT_TRUE(segment_meets_box(box, {-1, 0.5, 0.5}, {2, 0.5, 0.5}));      // through
  EXPECT_TRUE(segment_meets_box(box, {-1, -1, 0.5}, {1, 1, 0.5}));         // through a corner
  EXPECT_FALSE(segment_meets_box(box, {-1, 0.5, 0.5}, {-0.1, 0.5, 0.5}));  // stops short
  EXPECT_FALSE(segment_meets_box(box, {-1, 0, 0.5}, {0.5, 1.6, 0.5}));     // passes the corner
  EXPECT_FALSE(segment_meets_box(box, {2, 2, 2}, {2, 2, 2}));              // a point outside
}

TEST(ReachTask, PresetsAreThePapersSettings) {
  const ReachTaskSpec g3 = ReachTaskSpec::preset("G3");
  EXPECT_EQ(g3.goal, Eigen::Vector3d(-45, -100, -645));
  EXPECT_EQ(g3.obstacle.max().z(), -570.0);
  EXPECT_EQ(ReachTaskSpec::preset("G1").goal, Eigen::Vector3d(50, -100, -620));
  EXPECT_EQ(ReachTaskSpec::preset("G2").obstacle.max().z(), -610.0);
  EXPECT_EQ(ReachTaskSpec::relaxed_boundary().min(), Eigen::Vector3d(-170, -170, -700));
  EXPECT_THROW(ReachTaskSpec::preset("G4"), Error);
}

}  // namespace
}  // namespace tendril::envs::pneumatic
