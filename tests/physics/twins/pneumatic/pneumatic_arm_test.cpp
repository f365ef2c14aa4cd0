#include "tendril/physics/twins/pneumatic/pneumatic_arm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::physics::pneumatic {
namespace {

// The twin's defaults have every stochastic effect off.
ChamberVector only(int chamber, double bar) {
  ChamberVector commands = ChamberVector::Zero();
  commands[chamber] = bar;
  return commands;
}

// Holds `commands` for `seconds` from the start of a fresh trial.
TipPositions hold(PneumaticArm& arm, const ChamberVector& commands, double seconds) {
  arm.set_commands(commands);
  EXPECT_TRUE(arm.advance_samples(static_cast<int>(std::lround(seconds / arm.sample_period()))));
  return arm.true_tip_positions();
}

// Seed 002 §III-A: "all three at equal pressure → the arm extends". The three chambers' bending
// cancels, so every node stays on the vertical axis, and each module lengthens by
// extension_per_bar · p: the module tips sit 10 % lower at 1 bar (gravity's own sag, under a
// millimetre, scales with the length too).
TEST(PneumaticArm, EqualPressuresExtendWithoutBending) {
  PneumaticArm arm{PneumaticArmSpec{}};
  ASSERT_TRUE(arm.begin_trial(0));
  const TipPositions rest = arm.true_tip_positions();
  const TipPositions extended = hold(arm, ChamberVector::Constant(1.0), 4.0);
  EXPECT_LT(arm.rod().state().positions.topRows(2).cwiseAbs().maxCoeff(), 1e-12);
  for (int m = 0; m < kModules; ++m) {
    EXPECT_NEAR(extended(2, m), 1.1 * rest(2, m), 5e-4) << "module " << m;
  }
  EXPECT_LT(extended(2, 2), rest(2, 2) - 0.055);
}

// An extending chamber lengthens its side of the module, so the module bends away from it, in
// the vertical plane through the axis and the chamber. Chamber c of module 1 sits at c · 120°
// from +x (default chamber_rotation 0): the whole arm ends up on the ray at c · 120° + 180°, and
// every node lies in that plane.
TEST(PneumaticArm, OneChamberBendsAwayFromItselfInItsPlane) {
  for (int c = 0; c < kChambersPerModule; ++c) {
    PneumaticArm arm{PneumaticArmSpec{}};
    ASSERT_TRUE(arm.begin_trial(0));
    hold(arm, only(chamber_index(0, c), 1.0), 4.0);
    const double angle = c * 2.0 * std::numbers::pi / 3.0;
    const Eigen::Vector2d away(-std::cos(angle), -std::sin(angle));
    const auto& x = arm.rod().state().positions;
    for (int j = 1; j < x.cols(); ++j) {
      const Eigen::Vector2d horizontal(x(0, j), x(1, j));
      EXPECT_GT(horizontal.dot(away), 0.0) << "chamber " << c << ", node " << j;
      EXPECT_LT(std::abs(horizontal.x() * away.y() - horizontal.y() * away.x()), 1e-12)
          << "chamber " << c << ", node " << j;
    }
    EXPECT_GT(Eigen::Vector2d(x(0, x.cols() - 1), x(1, x.cols() - 1)).norm(), 0.05);
  }
}

// Without gravity a module with one chamber at p is a circular arc of angle θ = bend_per_bar · p
// and length L(1 + extension_per_bar · p / 3). Module 1's tip then sits at
// L'(1 − cos θ)/θ sideways and L' sin θ / θ down. The rod converges to this at first order in
// the element length (its clamped first element holds half an element's curvature back):
// doubling the elements halves the error (10.7 mm at 6 elements per module, 5.3 mm at 12).
TEST(PneumaticArm, AFreeModuleBendsIntoTheArcOfItsCalibration) {
  auto error_at = [](int elements_per_module) {
    PneumaticArmSpec spec;
    spec.gravity = 0.0;
    spec.elements_per_module = elements_per_module;
    spec.time_step = 1.0e-4;
    PneumaticArm arm(spec);
    EXPECT_TRUE(arm.begin_trial(0));
    const TipPositions tips = hold(arm, only(chamber_index(0, 0), 1.2), 4.0);
    const double theta = spec.bend_per_bar * 1.2;
    const double length = spec.module_length() * (1.0 + spec.extension_per_bar * 1.2 / 3.0);
    const Eigen::Vector3d expected(-length * (1.0 - std::cos(theta)) / theta, 0.0,
                                   -length * std::sin(theta) / theta);
    return (tips.col(0) - expected).norm();
  };
  const double coarse = error_at(6), fine = error_at(12);
  EXPECT_NEAR(fine / coarse, 0.5, 0.05);
  EXPECT_LT(fine, 0.03 * PneumaticArmSpec{}.module_length());
}

// A chamber whose supply is disrupted (damage scenarios) produces no force: commanding it alone
// leaves the arm exactly as an arm without commands, while on the intact arm the same command
// bends it.
TEST(PneumaticArm, DamagedChambersProduceNoForce) {
  const DamageScenario scenarios[] = {DamageScenario::kS1, DamageScenario::kS2, DamageScenario::kS3,
                                      DamageScenario::kS4};
  for (DamageScenario scenario : scenarios) {
    PneumaticArmSpec spec;
    spec.scenario = scenario;
    spec.damaged_chamber = 1;
    PneumaticArm damaged(spec), idle(spec);
    ASSERT_TRUE(damaged.begin_trial(0));
    ASSERT_TRUE(idle.begin_trial(0));
    ChamberVector commands = ChamberVector::Zero();
    const auto disabled = disabled_chambers(scenario, 1);
    for (int k = 0; k < kChambers; ++k) commands[k] = disabled[k] ? 1.5 : 0.0;
    hold(damaged, commands, 2.0);
    hold(idle, ChamberVector::Zero(), 2.0);
    EXPECT_EQ(damaged.rod().state().positions, idle.rod().state().positions) << to_string(scenario);
    EXPECT_EQ(damaged.pressures().maxCoeff(), 0.0);

    PneumaticArm intact{PneumaticArmSpec{}};
    ASSERT_TRUE(intact.begin_trial(0));
    const TipPositions bent = hold(intact, commands, 2.0);
    EXPECT_GT((bent - idle.true_tip_positions()).norm(), 0.01) << to_string(scenario);
  }
}

// The safety ceiling holds for any command: 1.5 bar, the regulator's 4 bar and absurd commands
// all move the arm exactly alike, and no chamber ever holds more than 1.5 bar.
TEST(PneumaticArm, ThePressureCeilingHoldsForAnyCommand) {
  PneumaticArm reference{PneumaticArmSpec{}};
  ASSERT_TRUE(reference.begin_trial(0));
  const ChamberVector at_ceiling = ChamberVector::Constant(1.5).cwiseProduct(
      (ChamberVector() << 1, 0, 1, 0, 1, 1, 0, 0, 1).finished());
  hold(reference, at_ceiling, 1.0);
  for (double command : {4.0, 1e3, 1e300}) {
    PneumaticArm arm{PneumaticArmSpec{}};
    ASSERT_TRUE(arm.begin_trial(0));
    arm.set_commands(at_ceiling / 1.5 * command);
    for (int s = 0; s < 100; ++s) {
      ASSERT_TRUE(arm.advance_samples(1));
      ASSERT_LE(arm.pressures().maxCoeff(), 1.5);
    }
    EXPECT_EQ(arm.rod().state().positions, reference.rod().state().positions) << command;
  }
}

}  // namespace
}  // namespace tendril::physics::pneumatic
