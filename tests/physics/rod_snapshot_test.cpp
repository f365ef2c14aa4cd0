#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "tendril/physics/arms/elastica_arm.hpp"
#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::physics {
namespace {

// Case 3's arm: rate-limited muscles (state carried between steps inside the part) and contact.
ElasticaArm actuated_arm() {
  ElasticaArm arm = build_elastica_arm(ElasticaArmSpec::structured_obstacles());
  Eigen::VectorXd targets(2);
  targets << 0.9, -0.7;
  arm.muscles->set_targets(targets);
  return arm;
}

void expect_same_state(const Rod& a, const Rod& b) {
  EXPECT_EQ(a.state().positions, b.state().positions);
  EXPECT_EQ(a.state().velocities, b.state().velocities);
  EXPECT_EQ(a.state().directors, b.state().directors);
  EXPECT_EQ(a.state().angular_velocities, b.state().angular_velocities);
  EXPECT_EQ(a.time(), b.time());
}

TEST(RodSnapshot, SteppingOnFromALoadedStateRepeatsTheOriginalBitForBit) {
  ElasticaArm original = actuated_arm();
  ASSERT_TRUE(original.rod.advance(30));  // the control points are still moving (0.01 per step)
  ASSERT_NE(original.muscles->current(), Eigen::Vector2d(0.9, -0.7));
  Snapshot bytes;
  SnapshotWriter out(bytes);
  original.rod.save_state(out);

  ElasticaArm copy = build_elastica_arm(ElasticaArmSpec::structured_obstacles());
  SnapshotReader in(bytes);
  copy.rod.load_state(in);
  EXPECT_TRUE(in.at_end());
  EXPECT_EQ(copy.muscles->current(), original.muscles->current());
  // The strains the read-outs use are recomputed on load.
  EXPECT_EQ(copy.rod.curvatures(), original.rod.curvatures());

  for (int chunk = 0; chunk < 5; ++chunk) {
    ASSERT_TRUE(original.rod.advance(14));
    ASSERT_TRUE(copy.rod.advance(14));
  }
  expect_same_state(copy.rod, original.rod);
  EXPECT_EQ(copy.muscles->current(), original.muscles->current());
}

TEST(RodSnapshot, WithoutThePartsStateTheRunWouldDiffer) {
  // The control points' state matters: a copy that got only the rod's configuration (its
  // muscles starting from rest) drifts apart. Guards the test above against vacuity.
  ElasticaArm original = actuated_arm();
  ASSERT_TRUE(original.rod.advance(30));
  ElasticaArm copy = build_elastica_arm(ElasticaArmSpec::structured_obstacles());
  copy.rod.mutable_state() = original.rod.state();
  copy.rod.state_changed();
  Eigen::VectorXd targets(2);
  targets << 0.9, -0.7;
  copy.muscles->set_targets(targets);
  ASSERT_TRUE(original.rod.advance(14));
  ASSERT_TRUE(copy.rod.advance(14));
  EXPECT_NE(copy.rod.state().positions, original.rod.state().positions);
}

TEST(RodSnapshot, AnotherRodIsRefusedAndNothingChanges) {
  ElasticaArm arm = actuated_arm();
  ASSERT_TRUE(arm.rod.advance(10));
  Snapshot bytes;
  SnapshotWriter out(bytes);
  arm.rod.save_state(out);

  ElasticaArm other = build_elastica_arm(ElasticaArmSpec::tracking());  // 20 elements
  const RodState before = other.rod.state();
  SnapshotReader in(bytes);
  EXPECT_EQ(testing::error_message([&] { other.rod.load_state(in); }),
            "Rod::load_state: snapshot of a rod with 50 elements and 4 parts; this rod has 20 "
            "and 3");
  EXPECT_EQ(other.rod.state().positions, before.positions);

  // A snapshot cut short inside the muscles' section: the rod is put back as it was.
  ElasticaArm same = build_elastica_arm(ElasticaArmSpec::structured_obstacles());
  const RodState same_before = same.rod.state();
  SnapshotReader truncated(std::span<const std::byte>(bytes).first(bytes.size() - 8));
  EXPECT_EQ(testing::error_message([&] { same.rod.load_state(truncated); }),
            "snapshot section 'SplineActuation': the snapshot ends early");
  EXPECT_EQ(same.rod.state().positions, same_before.positions);
  EXPECT_EQ(same.rod.state().velocities, same_before.velocities);
  EXPECT_EQ(same.muscles->current(), Eigen::VectorXd::Zero(2));
}

}  // namespace
}  // namespace tendril::physics
