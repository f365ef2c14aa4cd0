// The limb's state estimate (seed 001 eqs. 4.5 and 4.7) against a hand-computed example.
#include "tendril/control/state_filter.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"

namespace tendril::control {
namespace {

// Readings θx at t: 0 at 0 s, 1 at 0.05 s, 3 at 0.15 s, 3.5 at 0.2 s; θy = 2θx.
// By hand, α = 0.8: raw ω = 0 (first), 20, 20, 10; filtered θ = 0, 0.8, 0.8·3 + 0.2·0.8 = 2.56,
// 0.8·3.5 + 0.2·2.56 = 3.312; filtered ω = 0, 16, 0.8·20 + 0.2·16 = 19.2, 0.8·10 + 0.2·19.2 =
// 11.84. (tests/data/prepare_test.cpp checks that preparation writes the same.)
TEST(StateFilter, MatchesTheHandComputedExample) {
  const double t[4] = {0.0, 0.05, 0.15, 0.2}, x[4] = {0.0, 1.0, 3.0, 3.5};
  const double theta[4] = {0.0, 0.8, 2.56, 3.312}, omega[4] = {0.0, 16.0, 19.2, 11.84};
  StateFilter filter;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d angles(x[k], 2.0 * x[k]);
    // next() is update() without taking the reading.
    const Eigen::Vector4d ahead = filter.next(t[k], angles);
    const Eigen::Vector4d state = filter.update(t[k], angles);
    EXPECT_EQ(ahead, state) << k;
    EXPECT_NEAR(state[0], theta[k], 1e-12) << k;
    EXPECT_NEAR(state[1], 2.0 * theta[k], 1e-12) << k;
    EXPECT_NEAR(state[2], omega[k], 1e-12) << k;
    EXPECT_NEAR(state[3], 2.0 * omega[k], 1e-12) << k;
  }
  // After a reset the first reading is taken as it is, at rate 0.
  filter.reset();
  EXPECT_EQ(filter.update(7.0, Eigen::Vector2d(5, 6)), Eigen::Vector4d(5, 6, 0, 0));
}

// α = 1: the angles pass through and the rates are the plain finite difference.
TEST(StateFilter, AlphaOneIsTheFiniteDifference) {
  StateFilter filter(1.0);
  filter.update(0.5, Eigen::Vector2d(1, 2));
  EXPECT_EQ(filter.update(0.75, Eigen::Vector2d(2, 1)), Eigen::Vector4d(2, 1, 4, -4));
}

TEST(StateFilter, RefusesBadAlphasAndTimeGoingBack) {
  EXPECT_THROW(StateFilter(0.0), Error);
  EXPECT_THROW(StateFilter(1.5), Error);
  StateFilter filter;
  filter.update(1.0, Eigen::Vector2d::Zero());
  EXPECT_THROW(filter.next(1.0, Eigen::Vector2d::Zero()), Error);
  EXPECT_THROW(filter.update(0.5, Eigen::Vector2d::Zero()), Error);
}

}  // namespace
}  // namespace tendril::control
