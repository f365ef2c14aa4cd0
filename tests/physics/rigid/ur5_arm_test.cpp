// The position-controlled UR5 in its scene: servo behaviour, limits, contacts, the scene a
// viewer draws, snapshots and user model files.
#include "tendril/physics/rigid/ur5_arm.hpp"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <fstream>
#include <regex>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/error.hpp"

namespace tendril::physics {
namespace {

using Joints = Ur5Arm::Joints;

// Tool down, flange 0.25 m in front of the base and 0.1 m above the table (the reaching task's
// home pose).
Joints home() { return (Joints() << 2.69, -1.80, 2.76, -2.53, -1.571, 0.0).finished(); }

bool inside(const Eigen::Vector3d& point, const Eigen::Vector3d& centre,
            const Eigen::Vector3d& half_extents) {
  return ((point - centre).cwiseAbs().array() < half_extents.array()).all();
}

TEST(Ur5Arm, HoldsItsPoseAgainstGravityWhenTheTargetIsThePose) {
  Ur5Arm arm;
  arm.place(home());
  const Ur5Arm::Advance report = arm.advance(500);  // 1 s
  EXPECT_TRUE(report.stable);
  EXPECT_EQ(report.contacts, 0);
  EXPECT_LT((arm.joint_positions() - home()).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_NEAR(arm.time(), 1.0, 1e-12);
}

TEST(Ur5Arm, EachServoSettlesOnItsTargetWithoutOvershoot) {
  // With gravity cancelled each joint is a damped spring (overdamped with the default gains):
  // it approaches the target monotonically and is within 1 mrad after 1 s.
  Ur5Arm arm;
  arm.place(home());
  const Joints step = Joints::Constant(-0.1);
  arm.set_targets(home() + step);
  Joints farthest = Joints::Zero();
  for (int i = 0; i < 100; ++i) {
    ASSERT_TRUE(arm.advance(5).stable);
    farthest = farthest.cwiseMin(arm.joint_positions() - home());
  }
  EXPECT_LT((arm.joint_positions() - (home() + step)).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_GT(farthest.minCoeff(), -0.1 * 1.01);
}

TEST(Ur5Arm, TargetsAreClippedToTheJointLimits) {
  Ur5Arm arm;
  Joints wanted;
  wanted << 7.0, -7.0, 3.5, -1.0, 0.5, -100.0;
  const Joints set = arm.set_targets(wanted);
  Joints expected;
  expected << 2 * M_PI, -2 * M_PI, M_PI, -1.0, 0.5, -2 * M_PI;
  EXPECT_EQ(set, expected);
  EXPECT_EQ(arm.targets(), expected);
  for (int i = 0; i < 6; ++i) EXPECT_DOUBLE_EQ(arm.sim().data()->ctrl[i], expected[i]);
}

TEST(Ur5Arm, PlacingOutsideTheLimitsIsAnError) {
  Ur5Arm arm;
  Joints q = home();
  q[2] = 3.3;  // the elbow stops at π
  EXPECT_THROW(arm.place(q), Error);
  q[2] = NAN;
  EXPECT_THROW(arm.place(q), Error);
}

TEST(Ur5Arm, APoseWithTheFlangeInsideTheObstacleIsInContact) {
  Ur5Arm arm;
  arm.place(home());
  EXPECT_EQ(arm.contacts(), 0);
  Joints q;
  q << 2.865, -1.401, 2.381, -2.551, -1.571, -0.276;  // flange at the box's centre (by DH IK)
  arm.place(q);
  ASSERT_TRUE(inside(arm.flange_position(), arm.obstacle_centre(), arm.obstacle_half_extents()));
  EXPECT_GT(arm.contacts(), 0);
  // Advancing keeps reporting it.
  EXPECT_GT(arm.advance(1).contacts, 0);
}

TEST(Ur5Arm, APoseWithTheFlangeBelowTheTableIsInContact) {
  Ur5Arm arm;
  Joints q;
  q << 1.982, -0.908, 2.431, -3.094, -1.571, -1.159;  // flange at (0.25, −0.3, −0.05) m
  arm.place(q);
  ASSERT_LT(arm.flange_position().z(), 0.0);
  ASSERT_FALSE(inside(arm.flange_position(), arm.obstacle_centre(), arm.obstacle_half_extents()));
  EXPECT_GT(arm.contacts(), 0);
}

TEST(Ur5Arm, FoldingTheElbowIntoTheShoulderIsASelfContact) {
  // Folding the elbow fully (q₃ = π) with the wrist bent back brings the wrist onto the
  // shoulder housing; no table or obstacle is near.
  Ur5Arm arm;
  Joints q;
  q << 0.0, -1.571, M_PI, 0.0, 0.0, 0.0;
  arm.place(q);
  const mjModel* m = arm.sim().model();
  const mjData* d = arm.sim().data();
  int self = 0;
  for (int i = 0; i < d->ncon; ++i) {
    const int b1 = m->geom_bodyid[d->contact[i].geom1], b2 = m->geom_bodyid[d->contact[i].geom2];
    if (b1 != 0 && b2 != 0) ++self;
  }
  EXPECT_GT(self, 0);
  EXPECT_EQ(arm.contacts(), d->ncon);
}

TEST(Ur5Arm, TheSceneHasTheLinksTheObstacleAndTheTable) {
  Ur5Arm arm;
  arm.place(home());
  Scene scene;
  arm.describe(scene);
  ASSERT_EQ(scene.cylinders.size(), 8u);
  for (const auto& capsule : scene.cylinders) {
    EXPECT_EQ(capsule.role, "arm");
    EXPECT_TRUE(capsule.capped);
  }
  // One pole of the last capsule's end caps is the flange.
  const auto& tool = scene.cylinders.back();
  const Eigen::Vector3d axis = (tool.end - tool.start).normalized();
  const double pole_distance =
      std::min((tool.end + tool.radius * axis - arm.flange_position()).norm(),
               (tool.start - tool.radius * axis - arm.flange_position()).norm());
  EXPECT_LT(pole_distance, 1e-9);
  ASSERT_EQ(scene.boxes.size(), 1u);
  EXPECT_EQ(scene.boxes[0].role, "obstacle");
  EXPECT_TRUE(scene.boxes[0].centre.isApprox(Eigen::Vector3d(0.40, 0.0, 0.10)));
  EXPECT_TRUE(scene.boxes[0].half_extents.isApprox(Eigen::Vector3d(0.05, 0.20, 0.10)));
  ASSERT_EQ(scene.planes.size(), 1u);
  EXPECT_EQ(scene.planes[0].role, "table");
}

TEST(Ur5Arm, ASnapshotRestoresMotionAndTargets) {
  Ur5Arm arm;
  arm.place(home());
  arm.set_targets(home() + Joints::Constant(0.05));
  arm.advance(7);
  Snapshot bytes;
  SnapshotWriter out(bytes);
  arm.save_state(out);
  arm.advance(20);
  const Joints expected = arm.joint_positions();

  Ur5Arm copy;
  SnapshotReader in(bytes);
  copy.load_state(in);
  EXPECT_EQ(copy.targets(), arm.targets());
  copy.advance(20);
  EXPECT_EQ(copy.joint_positions(), expected);
}

class Ur5ArmFiles : public testing::ScratchDirectoryTest {
 protected:
  Ur5ArmFiles() : ScratchDirectoryTest("ur5_arm") {}
};

TEST_F(Ur5ArmFiles, AModelFileWithTheSameNamesWorksAndOneWithoutThemIsAnError) {
  const std::string mjcf = ur5_mjcf(Ur5SceneSpec{});
  std::ofstream(directory_ / "ur5.xml") << mjcf;
  Ur5Arm from_file(Ur5SceneSpec{}, directory_ / "ur5.xml");
  from_file.place(home());
  Ur5Arm built;
  built.place(home());
  EXPECT_EQ(from_file.flange_position(), built.flange_position());

  std::ofstream(directory_ / "no_flange.xml")
      << std::regex_replace(mjcf, std::regex("name='flange'"), "name='tool'");
  const std::string message =
      testing::error_message([&] { Ur5Arm(Ur5SceneSpec{}, directory_ / "no_flange.xml"); });
  EXPECT_NE(message.find("'flange'"), std::string::npos) << message;
  EXPECT_NE(message.find("no_flange.xml"), std::string::npos) << message;
}

}  // namespace
}  // namespace tendril::physics
