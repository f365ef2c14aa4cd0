// Frame invariance: rotating the initial state, boundary and loads by R rotates the trajectory.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "tendril/physics/forcing/loads.hpp"
#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/damping.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::physics {
namespace {

struct Scenario {
  Rod rod;
  ElementCouples* couples;
};

Scenario make_arm(const Eigen::Matrix3d& rotation) {
  RodSpec spec;
  spec.n_elements = 20;
  spec.youngs_modulus = 1.0e6;
  spec.time_step = 1.0e-4;
  spec.base_position = rotation * Eigen::Vector3d(0.1, -0.2, 0.3);
  spec.direction = rotation * Eigen::Vector3d::UnitY();
  spec.normal = rotation * Eigen::Vector3d::UnitZ();
  Scenario scenario{Rod(spec), nullptr};
  Rod& rod = scenario.rod;
  rod.add<FixedEnd>();
  rod.add<Gravity>(rotation * Eigen::Vector3d(0, 0, -9.81));
  rod.add<EndForces>(Eigen::Vector3d::Zero(), rotation * Eigen::Vector3d(1.0, 2.0, -0.5));
  rod.add<InternalDamping>(2.0);
  scenario.couples = &rod.add<ElementCouples>();
  for (int i = 0; i < spec.n_elements; ++i) {
    // Material-frame couples are invariant: they rotate with the directors.
    scenario.couples->couples().col(i) << 0.5 * std::sin(i), 0.3 * std::cos(i), 0.05;
  }
  RodState& state = rod.mutable_state();
  for (int j = 0; j <= spec.n_elements; ++j) {
    state.velocities.col(j) = rotation * Eigen::Vector3d(0.1 * j, -0.05, 0.02 * j * j) * 0.1;
  }
  for (int i = 0; i < spec.n_elements; ++i) {
    state.angular_velocities.col(i) << 0.3, -0.2 * i, 0.1;
  }
  rod.state_changed();
  return scenario;
}

TEST(RodInvariance, RotatedInitialStateGivesRotatedTrajectory) {
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  Scenario reference = make_arm(Eigen::Matrix3d::Identity());
  Scenario rotated = make_arm(rotation);
  for (int chunk = 0; chunk < 20; ++chunk) {
    ASSERT_TRUE(reference.rod.advance(100));
    ASSERT_TRUE(rotated.rod.advance(100));
    const RodState& a = reference.rod.state();
    const RodState& b = rotated.rod.state();
    EXPECT_LT((rotation * a.positions - b.positions).cwiseAbs().maxCoeff(), 1e-10);
    EXPECT_LT((rotation * a.velocities - b.velocities).cwiseAbs().maxCoeff(), 1e-10);
    EXPECT_LT((a.angular_velocities - b.angular_velocities).cwiseAbs().maxCoeff(), 1e-10);
    for (int i = 0; i < reference.rod.n_elements(); ++i) {
      EXPECT_LT((a.director(i) * rotation.transpose() - b.director(i)).cwiseAbs().maxCoeff(),
                1e-10);
    }
  }
  // The arm really moved: the check compares a non-trivial trajectory.
  EXPECT_GT((reference.rod.tip_position() - Eigen::Vector3d(0.1, 0.8, 0.3)).norm(), 1e-3);
}

}  // namespace
}  // namespace tendril::physics
