// The SMA limb twin as a whole: which way each coil bends it, its dead zone, loads, pushes,
// over-heating, the hardware's rules and exact snapshots.
#include "tendril/physics/twins/sma/sma_limb.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/error_message.hpp"

namespace tendril::physics {
namespace {

// Holds `pwm` for `seconds` and returns the largest true angles reached (deg, per axis, signed
// by the larger magnitude).
Eigen::Vector2d hold(SmaLimb& limb, const std::array<int, 4>& pwm, double seconds) {
  limb.set_pwm(pwm);
  Eigen::Vector2d extreme = Eigen::Vector2d::Zero();
  const double end = limb.time() + seconds;
  while (limb.time() < end) {
    limb.next_reading();
    const Eigen::Vector2d angles = limb.true_angles_deg();
    for (int axis = 0; axis < 2; ++axis) {
      if (std::abs(angles[axis]) > std::abs(extreme[axis])) extreme[axis] = angles[axis];
    }
  }
  return extreme;
}

TEST(SmaLimb, EachCoilBendsTheLimbTowardsItsOwnSide) {
  const std::array<std::array<int, 4>, 4> pwms{
      {{30, 0, 0, 0}, {0, 30, 0, 0}, {0, 0, 30, 0}, {0, 0, 0, 30}}};
  const Eigen::Vector2d directions[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (int coil = 0; coil < 4; ++coil) {
    SmaLimb limb(SmaLimbSpec::stiff(), 1);
    const Eigen::Vector2d bent = hold(limb, pwms[coil], 2.5);
    EXPECT_GT(bent.dot(directions[coil]), 30.0) << "coil " << coil;
    EXPECT_LT((bent - bent.dot(directions[coil]) * directions[coil]).norm(), 0.5)
        << "coil " << coil;
    EXPECT_GT(limb.coil(coil).wire_temperature, 80.0);
    EXPECT_LT(limb.coil(coil).phase.martensite, 0.8);
  }
}

// Two neighbouring coils bend it along the diagonal between them.
TEST(SmaLimb, NeighbouringCoilsBendItDiagonally) {
  SmaLimb limb(SmaLimbSpec::stiff(), 1);
  const Eigen::Vector2d bent = hold(limb, {28, 0, 0, 28}, 2.5);
  EXPECT_GT(bent.x(), 20.0);
  EXPECT_NEAR(bent.y(), -bent.x(), 0.5);
}

// Below the first effective duty nothing moves: the wire does not reach As within the hold.
TEST(SmaLimb, HasADeadZoneBelowTheFirstEffectiveDuty) {
  SmaLimb limb(SmaLimbSpec::stiff(), 1);
  const Eigen::Vector2d bent = hold(limb, {12, 0, 0, 0}, 2.5);
  EXPECT_LT(bent.norm(), 1e-3);
  EXPECT_LT(limb.coil(0).wire_temperature,
            limb.spec().actuator.coil.transformation.austenite_start);
  EXPECT_EQ(limb.coil(0).phase.martensite, 1.0);
}

// A coil cools after it is switched off; the limb straightens (both coils martensite again).
TEST(SmaLimb, StraightensAgainAsTheCoilCools) {
  SmaLimb limb(SmaLimbSpec::soft(), 1);
  const Eigen::Vector2d bent = hold(limb, {0, 0, 26, 0}, 2.5);
  ASSERT_GT(bent.y(), 40.0);
  hold(limb, {0, 0, 0, 0}, 60.0);
  EXPECT_LT(limb.true_angles_deg().norm(), 0.5);
  EXPECT_EQ(limb.coil(2).phase.martensite, 1.0);
}

TEST(SmaLimb, ATipLoadReducesTheBend) {
  SmaLimbSpec loaded = SmaLimbSpec::stiff();
  loaded.tip_mass = 0.05;
  SmaLimb free_limb(SmaLimbSpec::stiff(), 1), heavy_limb(loaded, 1);
  const double free_bend = hold(free_limb, {34, 0, 0, 0}, 2.5).x();
  const double heavy_bend = hold(heavy_limb, {34, 0, 0, 0}, 2.5).x();
  EXPECT_GT(free_bend, 60.0);
  EXPECT_LT(heavy_bend, 0.8 * free_bend);
  EXPECT_GT(heavy_bend, 10.0);
}

TEST(SmaLimb, APushDeflectsTheTipWhileItLasts) {
  SmaLimb limb(SmaLimbSpec::soft(), 1);
  limb.push(Eigen::Vector3d(0.05, 0.0, 0.0), 0.3);
  const Eigen::Vector2d pushed = hold(limb, {0, 0, 0, 0}, 0.3);
  EXPECT_GT(pushed.x(), 5.0);  // the limb's x axis is the lab's
  hold(limb, {0, 0, 0, 0}, 2.0);
  EXPECT_LT(limb.true_angles_deg().norm(), 0.5);
}

// Held far beyond its upper bound the wire passes the damage temperature and loses part of its
// shape memory for good: the same hold afterwards bends the limb less.
TEST(SmaLimb, OverHeatingDegradesACoilForGood) {
  SmaLimb limb(SmaLimbSpec::stiff(), 1);
  const double fresh = hold(limb, {34, 0, 0, 0}, 2.5).x();
  EXPECT_EQ(limb.coil(0).degradation, 0.0);
  hold(limb, {0, 0, 0, 0}, 120.0);
  hold(limb, {120, 0, 0, 0}, 20.0);
  const double degradation = limb.coil(0).degradation;
  EXPECT_GT(degradation, 0.05);
  hold(limb, {0, 0, 0, 0}, 180.0);
  EXPECT_EQ(limb.coil(0).degradation, degradation) << "never heals";
  const double worn = hold(limb, {34, 0, 0, 0}, 2.5).x();
  EXPECT_LT(worn, fresh - 5.0);
}

TEST(SmaLimb, RefusesAntagonistsTogetherAndOutOfRangePwm) {
  SmaLimb limb(SmaLimbSpec::stiff(), 1);
  using testing::error_message;
  EXPECT_NE(error_message([&] {
              limb.set_pwm({10, 10, 0, 0});
            }).find("antagonistic"),
            std::string::npos);
  EXPECT_NE(error_message([&] {
              limb.set_pwm({0, 0, 5, 7});
            }).find("antagonistic"),
            std::string::npos);
  EXPECT_NE(error_message([&] { limb.set_pwm({256, 0, 0, 0}); }).find("0-255"), std::string::npos);
  EXPECT_NE(error_message([&] { limb.set_pwm({0, -1, 0, 0}); }).find("0-255"), std::string::npos);
  EXPECT_EQ(error_message([&] { limb.set_pwm({10, 0, 0, 10}); }), "no error");
}

// Everything that evolves is in the snapshot: a copy loaded mid-way (coils hot, half
// transformed, a push under way) repeats the original's readings and coil states exactly.
TEST(SmaLimb, SnapshotsRestoreEverythingExactly) {
  SmaLimb original(SmaLimbSpec::soft(), 5);
  hold(original, {24, 0, 0, 20}, 2.0);
  original.push(Eigen::Vector3d(0.0, 0.02, 0.0), 0.5);
  hold(original, {0, 22, 0, 0}, 0.2);
  ASSERT_GT(original.coil(0).wire_temperature, 50.0);
  Snapshot bytes;
  SnapshotWriter out(bytes);
  original.save_state(out);

  SmaLimb copy(SmaLimbSpec::soft(), 99);
  hold(copy, {0, 0, 30, 0}, 1.0);
  SnapshotReader in(bytes);
  copy.load_state(in);
  EXPECT_TRUE(in.at_end());
  for (int k = 0; k < 60; ++k) {
    const std::array<int, 4> pwm{k % 3 == 0 ? 25 : 0, 0, 0, k % 2 == 0 ? 21 : 0};
    original.set_pwm(pwm);
    copy.set_pwm(pwm);
    const BendReading a = original.next_reading(), b = copy.next_reading();
    ASSERT_EQ(a.time_ms, b.time_ms) << k;
    ASSERT_EQ(a.angles_deg, b.angles_deg) << k;
  }
  for (int coil = 0; coil < 4; ++coil) {
    EXPECT_EQ(copy.coil(coil).wire_temperature, original.coil(coil).wire_temperature);
    EXPECT_EQ(copy.coil(coil).phase.martensite, original.coil(coil).phase.martensite);
  }

  SmaLimb stiff(SmaLimbSpec::stiff(), 5);
  SnapshotReader again(bytes);
  EXPECT_NE(testing::error_message([&] { stiff.load_state(again); }), "no error");
}

// A rod stepped beyond its stability blows up: the limb then reports NaN readings, still on its
// sensor's clock, and stops advancing the rod.
TEST(SmaLimb, ABlownUpRodGivesNaNReadingsOnTime) {
  physics::SmaLimbSpec spec = SmaLimbSpec::stiff();
  spec.steps_per_millisecond = 1;
  spec.rotary_inertia_scale = 1.0;
  SmaLimb limb(spec, 1);
  limb.set_pwm({30, 0, 0, 0});
  int readings = 0;
  while (limb.finite() && readings < 100) {
    limb.next_reading();
    ++readings;
  }
  ASSERT_FALSE(limb.finite()) << "1 ms steps must be unstable for this rod";
  int64_t previous = limb.last_reading().time_ms;
  for (int k = 0; k < 5; ++k) {
    const BendReading reading = limb.next_reading();
    EXPECT_TRUE(std::isnan(reading.angles_deg.x()));
    EXPECT_GE(reading.time_ms - previous, 55);
    previous = reading.time_ms;
  }
}

TEST(SmaLimb, DescribesItsRodCoilsAndReadouts) {
  SmaLimb limb(SmaLimbSpec::stiff(), 1);
  hold(limb, {30, 0, 0, 0}, 1.5);
  Scene scene;
  limb.describe(scene);
  ASSERT_EQ(scene.rods.size(), 1u);
  EXPECT_EQ(scene.rods[0].centreline.cols(), limb.spec().n_elements + 1);
  ASSERT_EQ(scene.paths.size(), 4u);
  // The +x coil runs on the limb's +x side, 3.5 mm off the centreline.
  const Eigen::Vector3d mid_coil = scene.paths[0].points.col(5);
  const Eigen::Vector3d mid_rod = scene.rods[0].centreline.col(5);
  EXPECT_NEAR((mid_coil - mid_rod).norm(), limb.spec().actuator.tendon_offset, 1e-6);
  EXPECT_GT(mid_coil.x(), mid_rod.x());
  EXPECT_FALSE(scene.values.empty());
  EXPECT_DOUBLE_EQ(scene.time, limb.time());
}

}  // namespace
}  // namespace tendril::physics
