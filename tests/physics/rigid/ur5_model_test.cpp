// The MJCF UR5 against the published parameters it is built from: forward kinematics against the
// DH formulas, masses and centres of mass, limits and torque saturation.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <numbers>

#include "tendril/core/rng.hpp"
#include "tendril/physics/rigid/dh_kinematics.hpp"
#include "tendril/physics/rigid/ur5_arm.hpp"
#include "tendril/physics/rigid/ur5_parameters.hpp"

namespace tendril::physics {
namespace {

Ur5Arm::Joints random_joints(Rng& rng) {
  Ur5Arm::Joints q;
  for (int i = 0; i < ur5::kJoints; ++i)
    q[i] = rng.uniform(-ur5::kJointUpper[i], ur5::kJointUpper[i]);
  return q;
}

// The rotation angle between two frames (rad).
double angle_between(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle();
}

TEST(Ur5Model, FlangeMatchesTheDhFormulasAtRandomConfigurations) {
  // Tolerance: 1 mm and 1e-6 rad (the model places every body from the same numbers, so the
  // agreement is to rounding; a sign or axis slip would be off by centimetres).
  Ur5Arm arm;
  const std::vector<DhLink> links = ur5_dh_links();
  Rng rng(2024);
  double worst_position = 0.0, worst_angle = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    const Ur5Arm::Joints q = random_joints(rng);
    arm.place(q);
    const Eigen::Isometry3d expected = dh_forward_kinematics(links, q);
    worst_position =
        std::max(worst_position, (arm.flange_position() - expected.translation()).norm());
    worst_angle = std::max(worst_angle, angle_between(arm.flange_rotation(), expected.linear()));
  }
  EXPECT_LT(worst_position, 1e-3);
  EXPECT_LT(worst_angle, 1e-6);
}

TEST(Ur5Model, EveryJointAnchorLiesOnItsDhAxis) {
  // Joint k+1 turns about z_k through the origin of DH frame k.
  Ur5Arm arm;
  const std::vector<DhLink> links = ur5_dh_links();
  Rng rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const Ur5Arm::Joints q = random_joints(rng);
    arm.place(q);
    const auto frames = dh_frames(links, q);
    const mjData* d = arm.sim().data();
    for (int joint = 1; joint < ur5::kJoints; ++joint) {
      const Eigen::Vector3d anchor = Eigen::Map<const Eigen::Vector3d>(d->xanchor + 3 * joint);
      const Eigen::Vector3d axis = Eigen::Map<const Eigen::Vector3d>(d->xaxis + 3 * joint);
      EXPECT_LT((anchor - frames[joint - 1].translation()).norm(), 1e-9) << "joint " << joint;
      EXPECT_LT((axis - frames[joint - 1].linear().col(2)).norm(), 1e-9) << "joint " << joint;
    }
  }
}

TEST(Ur5Model, MassesAndCentresOfMassAreThePublishedOnes) {
  Ur5Arm arm;
  const mjModel* m = arm.sim().model();
  const mjData* d = arm.sim().data();
  Rng rng(3);
  const Ur5Arm::Joints q = random_joints(rng);
  arm.place(q);
  const auto frames = dh_frames(ur5_dh_links(), q);
  double total = 0.0;
  for (int link = 0; link < ur5::kJoints; ++link) {
    const int body = arm.sim().id_of(mjOBJ_BODY, ur5_names::kLinkBodies[link]);
    EXPECT_DOUBLE_EQ(m->body_mass[body], ur5::kLinkMass[link]);
    total += m->body_mass[body];
    // The published centre of mass is given in DH frame `link + 1`.
    const auto& c = ur5::kLinkCentreOfMass[link];
    const Eigen::Vector3d expected = frames[link] * Eigen::Vector3d(c[0], c[1], c[2]);
    const Eigen::Vector3d actual = Eigen::Map<const Eigen::Vector3d>(d->xipos + 3 * body);
    EXPECT_LT((actual - expected).norm(), 1e-9) << ur5_names::kLinkBodies[link];
  }
  EXPECT_NEAR(total, 3.7 + 8.393 + 2.275 + 1.219 + 1.219 + 0.1879, 1e-12);
}

TEST(Ur5Model, LimitsAndTorquesAreTheDataSheets) {
  Ur5Arm arm;
  const mjModel* m = arm.sim().model();
  for (int joint = 0; joint < ur5::kJoints; ++joint) {
    const double limit = joint == 2 ? std::numbers::pi : 2 * std::numbers::pi;
    EXPECT_TRUE(m->jnt_limited[joint]);
    EXPECT_DOUBLE_EQ(m->jnt_range[2 * joint + 1], limit);
    EXPECT_DOUBLE_EQ(m->jnt_range[2 * joint], -limit);
    EXPECT_DOUBLE_EQ(m->actuator_forcerange[2 * joint + 1], ur5::kMaxTorque[joint]);
  }
  EXPECT_DOUBLE_EQ(Ur5Arm::upper_limits()[2], std::numbers::pi);
}

}  // namespace
}  // namespace tendril::physics
