#include "tendril/physics/rod/rotation.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace tendril::physics {
namespace {

TEST(Rotation, ExpMatchesAngleAxisForSmallAndLargeAngles) {
  for (double angle : {1e-9, 1e-4, 0.05, 0.09, 0.11, 1.0, 3.0}) {
    const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
    const Eigen::Matrix3d expected = Eigen::AngleAxisd(-angle, axis).toRotationMatrix();
    EXPECT_LT((exp_rotation_minus(angle * axis) - expected).cwiseAbs().maxCoeff(), 1e-15)
        << "angle " << angle;
  }
}

TEST(Rotation, LogInvertsExp) {
  for (double angle : {0.0, 1e-8, 1e-3, 0.3, 1.5, 3.0}) {
    const Eigen::Vector3d a = angle * Eigen::Vector3d(-0.2, 0.9, 0.4).normalized();
    const Eigen::Vector3d back = log_rotation(exp_rotation_minus(-a));
    EXPECT_LT((back - a).norm(), 1e-14) << "angle " << angle;
  }
}

TEST(Rotation, SkewIsTheCrossProduct) {
  const Eigen::Vector3d a(1, 2, 3), b(-4, 0.5, 2);
  EXPECT_LT((skew(a) * b - a.cross(b)).norm(), 1e-15);
}

}  // namespace
}  // namespace tendril::physics
