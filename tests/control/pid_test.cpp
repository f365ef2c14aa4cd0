#include "tendril/control/pid.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"

namespace tendril::control {
namespace {

const Eigen::Vector2d kZero = Eigen::Vector2d::Zero();

// Kp = 2 on errors (0.2, −0.1)° gives (0.4, −0.2) of the unit range: throttles (4, −2).
TEST(Pid, ProportionalTermOnSmallErrors) {
  Pid pid;
  const Eigen::Vector2d u = pid.throttles(kZero, kZero, Eigen::Vector2d(0.2, -0.1), 0.0);
  EXPECT_NEAR(u.x(), 4.0, 1e-12);
  EXPECT_NEAR(u.y(), -2.0, 1e-12);
}

// Beyond 0.5° of error the output saturates at the throttle range.
TEST(Pid, SaturatesToTheThrottleRange) {
  Pid pid;
  const Eigen::Vector2d u = pid.throttles(kZero, kZero, Eigen::Vector2d(5.0, -40.0), 0.0);
  EXPECT_EQ(u, Eigen::Vector2d(10.0, -10.0));
}

// The derivative acts on the measured rate: −Kd θ̇ = −0.5 · 0.4 = −0.2 → −2, and a jump of the
// goal changes only the proportional part (no derivative kick).
TEST(Pid, DerivativeOnMeasurement) {
  Pid pid;
  const Eigen::Vector2d rates(0.4, 0.0);
  EXPECT_NEAR(pid.throttles(kZero, rates, kZero, 0.0).x(), -2.0, 1e-12);
  Pid jumped;
  EXPECT_NEAR(jumped.throttles(kZero, rates, Eigen::Vector2d(0.3, 0.0), 0.0).x(),
              10.0 * (2.0 * 0.3 - 0.2), 1e-12);
}

// Ki = 0.001 on ∫e dt: e = 0.1° for 0.5 s twice gives ∫ = 0.1 deg·s, output 0.2 + 0.0001.
TEST(Pid, IntegratesTheErrorOverRealTime) {
  Pid pid;
  const Eigen::Vector2d goal(0.1, 0.0);
  pid.throttles(kZero, kZero, goal, 0.5);
  const Eigen::Vector2d u = pid.throttles(kZero, kZero, goal, 0.5);
  EXPECT_NEAR(pid.integral().x(), 0.1, 1e-15);
  EXPECT_NEAR(u.x(), 10.0 * (0.2 + 0.001 * 0.1), 1e-12);
  pid.reset();
  EXPECT_EQ(pid.integral(), kZero);
  EXPECT_THROW(pid.throttles(kZero, kZero, goal, -1.0), Error);
  EXPECT_THROW(pid.throttles(Eigen::Vector2d(NAN, 0), kZero, goal, 0.1), Error);
}

}  // namespace
}  // namespace tendril::control
