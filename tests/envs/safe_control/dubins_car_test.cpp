#include "tendril/envs/safe_control/dubins_car.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "tendril/core/error.hpp"

namespace tendril::envs::safe_control {
namespace {

TEST(DubinsCar, StraightAndTurningStepsFollowTheUnicycle) {
  DubinsCar env;
  env.reset(0);
  env.set_state(-1.5, -1.5, 0.0);
  env.step(Action::Constant(1, 0.0f));
  EXPECT_NEAR(env.state()[0], -1.5 + 1.2 * 0.05, 1e-12);
  EXPECT_NEAR(env.state()[1], -1.5, 1e-12);

  // Forty steps at ω = 2 rad/s sweep 4 rad along a circle of radius 0.6 m about (−1.5, −0.9).
  env.set_state(-1.5, -1.5, 0.0);
  for (int t = 0; t < 40; ++t) env.step(Action::Constant(1, 2.0f));
  const double angle = 4.0;
  EXPECT_NEAR(env.state()[0], -1.5 + 0.6 * std::sin(angle), 1e-9);
  EXPECT_NEAR(env.state()[1], -0.9 - 0.6 * std::cos(angle), 1e-9);
  EXPECT_NEAR(env.state()[2], std::remainder(angle, 2.0 * std::numbers::pi), 1e-9);
}

TEST(DubinsCar, MarginCombinesWallsAndDisc) {
  const DubinsCar::Params p;
  EXPECT_DOUBLE_EQ(DubinsCar::safety_margin(p, 1.5, 0.0), 0.5);
  EXPECT_NEAR(DubinsCar::safety_margin(p, 1.9, 1.0), 0.1, 1e-12);  // 2 − 1.9 rounds
  EXPECT_NEAR(DubinsCar::safety_margin(p, 0.3, 0.4), -0.5, 1e-15);
  // The closed-form maximum agrees with a fine grid search over the safe square.
  double best = -1.0;
  for (int i = 0; i <= 800; ++i) {
    for (int j = 0; j <= 800; ++j) {
      best = std::max(best, DubinsCar::safety_margin(p, -2.0 + i * 0.005, -2.0 + j * 0.005));
    }
  }
  EXPECT_NEAR(DubinsCar::max_safety_margin(p), best, 5e-3);
  EXPECT_NEAR(DubinsCar::max_safety_margin(p), 2.0 - 3.0 / (1.0 + std::numbers::sqrt2), 1e-15);
}

TEST(DubinsCar, ReportsGoalCostAndTerminatesOutsideTheAbsoluteBox) {
  DubinsCar env;
  env.reset(0);
  env.set_state(1.8 - 0.06, 1.8, 0.0);
  Step step = env.step(Action::Constant(1, 0.0f));
  EXPECT_EQ(*step.info.get("is_success"), 1.0);
  EXPECT_NEAR(step.reward, 1.0, 1e-12);  // at the goal: bonus, no distance term
  EXPECT_EQ(*step.info.get("unsafe"), 0.0);
  env.set_state(0.5, 0.0, 0.0);
  step = env.step(Action::Constant(1, 0.0f));
  EXPECT_EQ(*step.info.get("cost"), 1.0);
  EXPECT_FALSE(step.terminated);
  env.set_state(2.99, 0.0, 0.0);
  EXPECT_TRUE(env.step(Action::Constant(1, 0.0f)).terminated);
}

TEST(DubinsCar, StartsInTheLowerLeftAndRejectsBadParams) {
  DubinsCar env;
  for (uint64_t seed = 0; seed < 50; ++seed) {
    const Observation o = env.reset(seed);
    EXPECT_GE(o[0], -1.8f);
    EXPECT_LE(o[0], -1.3f);
    EXPECT_GE(o[3], 0.0f);  // heading in [0, π/2]
    EXPECT_GE(o[2], 0.0f);
  }
  EXPECT_THROW(DubinsCar::create(Config::parse("start_high: -0.5")), Error);
  EXPECT_THROW(DubinsCar::create(Config::parse("sped: 1")), Error);
}

// start_anywhere: starts spread over the whole safe set, in every quadrant and heading.
TEST(DubinsCar, StartsAnywhereInTheSafeSetWhenAsked) {
  DubinsCar::Params params;
  params.start_anywhere = true;
  DubinsCar env(params);
  int upper_right = 0, heading_down = 0;
  for (uint64_t seed = 0; seed < 200; ++seed) {
    const Observation o = env.reset(seed);
    EXPECT_GT(DubinsCar::safety_margin(params, o[0], o[1]), 0.0);
    upper_right += o[0] > 0.0f && o[1] > 0.0f ? 1 : 0;
    heading_down += o[3] < 0.0f ? 1 : 0;
  }
  EXPECT_GT(upper_right, 20);
  EXPECT_GT(heading_down, 60);
}

// The reward-penalty baseline: −penalty on a step into the keep-out disc, nothing outside it.
TEST(DubinsCar, UnsafePenaltyIsSubtractedOnlyInTheUnsafeSet) {
  DubinsCar::Params penalized;
  penalized.unsafe_penalty = 5.0;
  DubinsCar plain, with_penalty(penalized);
  for (DubinsCar* env : {&plain, &with_penalty}) env->reset(0);
  for (auto [x, y] : {std::pair{-1.5, -1.5}, std::pair{-1.0, 0.0}}) {  // safe; enters the disc
    plain.set_state(x, y, 0.0);
    with_penalty.set_state(x, y, 0.0);
    const Step a = plain.step(Action::Constant(1, 0.0f));
    const Step b = with_penalty.step(Action::Constant(1, 0.0f));
    EXPECT_DOUBLE_EQ(a.info.get("unsafe").value(), x == -1.0 ? 1.0 : 0.0);
    EXPECT_DOUBLE_EQ(b.reward, a.reward - 5.0 * a.info.get("unsafe").value());
  }
}

// The safe set is reachable from every start: a scripted controller that steers onto the
// counter-clockwise circle of radius 1.5 m about the keep-out disc (ω = 0.8 rad/s on it) keeps
// whole episodes out of X_unsafe. What a safety agent on this environment can reach.
TEST(DubinsCar, AScriptedOrbitKeepsEveryStartSafe) {
  DubinsCar env;
  for (uint64_t seed = 0; seed < 50; ++seed) {
    Observation o = env.reset(seed);
    bool safe = true, done = false;
    while (!done) {
      const double r = std::hypot(o[0], o[1]), angle = std::atan2(o[1], o[0]);
      const double desired = angle + std::numbers::pi / 2 + std::atan(2.0 * (r - 1.5));
      const double error = std::remainder(desired - std::atan2(o[3], o[2]), 2 * std::numbers::pi);
      const Step step =
          env.step(Action::Constant(1, static_cast<float>(std::clamp(3.0 * error, -2.0, 2.0))));
      safe = safe && step.info.get("unsafe").value() == 0.0;
      done = step.terminated || step.truncated;
      o = step.observation;
    }
    EXPECT_TRUE(safe) << "reset seed " << seed;
  }
}

}  // namespace
}  // namespace tendril::envs::safe_control

namespace tendril::envs::safe_control {
namespace {

// The speed-input reading of §6.4.1: the action [ω, v] sets the speed too; at v = 0 the car
// stands (every safe state is recoverable), and v is held to [min_speed, speed].
TEST(DubinsCar, SpeedControlMakesTheSpeedAnInput) {
  DubinsCar::Params params;
  params.speed_control = true;
  DubinsCar env(params);
  ASSERT_EQ(env.action_space().size(), 2);
  EXPECT_FLOAT_EQ(env.action_space().low()[1], 0.0f);
  EXPECT_FLOAT_EQ(env.action_space().high()[1], 1.2f);
  env.reset(0);
  env.set_state(-1.5, -1.5, 0.0);
  env.step(Eigen::Vector2f(0.0f, 0.0f));
  EXPECT_DOUBLE_EQ(env.state()[0], -1.5);
  env.step(Eigen::Vector2f(0.0f, 0.6f));
  EXPECT_NEAR(env.state()[0], -1.5 + 0.6 * 0.05, 1e-8);  // v = 0.6f
  env.step(Eigen::Vector2f(0.0f, 5.0f));                 // held to 1.2 m/s
  EXPECT_NEAR(env.state()[0], -1.5 + 1.8 * 0.05, 1e-8);
  EXPECT_THROW(DubinsCar::create(Config::parse("speed_control: true\ndiscrete_actions: 5")), Error);
  EXPECT_THROW(DubinsCar::create(Config::parse("speed_control: true\nmin_speed: 2.0")), Error);
}

TEST(DubinsCar, DiscreteSpeedsPairEveryTurnRateWithEverySpeedLevel) {
  DubinsCar::Params params;
  params.speed_control = true;
  params.discrete_actions = 3;  // ω ∈ {−2, 0, 2} rad/s
  params.discrete_speeds = 3;   // v ∈ {0, 0.6, 1.2} m/s
  DubinsCar env(params);
  ASSERT_TRUE(env.action_space().is_discrete());
  ASSERT_EQ(env.action_space().n(), 9);
  const auto index = [](int k) { return Action::Constant(1, static_cast<float>(k)); };
  EXPECT_DOUBLE_EQ(env.turn_rate(index(0)), -2.0);
  EXPECT_DOUBLE_EQ(env.commanded_speed(index(0)), 0.0);
  EXPECT_DOUBLE_EQ(env.turn_rate(index(5)), 2.0);        // k mod 3 = 2
  EXPECT_DOUBLE_EQ(env.commanded_speed(index(5)), 0.6);  // k div 3 = 1
  EXPECT_DOUBLE_EQ(env.turn_rate(index(7)), 0.0);
  EXPECT_DOUBLE_EQ(env.commanded_speed(index(7)), 1.2);
  env.reset(0);
  env.set_state(-1.5, -1.5, 0.0);
  env.step(index(1));  // straight, stopped
  EXPECT_DOUBLE_EQ(env.state()[0], -1.5);
  env.step(index(7));  // straight at 1.2 m/s
  EXPECT_NEAR(env.state()[0], -1.5 + 1.2 * 0.05, 1e-12);
  EXPECT_THROW(env.step(index(9)), Error);
  EXPECT_THROW(DubinsCar::create(Config::parse("speed_control: true\ndiscrete_speeds: 3")), Error);
  EXPECT_THROW(DubinsCar::create(Config::parse("discrete_actions: 3\ndiscrete_speeds: 3")), Error);
  EXPECT_THROW(DubinsCar::create(
                   Config::parse("speed_control: true\ndiscrete_actions: 3\ndiscrete_speeds: 1")),
               Error);
}

TEST(DubinsCar, ObserveMarginAppendsTheSafetyMargin) {
  DubinsCar::Params plain;
  DubinsCar::Params params = plain;
  params.observe_margin = true;
  DubinsCar with(params), without(plain);
  ASSERT_EQ(with.observation_space().size(), 6);
  EXPECT_FLOAT_EQ(with.observation_space().high()[5], 2.0f - 3.0f / (1.0f + std::sqrt(2.0f)));
  // The same episode: the first five entries are the plain car's, the sixth the margin of the
  // position observed (0.5 m from the disc at (1.5, 0); beyond the wall at (2.5, 0)).
  Observation a = with.reset(3), b = without.reset(3);
  EXPECT_EQ(a.head(5), b);
  EXPECT_FLOAT_EQ(a[5], static_cast<float>(DubinsCar::safety_margin(params, a[0], a[1])));
  with.set_state(1.5, 0.0, 0.0);
  a = with.step(Action::Constant(1, 0.0f)).observation;
  EXPECT_NEAR(a[5], 0.5 - 1.2 * 0.05, 1e-6);  // a step of 6 cm towards the wall
  with.set_state(2.5, 0.0, 0.0);
  const Step outside = with.step(Action::Constant(1, 0.0f));
  EXPECT_NEAR(outside.observation[5], -0.56, 1e-6);
  EXPECT_NEAR(*outside.info.get("safety_margin"), outside.observation[5], 1e-6);
}

}  // namespace
}  // namespace tendril::envs::safe_control
