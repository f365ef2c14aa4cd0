// The twin's stochastic behaviours (seed 002 §III-B): off, the twin is deterministic whatever
// the seeds; on, it repeats exactly for a seed and differs between seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/physics/twins/pneumatic/pneumatic_arm.hpp"

namespace tendril::physics::pneumatic {
namespace {

PneumaticArmSpec with_every_effect(uint64_t instance_seed = 0) {
  PneumaticArmSpec spec;
  spec.effects.drift = true;
  spec.effects.hysteresis = true;
  spec.effects.imbalance = true;
  spec.effects.sensor_noise = true;
  spec.effects.elasticity = true;
  spec.instance_seed = instance_seed;
  return spec;
}

// Three trials (each begun without a seed after the first) of the same 2 s command sequence;
// the measured tip positions at 10 Hz.
std::vector<TipPositions> three_trials(PneumaticArm& arm, uint64_t seed) {
  std::vector<TipPositions> measured;
  Rng commands_rng(21);  // the same commands every time
  for (int trial = 0; trial < 3; ++trial) {
    EXPECT_TRUE(trial == 0 ? arm.begin_trial(seed) : arm.begin_trial());
    for (int step = 0; step < 20; ++step) {
      ChamberVector commands;
      for (int k = 0; k < kChambers; ++k) commands[k] = commands_rng.uniform(0.0, 1.5);
      arm.set_commands(commands);
      EXPECT_TRUE(arm.advance_samples(10));
      measured.push_back(arm.measured_tip_positions());
    }
  }
  return measured;
}

TEST(PneumaticArmEffects, SwitchedOffTheTwinIsDeterministicWhateverTheSeeds) {
  PneumaticArmSpec spec;
  spec.instance_seed = 5;
  PneumaticArm a(spec), b(spec);
  spec.instance_seed = 6;
  PneumaticArm c(spec);
  const auto first = three_trials(a, 1);
  EXPECT_EQ(three_trials(b, 2), first);
  EXPECT_EQ(three_trials(c, 3), first);
  // Every trial starts from the same rest, begun with a seed or without.
  a.begin_trial();
  const TipPositions rest = a.measured_tip_positions();
  a.begin_trial(8);
  EXPECT_EQ(a.measured_tip_positions(), rest);
  EXPECT_EQ(a.chamber_gains(), ChamberVector::Ones());
  EXPECT_EQ(a.module_gains(), (Eigen::Matrix<double, 1, kModules>::Ones()));
}

TEST(PneumaticArmEffects, SwitchedOnTheyRepeatForASeedAndDifferBetweenSeeds) {
  PneumaticArm a(with_every_effect()), b(with_every_effect());
  const auto first = three_trials(a, 1);
  EXPECT_EQ(three_trials(b, 1), first);
  const auto other = three_trials(b, 2);
  double largest = 0.0;
  for (size_t t = 0; t < first.size(); ++t)
    largest = std::max(largest, (other[t] - first[t]).norm());
  EXPECT_GT(largest, 1e-3);
  // Another robot instance has other chamber gains.
  PneumaticArm c(with_every_effect(1));
  EXPECT_NE(c.chamber_gains(), a.chamber_gains());
}

// Each effect on its own changes what the arm does, by about its stated magnitude.
TEST(PneumaticArmEffects, EachEffectActsOnItsOwn) {
  PneumaticArm plain{PneumaticArmSpec{}};
  ASSERT_TRUE(plain.begin_trial(0));
  const TipPositions rest = plain.true_tip_positions();

  // Drift: successive trials start from rest positions a few millimetres apart, within the cap.
  PneumaticArmSpec drifting;
  drifting.effects.drift = true;
  PneumaticArm drift(drifting);
  ASSERT_TRUE(drift.begin_trial(3));
  double largest_offset = 0.0, moved = 0.0;
  TipPositions previous = drift.true_tip_positions();
  for (int trial = 0; trial < 30; ++trial) {
    ASSERT_TRUE(drift.begin_trial());
    const TipPositions start = drift.true_tip_positions();
    moved += (start - previous).col(2).norm() / 30.0;
    largest_offset = std::max(largest_offset, (start - rest).col(2).norm());
    previous = start;
  }
  EXPECT_GT(moved, 0.5e-3);
  EXPECT_LT(moved, 2.0 * drifting.effects.drift_step);
  EXPECT_LT(largest_offset, drifting.effects.drift_cap);

  // Hysteresis: after a chamber is filled and vented, the arm stays off its rest; without it,
  // it returns.
  for (bool hysteresis : {false, true}) {
    PneumaticArmSpec spec;
    spec.effects.hysteresis = hysteresis;
    PneumaticArm arm(spec);
    ASSERT_TRUE(arm.begin_trial(0));
    ChamberVector commands = ChamberVector::Zero();
    commands[chamber_index(0, 0)] = 1.5;
    arm.set_commands(commands);
    ASSERT_TRUE(arm.advance_samples(300));
    arm.set_commands(ChamberVector::Zero());
    ASSERT_TRUE(arm.advance_samples(800));
    const double residual = (arm.true_tip_positions() - rest).col(2).norm();
    if (hysteresis) {
      EXPECT_GT(residual, 2e-3);
    } else {
      EXPECT_LT(residual, 1e-5);
    }
  }

  // Imbalance: chamber gains within the spread, and equal pressures now bend the arm.
  PneumaticArmSpec imbalanced;
  imbalanced.effects.imbalance = true;
  PneumaticArm arm(imbalanced);
  EXPECT_LE((arm.chamber_gains().array() - 1.0).abs().maxCoeff(), imbalanced.effects.gain_spread);
  ASSERT_TRUE(arm.begin_trial(0));
  arm.set_commands(ChamberVector::Constant(1.0));
  ASSERT_TRUE(arm.advance_samples(300));
  EXPECT_GT(arm.true_tip_positions().col(2).head<2>().norm(), 1e-3);

  // Sensor noise: measured and true tips differ by about the centroid noise.
  PneumaticArmSpec noisy;
  noisy.effects.sensor_noise = true;
  PneumaticArm sensed(noisy);
  ASSERT_TRUE(sensed.begin_trial(0));
  const double error = (sensed.measured_tip_positions() - sensed.true_tip_positions()).norm();
  EXPECT_GT(error, 0.0);
  EXPECT_LT(error, 10.0 * noisy.effects.marker_noise);
}

// The elasticity of the day: every trial scales each module's response by its own factor
// 1 + σξ (|ξ| ≤ 2), which moves nothing at rest and scales a module's bend.
TEST(PneumaticArmEffects, TheElasticityOfTheDayScalesEachModulesResponse) {
  PneumaticArm plain{PneumaticArmSpec{}};
  ASSERT_TRUE(plain.begin_trial(0));
  const TipPositions rest = plain.true_tip_positions();
  ChamberVector commands = ChamberVector::Zero();
  commands[chamber_index(2, 0)] = 1.5;  // module 3 bends
  plain.set_commands(commands);
  ASSERT_TRUE(plain.advance_samples(300));
  const double plain_shift = (plain.true_tip_positions() - rest).col(2).norm();

  PneumaticArmSpec spec;
  spec.effects.elasticity = true;
  spec.effects.elasticity_sigma = 0.1;
  PneumaticArm arm(spec);
  std::vector<double> module_3_gains;
  for (int trial = 0; trial < 6; ++trial) {
    ASSERT_TRUE(trial == 0 ? arm.begin_trial(7) : arm.begin_trial());
    const auto gains = arm.module_gains();
    EXPECT_TRUE((gains.array() >= 0.8).all() && (gains.array() <= 1.2).all()) << gains;
    EXPECT_EQ(arm.true_tip_positions(), rest);  // at zero pressure nothing moves
    module_3_gains.push_back(gains[2]);
    arm.set_commands(commands);
    ASSERT_TRUE(arm.advance_samples(300));
    const double shift = (arm.true_tip_positions() - rest).col(2).norm();
    EXPECT_NEAR(shift / plain_shift, gains[2], 0.1 * std::abs(gains[2] - 1.0) + 0.01) << trial;
  }
  std::sort(module_3_gains.begin(), module_3_gains.end());
  EXPECT_GT(module_3_gains.back() - module_3_gains.front(), 0.05);
  ASSERT_TRUE(arm.begin_trial(7));
  const auto again = arm.module_gains();
  ASSERT_TRUE(arm.begin_trial(7));
  EXPECT_EQ(arm.module_gains(), again);
  spec.effects.elasticity_sigma = 0.5;  // a module could lose all its response
  EXPECT_THROW(PneumaticArm{spec}, Error);
}

TEST(PneumaticArmEffects, SnapshotsRepeatTheTwinExactly) {
  PneumaticArm arm(with_every_effect());
  ASSERT_TRUE(arm.begin_trial(4));
  arm.set_commands(ChamberVector::Constant(0.7));
  ASSERT_TRUE(arm.advance_samples(25));
  Snapshot bytes;
  SnapshotWriter out(bytes);
  arm.save_state(out);
  PneumaticArm copy(with_every_effect());
  ASSERT_TRUE(copy.begin_trial(99));
  SnapshotReader in(bytes);
  copy.load_state(in);
  EXPECT_TRUE(in.at_end());
  const auto expected = three_trials(arm, 7);
  EXPECT_EQ(three_trials(copy, 7), expected);
  // And mid-trial, without a new seed:
  Snapshot again;
  SnapshotWriter out_again(again);
  arm.save_state(out_again);
  SnapshotReader in_again(again);
  copy.load_state(in_again);
  for (int s = 0; s < 15; ++s) {
    arm.set_commands(ChamberVector::Constant(0.1 * s));
    copy.set_commands(ChamberVector::Constant(0.1 * s));
    ASSERT_TRUE(arm.advance_samples(3));
    ASSERT_TRUE(copy.advance_samples(3));
    ASSERT_EQ(copy.measured_tip_positions(), arm.measured_tip_positions());
  }
  ASSERT_TRUE(arm.begin_trial());
  ASSERT_TRUE(copy.begin_trial());
  EXPECT_EQ(copy.measured_tip_positions(), arm.measured_tip_positions());
  EXPECT_EQ(copy.drift_angles(), arm.drift_angles());
}

}  // namespace
}  // namespace tendril::physics::pneumatic
