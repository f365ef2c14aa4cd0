#include "tendril/safety/safety_reward.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::safety {
namespace {

TEST(SafetyReward, LevelIsTheNormalizedMargin) {
  EXPECT_DOUBLE_EQ(SafetyReward::level(0.5, 2.0), 0.25);
  EXPECT_DOUBLE_EQ(SafetyReward::level(2.0, 2.0), 1.0);
  // Eq. 6.4 caps l(x) at 1: a state farther from the unsafe set than the largest margin the
  // normalization names is worth no more than one at that margin.
  EXPECT_DOUBLE_EQ(SafetyReward::level(5.0, 2.0), 1.0);
  EXPECT_THROW(SafetyReward::level(0.5, 0.0), Error);
}

TEST(SafetyReward, ThreeCasesOfEquation63) {
  const SafetyReward reward(0.9);
  EXPECT_DOUBLE_EQ(reward.reward(0.3, 5, false, false), 0.3);
  // Entering X_unsafe at t = 2: −1/(0.81 · 0.1).
  EXPECT_NEAR(reward.reward(0.3, 2, false, true), -1.0 / (0.81 * 0.1), 1e-12);
  EXPECT_NEAR(reward.reward(0.3, 0, false, true), -10.0, 1e-12);
  EXPECT_DOUBLE_EQ(reward.reward(0.3, 2, true, true), -1.0);
  EXPECT_DOUBLE_EQ(reward.reward(0.3, 2, true, false), -1.0);
  EXPECT_THROW(SafetyReward(1.0), Error);
}

TEST(SafetyReward, EnteringTheUnsafeSetIsWorthTheSameWheneverItHappens) {
  // Discounted to the episode's start, the penalty at t is γ^t · (−1/(γ^t(1 − γ))) = −1/(1 − γ).
  const SafetyReward reward(0.99);
  for (const int64_t t : {0, 10, 150}) {
    EXPECT_NEAR(std::pow(0.99, t) * reward.reward(1.0, t, false, true), -100.0, 1e-9);
  }
}

// A tiny deterministic chain with time in the state: positions 0..4, position 4 unsafe, each
// step moves ±1 (clamped at 0), horizon T = 6. The discounted value of the optimal safety
// policy is computed by backward induction over (position, t) and checked against §6.2.2:
// positive on X_safe, in [−(1 + γ)/(1 − γ), 0) on the irrecoverable states, which here are
// those forced into position 4 by a drift we add at position 3 (every action moves right).
TEST(SafetyReward, ValueBoundsHoldOnATabularChain) {
  const double gamma = 0.9;
  const SafetyReward reward(gamma);
  constexpr int kPositions = 5, kHorizon = 6;
  const auto unsafe = [](int p) { return p == 4; };
  const auto next_of = [](int p, int action) {
    if (p == 3) return 4;  // irrecoverable: every action drifts into the unsafe set
    return std::clamp(p + (action == 0 ? -1 : 1), 0, 4);
  };
  const auto level = [](int p) { return SafetyReward::level(4.0 - p, 4.0); };
  // V[t][p]: value from position p at time t; episodes end at T or on entering X_unsafe.
  double value[kHorizon + 1][kPositions] = {};
  for (int t = kHorizon - 1; t >= 0; --t) {
    for (int p = 0; p < kPositions; ++p) {
      double best = -1e300;
      for (int action = 0; action < 2; ++action) {
        const int next = unsafe(p) ? p : next_of(p, action);
        const double r = reward.reward(level(p), t, unsafe(p), unsafe(next));
        const bool ends = unsafe(p) || unsafe(next);
        best = std::max(best, r + (ends ? 0.0 : gamma * value[t + 1][next]));
      }
      value[t][p] = best;
    }
  }
  for (int p = 0; p <= 2; ++p) {  // safe
    EXPECT_GT(value[0][p], 0.0);
    EXPECT_LE(value[0][p], reward.safe_value_bound(kHorizon));
  }
  // Irrecoverable at t = 0 and, scaled back to the start, at later times too.
  EXPECT_LT(value[0][3], 0.0);
  EXPECT_GE(value[0][3], reward.irrecoverable_value_bound());
  for (int t = 1; t < kHorizon; ++t) {
    EXPECT_GE(std::pow(gamma, t) * value[t][3], reward.irrecoverable_value_bound()) << t;
  }
  EXPECT_NEAR(reward.unsafe_value(kHorizon), -reward.safe_value_bound(kHorizon), 1e-15);
}

}  // namespace
}  // namespace tendril::safety
