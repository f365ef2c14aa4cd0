#include "tendril/envs/sma_limb/power_proxy.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::envs::sma_limb {
namespace {

// Algorithm 2 by hand, k = 0.2, Δt = 0.075 (decay 0.985 per step), R = 3: a throttle u heats its
// coil by u²/3 · 0.075 (10 → 2.5, 4 → 0.4, 2 → 0.1). Order [+x, −x, +y, −y].
TEST(PowerProxy, FollowsAlgorithm2OnAHandComputedSequence) {
  PowerProxy proxy(PowerProxy::Params{});
  proxy.update(10.0, -4.0);
  EXPECT_NEAR(proxy.power()[0], 2.5, 1e-12);
  EXPECT_EQ(proxy.power()[1], 0.0);
  EXPECT_EQ(proxy.power()[2], 0.0);
  EXPECT_NEAR(proxy.power()[3], 0.4, 1e-12);
  proxy.update(0.0, 0.0);  // cooling only; u = 0 takes the "else" branch and adds 0
  EXPECT_NEAR(proxy.power()[0], 2.4625, 1e-12);
  EXPECT_NEAR(proxy.power()[3], 0.394, 1e-12);
  proxy.update(-10.0, 2.0);
  EXPECT_NEAR(proxy.power()[0], 2.4255625, 1e-12);
  EXPECT_NEAR(proxy.power()[1], 2.5, 1e-12);
  EXPECT_NEAR(proxy.power()[2], 0.1, 1e-12);
  EXPECT_NEAR(proxy.power()[3], 0.38809, 1e-12);
  proxy.reset();
  EXPECT_EQ(proxy.power(), Eigen::Vector4d::Zero());
}

// Constantly on at |u| = 10 a coil settles where heating balances cooling: p = u²/(R k) = 166.7.
TEST(PowerProxy, SettlesAtTheBalanceOfHeatingAndCooling) {
  PowerProxy proxy(PowerProxy::Params{});
  for (int step = 0; step < 5000; ++step) proxy.update(10.0, -10.0);
  EXPECT_NEAR(proxy.power()[0], 100.0 / 0.6, 1e-6);
  EXPECT_NEAR(proxy.power()[3], 100.0 / 0.6, 1e-6);
  EXPECT_NEAR(proxy.bound(10.0), 100.0 / 0.6, 1e-12);
  EXPECT_EQ(proxy.power()[1], 0.0);
}

// The thesis' Fig. A.4: from p₀ ≈ 1600, throttles off, a coil cools by (1 − kΔt) per step, so
// after t seconds p = p₀ (1 − kΔt)^(t/Δt); at k = 0.2 that leaves 0.24 % after 30 s ("cools to
// around room temperature in 30 seconds"). docs/results/sma_limb_rl/power_cooling.py plots these
// curves.
TEST(PowerProxy, CoolsAsTheClosedFormOfFigA4) {
  for (const double k : {0.05, 0.1, 0.2, 0.5, 1.0}) {
    PowerProxy proxy(PowerProxy::Params{.cooling_rate = k});
    proxy.update(std::sqrt(1600.0 * 3.0 / 0.075), 0.0);  // one step: u²/R · Δt = 1600
    ASSERT_NEAR(proxy.power()[0], 1600.0, 1e-9);
    for (int step = 1; step <= 400; ++step) {  // 30 s
      proxy.update(0.0, 0.0);
      ASSERT_NEAR(proxy.power()[0], 1600.0 * std::pow(1.0 - k * 0.075, step), 1e-9) << "k " << k;
    }
    if (k == 0.2) EXPECT_LT(proxy.power()[0] / 1600.0, 0.0025);
  }
}

TEST(PowerProxy, SnapshotRoundTripIsExact) {
  PowerProxy proxy(PowerProxy::Params{});
  proxy.update(7.0, -3.0);
  Snapshot bytes;
  SnapshotWriter out(bytes);
  proxy.save_state(out);
  PowerProxy copy(PowerProxy::Params{});
  SnapshotReader in(bytes);
  copy.load_state(in);
  EXPECT_EQ(copy.power(), proxy.power());
}

TEST(PowerProxy, RejectsUnstableCooling) {
  EXPECT_THROW(PowerProxy(PowerProxy::Params{.cooling_rate = 20.0, .period = 0.1}), Error);
  EXPECT_THROW(PowerProxy(PowerProxy::Params{.resistance = 0.0}), Error);
}

}  // namespace
}  // namespace tendril::envs::sma_limb
