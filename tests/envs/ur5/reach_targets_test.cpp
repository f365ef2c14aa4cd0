// Target sampling for UR5/Reach-v0: the segment–box test and the rejection rules.
#include "tendril/envs/ur5/reach_targets.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "tendril/core/error.hpp"

namespace tendril::envs::ur5 {
namespace {

const Eigen::Vector3d kCentre(0.40, 0.0, 0.10);
const Eigen::Vector3d kHalf(0.05, 0.20, 0.10);

TEST(ReachTargets, SegmentBoxTestOnHandPlacedSegments) {
  // Straight through the middle, over the top, beside it, ending in front of it, and starting
  // inside it.
  EXPECT_TRUE(segment_hits_box({0.2, 0, 0.1}, {0.6, 0, 0.1}, kCentre, kHalf));
  EXPECT_FALSE(segment_hits_box({0.2, 0, 0.25}, {0.6, 0, 0.25}, kCentre, kHalf));
  EXPECT_FALSE(segment_hits_box({0.2, 0.3, 0.1}, {0.6, 0.3, 0.1}, kCentre, kHalf));
  EXPECT_FALSE(segment_hits_box({0.2, 0, 0.1}, {0.34, 0, 0.1}, kCentre, kHalf));
  EXPECT_TRUE(segment_hits_box({0.4, 0, 0.1}, {0.4, 0, 0.9}, kCentre, kHalf));
  // Diagonal: enters the front face at x = 0.35 where z = 0.1 + 0.5·0.18 = 0.19 < 0.2 ...
  EXPECT_TRUE(segment_hits_box({0.2, 0, 0.1}, {0.5, 0, 0.28}, kCentre, kHalf));
  // ... and passes over it when the target is higher: z = 0.21 at x = 0.35, 0.28 at x = 0.45.
  EXPECT_FALSE(segment_hits_box({0.2, 0, 0.1}, {0.5, 0, 0.32}, kCentre, kHalf));
}

TEST(ReachTargets, DistanceToTheBoxIsEuclideanOutsideAndZeroInside) {
  EXPECT_DOUBLE_EQ(distance_to_box({0.4, 0.0, 0.1}, kCentre, kHalf), 0.0);
  EXPECT_NEAR(distance_to_box({0.55, 0.0, 0.1}, kCentre, kHalf), 0.10, 1e-15);
  EXPECT_NEAR(distance_to_box({0.48, 0.23, 0.24}, kCentre, kHalf),
              std::sqrt(0.03 * 0.03 + 0.03 * 0.03 + 0.04 * 0.04), 1e-15);
}

TEST(ReachTargets, SampledTargetsKeepEveryRule) {
  const TargetRegion region;
  const Eigen::Vector3d start(0.2, 0.0, 0.1);
  const Eigen::Vector3d shoulder(0.0, 0.0, 0.089159);
  Rng rng(17);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d target = sample_target(region, start, kCentre, kHalf, rng);
    ASSERT_TRUE((target.array() >= region.low.array()).all() &&
                (target.array() <= region.high.array()).all());
    ASSERT_GT(distance_to_box(target, kCentre, kHalf), region.obstacle_margin);
    ASSERT_LE((target - shoulder).norm(), region.max_reach);
    ASSERT_TRUE(segment_hits_box(start, target, kCentre, kHalf));
  }
}

TEST(ReachTargets, ARegionTheBoxCannotHideIsAnError) {
  TargetRegion region;
  region.low = Eigen::Vector3d(0.5, -0.2, 0.5);  // far above the 0.2 m box
  region.high = Eigen::Vector3d(0.6, 0.2, 0.6);
  Rng rng(1);
  EXPECT_THROW(sample_target(region, {0.2, 0.0, 0.1}, kCentre, kHalf, rng), Error);
}

TEST(ReachTargets, RegionIsReadFromParams) {
  const Config params = Config::parse("{target_low: [0.5, -0.1, 0.2], target_max_reach: 0.7}");
  const TargetRegion region = TargetRegion::from_config(params);
  EXPECT_EQ(region.low, Eigen::Vector3d(0.5, -0.1, 0.2));
  EXPECT_EQ(region.high, TargetRegion().high);
  EXPECT_EQ(region.max_reach, 0.7);
  const Config bad = Config::parse("{target_high: [0.5, 0.1]}", "exp.yaml");
  EXPECT_NE(testing::error_message([&] { TargetRegion::from_config(bad); }).find("target_high"),
            std::string::npos);
  const Config crossed = Config::parse("{target_low: [0.9, 0, 0]}", "exp.yaml");
  EXPECT_THROW(TargetRegion::from_config(crossed), Error);
}

}  // namespace
}  // namespace tendril::envs::ur5
