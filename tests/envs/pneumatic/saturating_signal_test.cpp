#include "tendril/envs/pneumatic/saturating_signal.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"

namespace tendril::envs::pneumatic {
namespace {

// Ten minutes at 10 Hz under the default spec: every value within [0, ceiling] ≤ 1.5 bar, and
// the ceiling redrawn over its range.
TEST(SaturatingSignal, NeverExceedsItsMovingCeiling) {
  SaturatingSignal signal(SaturatingSignalSpec{}, Rng(3));
  double lowest = 10.0, highest = 0.0;
  for (int k = 0; k < 6000; ++k) {
    const physics::pneumatic::ChamberVector levels = signal.next(0.1);
    ASSERT_GE(levels.minCoeff(), 0.0);
    ASSERT_LE(levels.maxCoeff(), signal.ceiling());
    ASSERT_LE(signal.ceiling(), 1.5);
    lowest = std::min(lowest, signal.ceiling());
    highest = std::max(highest, signal.ceiling());
  }
  EXPECT_LT(lowest, 0.7);
  EXPECT_GT(highest, 1.3);
}

// Under a fixed ceiling no level is cut short: every level is held at least hold_min (5 steps)
// and, with holds uniform in 0.5–3 s, a new level is drawn every 17.5 steps on average. A draw
// is seen as a change unless it saturates after a saturated level (p² = 9 %), so changes come
// every 17.5 / 0.91 ≈ 19.2 steps — 2810 over 9 signals × 6000 steps — and a fraction
// p (1 − p) / (1 − p²) = p / (1 + p) ≈ 0.231 of them land on the ceiling.
TEST(SaturatingSignal, HoldsItsLevelsAndSaturatesAsSpecified) {
  SaturatingSignalSpec spec;
  spec.ceiling_min = spec.ceiling_max = 1.2;
  SaturatingSignal signal(spec, Rng(5));
  physics::pneumatic::ChamberVector previous = signal.next(0.1);
  std::array<int, 9> run{};
  run.fill(1);
  int changes = 0, saturated = 0, shortest = 1 << 30;
  for (int k = 1; k < 6000; ++k) {
    const physics::pneumatic::ChamberVector levels = signal.next(0.1);
    for (int c = 0; c < 9; ++c) {
      if (levels[c] != previous[c]) {
        shortest = std::min(shortest, run[c]);
        run[c] = 0;
        ++changes;
        saturated += levels[c] == 1.2;
      }
      ++run[c];
    }
    previous = levels;
  }
  EXPECT_GE(shortest, 5);
  EXPECT_NEAR(changes, 2810.0, 0.1 * 2810.0);
  EXPECT_NEAR(static_cast<double>(saturated) / changes, 0.3 / 1.3, 0.03);
}

TEST(SaturatingSignal, RepeatsForASeedAndRestoresFromASnapshot) {
  SaturatingSignal a(SaturatingSignalSpec{}, Rng(8)), b(SaturatingSignalSpec{}, Rng(8));
  for (int k = 0; k < 100; ++k) ASSERT_EQ(a.next(0.1), b.next(0.1));
  Snapshot bytes;
  SnapshotWriter out(bytes);
  a.save_state(out);
  SaturatingSignal c(SaturatingSignalSpec{}, Rng(9));
  SnapshotReader in(bytes);
  c.load_state(in);
  for (int k = 0; k < 300; ++k) ASSERT_EQ(c.next(0.1), a.next(0.1));
  SaturatingSignalSpec bad;
  bad.hold_min = 4.0;  // above hold_max
  EXPECT_THROW(SaturatingSignal(bad, Rng(1)), Error);
}

}  // namespace
}  // namespace tendril::envs::pneumatic
