#include "tendril/physics/twins/pneumatic/pressure_regulators.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tendril/core/error.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::physics::pneumatic {
namespace {

// The safety ceiling holds for any command: huge, negative, tiny, beyond the regulator range;
// no chamber pressure ever exceeds it, however long the command is held.
TEST(PressureRegulators, NoCommandDrivesAChamberAboveTheCeiling) {
  PressureRegulators regulators{RegulatorSpec{}};
  Rng rng(4);
  for (int trial = 0; trial < 200; ++trial) {
    ChamberVector commands;
    for (int k = 0; k < kChambers; ++k)
      commands[k] = rng.uniform(-10.0, 10.0) * std::pow(10.0, rng.uniform(-3.0, 6.0));
    regulators.set_commands(commands);
    for (int s = 0; s < 50; ++s) regulators.advance(0.05);
    EXPECT_LE(regulators.pressures().maxCoeff(), 1.5);
    EXPECT_GE(regulators.pressures().minCoeff(), 0.0);
    for (int k = 0; k < kChambers; ++k) {
      EXPECT_EQ(regulators.targets()[k], std::clamp(commands[k], 0.0, 1.5)) << commands[k];
    }
  }
  // Commands beyond the regulator range (4 bar) are first cut to it, then to the ceiling.
  EXPECT_EQ(regulators.target_for(3.0, false), 1.5);
  EXPECT_EQ(regulators.target_for(1e300, false), 1.5);
  EXPECT_EQ(regulators.target_for(-0.5, false), 0.0);
}

TEST(PressureRegulators, NonFiniteCommandsAndBadSpecsAreRefused) {
  PressureRegulators regulators{RegulatorSpec{}};
  ChamberVector commands = ChamberVector::Zero();
  commands[4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(regulators.set_commands(commands), Error);
  commands[4] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(regulators.set_commands(commands), Error);
  RegulatorSpec above_range;
  above_range.ceiling_bar = 5.0;  // beyond the 4 bar regulator
  EXPECT_THROW(PressureRegulators{above_range}, Error);
  RegulatorSpec no_lag;
  no_lag.inflate_time = 0.0;
  EXPECT_THROW(PressureRegulators{no_lag}, Error);
}

// First-order lag, exact over any step: p(t) = p∞ (1 − e^{−t/τ_in}) while filling, and
// p(t) = p₀ e^{−t/τ_out} while venting.
TEST(PressureRegulators, FillAndVentFollowTheirTimeConstants) {
  RegulatorSpec spec;
  spec.inflate_time = 0.15;
  spec.deflate_time = 0.4;
  PressureRegulators regulators(spec);
  regulators.set_commands(ChamberVector::Constant(1.2));
  for (int s = 0; s < 30; ++s) regulators.advance(0.01);
  EXPECT_NEAR(regulators.pressures()[0], 1.2 * (1.0 - std::exp(-0.3 / 0.15)), 1e-13);
  const double filled = regulators.pressures()[0];
  regulators.set_commands(ChamberVector::Zero());
  for (int s = 0; s < 5; ++s) regulators.advance(0.1);
  EXPECT_NEAR(regulators.pressures()[0], filled * std::exp(-0.5 / 0.4), 1e-13);
}

// Seed 002 §III-B: at high command rates the chambers neither fill nor empty fully. A 0–1.5 bar
// square wave at 5 Hz leaves the pressure swinging over well under half the commanded range,
// and never back to zero; at 0.2 Hz it reaches within 1 % of both ends.
TEST(PressureRegulators, FastCommandsFillAndVentIncompletely) {
  auto swing = [](double frequency) {
    PressureRegulators regulators{RegulatorSpec{}};
    const double dt = 1e-3;
    const int half_period = static_cast<int>(std::lround(0.5 / frequency / dt));
    double low = 10.0, high = -10.0;
    for (int cycle = 0; cycle < 12; ++cycle) {
      for (double level : {1.5, 0.0}) {
        regulators.set_commands(ChamberVector::Constant(level));
        for (int s = 0; s < half_period; ++s) regulators.advance(dt);
        if (cycle >= 10) {
          low = std::min(low, regulators.pressures()[0]);
          high = std::max(high, regulators.pressures()[0]);
        }
      }
    }
    return std::pair(low, high);
  };
  const auto [fast_low, fast_high] = swing(5.0);
  EXPECT_GT(fast_low, 0.5);
  EXPECT_LT(fast_high - fast_low, 0.5 * 1.5);
  const auto [slow_low, slow_high] = swing(0.2);
  EXPECT_LT(slow_low, 0.015);
  EXPECT_GT(slow_high, 1.5 - 0.015);
}

TEST(PressureRegulators, DisabledChambersStayVentedOrReachTheirFraction) {
  RegulatorSpec spec;
  spec.disabled[chamber_index(1, 2)] = true;
  PressureRegulators vented(spec);
  vented.set_commands(ChamberVector::Constant(1.0));
  for (int s = 0; s < 100; ++s) vented.advance(0.01);
  EXPECT_EQ(vented.pressures()[chamber_index(1, 2)], 0.0);
  EXPECT_GT(vented.pressures()[chamber_index(1, 1)], 0.9);

  spec.disabled_fraction = 0.25;
  PressureRegulators leaky(spec);
  leaky.set_commands(ChamberVector::Constant(1.0));
  EXPECT_DOUBLE_EQ(leaky.targets()[chamber_index(1, 2)], 0.25);
}

TEST(PressureRegulators, SnapshotsRestoreEveryChamber) {
  PressureRegulators regulators{RegulatorSpec{}};
  ChamberVector commands;
  for (int k = 0; k < kChambers; ++k) commands[k] = 0.15 * k;
  regulators.set_commands(commands);
  regulators.advance(0.05);
  Snapshot bytes;
  SnapshotWriter out(bytes);
  regulators.save_state(out);
  PressureRegulators copy{RegulatorSpec{}};
  SnapshotReader in(bytes);
  copy.load_state(in);
  EXPECT_TRUE(in.at_end());
  regulators.advance(0.05);
  copy.advance(0.05);
  EXPECT_EQ(copy.pressures(), regulators.pressures());
  EXPECT_EQ(copy.commands(), regulators.commands());
}

}  // namespace
}  // namespace tendril::physics::pneumatic
