#include "tendril/envs/sma_limb/power_proxy.hpp"

#include <gtest/gtest.h>

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
