#include "tendril/envs/sma_limb/learned_reach_task.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::envs::sma_limb {
namespace {

// Eq. 5.5: ‖(3, 4)‖ = 5 from the goal, throttles (10, 0) cost ‖u/10‖² = 1.
TEST(ReachOutcome, AwayFromTheGoalPaysDistanceAndThrottle) {
  const ReachOutcome outcome = reach_outcome(
      Eigen::Vector4d(3, 4, 20, -20), Eigen::Vector4d::Zero(), Eigen::Vector2d(10, 0), 1.0, 80.0);
  EXPECT_DOUBLE_EQ(outcome.distance_deg, 5.0);
  EXPECT_DOUBLE_EQ(outcome.reward, -6.0);
  EXPECT_FALSE(outcome.reached);
  EXPECT_FALSE(outcome.out_of_bounds);
}

// Within δ: +1000 (eq. 5.7) and the velocity term of eq. 5.6, −sqrt(‖θ̇‖‖θ̇_g‖ − θ̇·θ̇_g):
// θ̇ = (3, 0), θ̇_g = (0, 4) are orthogonal, so −sqrt(12).
TEST(ReachOutcome, AtTheGoalEarnsTheBonusLessTheVelocityMismatch) {
  const ReachOutcome outcome =
      reach_outcome(Eigen::Vector4d(10.3, -5.4, 3, 0), Eigen::Vector4d(10, -5, 0, 4),
                    Eigen::Vector2d(-5, 0), 1.0, 80.0);
  EXPECT_TRUE(outcome.reached);
  EXPECT_NEAR(outcome.reward, -0.5 - 0.25 - std::sqrt(12.0) + 1000.0, 1e-12);
  // Velocities in the goal's direction cost nothing.
  const ReachOutcome aligned =
      reach_outcome(Eigen::Vector4d(10.3, -5.4, 0, 8), Eigen::Vector4d(10, -5, 0, 4),
                    Eigen::Vector2d::Zero(), 1.0, 80.0);
  EXPECT_NEAR(aligned.reward, -0.5 + 1000.0, 1e-12);
  // The same state misses a tighter tolerance.
  EXPECT_FALSE(reach_outcome(Eigen::Vector4d(10.3, -5.4, 0, 8), Eigen::Vector4d(10, -5, 0, 4),
                             Eigen::Vector2d::Zero(), 0.5, 80.0)
                   .reached);
}

// Any of θx, θy, θ̇x, θ̇y beyond ±80 ends the episode with −5000; exactly 80 is inside.
TEST(ReachOutcome, LeavingTheBoundsCosts5000) {
  const ReachOutcome out = reach_outcome(Eigen::Vector4d(81, 0, 0, 0), Eigen::Vector4d(75, 0, 0, 0),
                                         Eigen::Vector2d::Zero(), 1.0, 80.0);
  EXPECT_TRUE(out.out_of_bounds);
  EXPECT_DOUBLE_EQ(out.reward, -6.0 - 5000.0);
  EXPECT_TRUE(reach_outcome(Eigen::Vector4d(0, 0, 0, -80.5), Eigen::Vector4d(75, 0, 0, 0),
                            Eigen::Vector2d::Zero(), 1.0, 80.0)
                  .out_of_bounds);
  EXPECT_FALSE(reach_outcome(Eigen::Vector4d(80, -80, 80, -80), Eigen::Vector4d(75, 0, 0, 0),
                             Eigen::Vector2d::Zero(), 1.0, 80.0)
                   .out_of_bounds);
}

TEST(GoalTolerance, ShrinksLinearlyToItsEndThenStays) {
  const GoalTolerance tolerance{.dynamic = true, .start_deg = 5.0, .end_deg = 1.0, .steps = 8000};
  EXPECT_DOUBLE_EQ(tolerance.at(0), 5.0);
  EXPECT_DOUBLE_EQ(tolerance.at(2000), 4.0);
  EXPECT_DOUBLE_EQ(tolerance.at(4000), 3.0);
  EXPECT_DOUBLE_EQ(tolerance.at(8000), 1.0);
  EXPECT_DOUBLE_EQ(tolerance.at(1'000'000), 1.0);
  GoalTolerance fixed = tolerance;
  fixed.dynamic = false;
  EXPECT_DOUBLE_EQ(fixed.at(0), 1.0);
}

TEST(LearnedReachOptions, ReadsEveryKeyAndRejectsBadValues) {
  const Config params = Config::parse(
      "power_proxy: false\ninteger_throttles: false\ndynamic_tolerance: false\n"
      "tolerance_end: 2\nbound: 90\nfull_reset_probability: 0.5\n");
  const LearnedReachOptions options = LearnedReachOptions::from_config(params);
  EXPECT_FALSE(options.power_proxy);
  EXPECT_FALSE(options.integer_throttles);
  EXPECT_FALSE(options.tolerance.dynamic);
  EXPECT_DOUBLE_EQ(options.tolerance.at(0), 2.0);
  EXPECT_DOUBLE_EQ(options.bound, 90.0);
  EXPECT_DOUBLE_EQ(options.full_reset_probability, 0.5);
  EXPECT_THROW(LearnedReachOptions::from_config(Config::parse("full_reset_probability: 2")), Error);
  EXPECT_THROW(LearnedReachOptions::from_config(Config::parse("tolerance_start: 0.5")), Error);
  EXPECT_THROW(LearnedReachOptions::from_config(Config::parse("bound: 70")), Error);
}

}  // namespace
}  // namespace tendril::envs::sma_limb
