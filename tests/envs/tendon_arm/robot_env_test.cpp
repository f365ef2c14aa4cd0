// TendonArm/Robot-v0 against the closed form of a tendon-driven continuum robot (Rucker & Webster
// 2011, straight routing): with gravity off, a constant tension T on one tendon at offset r bends
// the arm to the constant curvature κ = T r ε³ / (E I) (ε = E A / (E A + T), the compression's
// dilatation; tests/physics/tendons_test.cpp derives it), towards that tendon.
#include "tendril/envs/tendon_arm/robot_env.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/error_message.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::envs::tendon_arm {
namespace {

using testing::error_message;

ArmSpec weightless() {
  ArmSpec spec;
  spec.gravity = false;
  return spec;
}

// Holds `action` until the tip moves less than 1 nm in a control period (or 30 s pass).
Observation settle(RobotEnv& env, const Action& action) {
  Observation last = env.step(action).observation;
  for (int k = 0; k < 300; ++k) {
    const Observation next = env.step(action).observation;
    if ((next.head<3>() - last.head<3>()).cast<double>().norm() < 1e-9) return next;
    last = next;
  }
  ADD_FAILURE() << "the arm did not settle";
  return last;
}

// The tip of the discrete arc: n elements of length ε L / n, each turned from the last by the
// joint angle κ D̂ (D̂ = L / n), in the plane of `direction` (lab, horizontal, unit).
Eigen::Vector3d polygon_tip(const ArmSpec& spec, double kappa, double dilatation,
                            const Eigen::Vector3d& direction) {
  const int n = spec.elements;
  const double element = dilatation * spec.length / n, joint = kappa * spec.length / n;
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) {
    const double angle = i * joint;
    tip += element * (std::sin(angle) * direction - std::cos(angle) * Eigen::Vector3d::UnitZ());
  }
  return tip;
}

// Tolerances: the curvature within 0.1 % (the moment T r is exact at every joint; measured: 1e-7
// for the tendon on d1, 1.4e-4 for those at ±120°), the tip within 50 µm of the polygon's
// (0.017 % of L; measured 0.006 µm and 23 µm).
class ConstantTension : public ::testing::TestWithParam<int> {};

TEST_P(ConstantTension, BendsTheWeightlessArmToTheClosedFormCurvatureTowardsItsTendon) {
  const int tendon = GetParam();
  const ArmSpec spec = weightless();
  RobotEnv env(spec);
  env.reset(0);
  const double tension = 4.0;
  Action action = Action::Zero(3);
  action[tendon] = static_cast<float>(tension);
  const Observation settled = settle(env, action);

  const double axial = spec.youngs_modulus * std::numbers::pi * spec.radius * spec.radius;
  const double dilatation = axial / (axial + tension);
  const double expected =
      tension * spec.tendon_offset * std::pow(dilatation, 3) / spec.bending_stiffness();
  ASSERT_GT(expected * spec.length, 1.0) << "a bend of more than 57°";
  const Eigen::Matrix3Xd& kappa = env.rod().curvatures();
  for (int j = 0; j < kappa.cols(); ++j) {
    EXPECT_NEAR(kappa.col(j).norm(), expected, 1e-3 * expected) << "Voronoi point " << j;
  }
  // Tendon k lies at 120° k about the arm's axis d3 = −z from d1 = +x: towards (cos φ, −sin φ).
  const double phi = 2.0 * std::numbers::pi * tendon / 3.0;
  const Eigen::Vector3d direction(std::cos(phi), -std::sin(phi), 0.0);
  const Eigen::Vector3d tip = settled.head<3>().cast<double>();
  EXPECT_LT((tip - polygon_tip(spec, expected, dilatation, direction)).norm(), 5e-5)
      << tip.transpose();
  // The tendon reeled in by r θ more than the arm shortened (its path is the arc's inside);
  // the other two paid out by r θ / 2 (they sit at −r/2 across the bending plane).
  const double theta = expected * spec.length * (spec.elements - 1.0) / spec.elements;
  const double shortening = spec.length * (1.0 - dilatation);
  for (int k = 0; k < 3; ++k) {
    const double travel = settled[3 + k];
    const double expected_travel =
        shortening + (k == tendon ? 1.0 : -0.5) * spec.tendon_offset * theta;
    EXPECT_NEAR(travel, expected_travel, 2e-3 * spec.tendon_offset * theta) << "tendon " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Tendons, ConstantTension, ::testing::Values(0, 1, 2));

// Under gravity, equal tensions cancel sideways: the tip stays on the axis, pulled up by the
// compression only; the arm hangs at RobotEnv::kDefaultRest with slack tendons.
TEST(TendonArmRobot, EqualTensionsOnlyCompressAndTheRestIsTheDefault) {
  RobotEnv env{ArmSpec()};
  const Observation rest = env.reset(0);
  EXPECT_LT((rest.head<3>().cast<double>() - RobotEnv::kDefaultRest).norm(), 1e-6);
  EXPECT_LT(rest.head<3>().cast<double>().z(), -0.30) << "its weight stretches it";
  const Observation pulled = settle(env, Action::Constant(3, 5.0f));
  EXPECT_LT(pulled.head<2>().cast<double>().norm(), 1e-6);
  EXPECT_GT(pulled[2], rest[2]);
}

TEST(TendonArmRobot, ResetIsTheSameStateWhateverTheSeedAndHistory) {
  RobotEnv first{ArmSpec()}, second{ArmSpec()};
  const Observation a = first.reset(0);
  Action action(3);
  action << 6.0f, 1.0f, 0.0f;
  for (int k = 0; k < 7; ++k) first.step(action);
  EXPECT_EQ(first.reset(17), a);
  EXPECT_EQ(second.reset(), a);
  for (int k = 0; k < 5; ++k) {
    const Step x = first.step(action), y = second.step(action);
    EXPECT_EQ(x.observation, y.observation) << "step " << k;
    EXPECT_NEAR(x.info.get("time_s").value(), 0.1 * (k + 1), 1e-9);
  }
}

TEST(TendonArmRobot, SpacesAndTheDriversClamp) {
  RobotEnv env{ArmSpec()};
  EXPECT_EQ(env.observation_space().size(), 6);
  ASSERT_TRUE(env.action_space().is_box());
  EXPECT_EQ(env.action_space().size(), 3);
  EXPECT_EQ(env.action_space().low(), Eigen::VectorXf::Zero(3));
  EXPECT_EQ(env.action_space().high(), Eigen::VectorXf::Constant(3, 6.0f));
  // Beyond the range acts as its end: 10 N as 6 N, −2 N as slack.
  RobotEnv other{ArmSpec()};
  env.reset(0);
  other.reset(0);
  Action over(3), within(3);
  over << 10.0f, -2.0f, 3.0f;
  within << 6.0f, 0.0f, 3.0f;
  EXPECT_EQ(env.step(over).observation, other.step(within).observation);
  EXPECT_NE(error_message([&] { env.step(Action::Zero(2)); }).find("TendonArm/Robot-v0"),
            std::string::npos);
  const auto four = make("TendonArm/Robot-v0", Config::parse("tendons: 4\n"));
  EXPECT_EQ(four->action_space().size(), 4);
  EXPECT_EQ(four->observation_space().size(), 7);
}

TEST(TendonArmRobot, BadParametersAreNamed) {
  EXPECT_NE(error_message([] {
              make("TendonArm/Robot-v0", Config::parse("max_tension_n: -1\n"));
            }).find("max_tension_n"),
            std::string::npos);
  EXPECT_NE(error_message([] {
              make("TendonArm/Robot-v0", Config::parse("tendons: 5\n"));
            }).find("tendons must be 3 or 4"),
            std::string::npos);
  EXPECT_NE(error_message([] {
              make("TendonArm/Robot-v0", Config::parse("control_period_s: 0.00015\n"));
            }).find("whole number of time steps"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::envs::tendon_arm
