// Waypoint tracking as a policy on the limb's readings; its closed loop through the policy
// runner is tested in tests/envs/runner/tracking_record_test.cpp.
#include "tendril/control/tracking_policy.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <vector>

#include "tendril/core/error.hpp"

namespace tendril::control {
namespace {

// Only the spaces of a limb: readings (θx, θy, t) and `throttles` actions.
class LimbSpaces final : public Env {
 public:
  explicit LimbSpaces(int throttles = 2)
      : readings_(Space::box(3, -std::numeric_limits<float>::infinity(),
                             std::numeric_limits<float>::infinity())),
        throttles_(Space::box(throttles, -10.0f, 10.0f)) {}
  const Space& observation_space() const override { return readings_; }
  const Space& action_space() const override { return throttles_; }
  Observation reset(std::optional<uint64_t> = std::nullopt) override {
    throw Error("not a limb", "LimbSpaces");
  }
  Step step(const Action&) override { throw Error("not a limb", "LimbSpaces"); }

 private:
  Space readings_, throttles_;
};

// The PID, recording what the policy hands it.
class Recorder final : public TrackingController {
 public:
  void reset() override {
    pid.reset();
    ++resets;
  }
  Eigen::Vector2d throttles(const LimbState& state, const Eigen::Vector2d& goal,
                            double dt_s) override {
    states.push_back(state);
    goals.push_back(goal);
    dts.push_back(dt_s);
    return pid.throttles(state.angles, state.rates, goal, dt_s);
  }
  Pid pid;
  int resets = 0;
  std::vector<LimbState> states;
  std::vector<Eigen::Vector2d> goals;
  std::vector<double> dts;
};

Observation reading(float theta_x, float theta_y, float t) {
  return Eigen::Vector3f(theta_x, theta_y, t);
}

// Path (0,0) → (15,0) → (30,0) and readings at 0, 0.25, 0.5 s (exact in float).
TEST(TrackingPolicy, HandsItsControllerTheFilteredStateAndTheFollowersGoal) {
  Eigen::Matrix2Xd path(2, 3);
  path << 0, 15, 30, 0, 0, 0;
  const LimbSpaces limb;
  auto recorder = std::make_shared<Recorder>();
  const TrackingPolicy policy(limb, recorder, WaypointFollower(path));
  const std::vector<Observation> readings = {reading(2, 1, 0), reading(8, 1, 0.25f),
                                             reading(12, -1, 0.5f)};
  Rng rng(0);
  std::vector<Action> actions;
  policy.begin_episode(readings[0]);
  StateFilter filter;  // the thesis' α = 0.8, the policy's default
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector4d x =
        filter.update(readings[k][2], Eigen::Vector2d(readings[k][0], readings[k][1]));
    // progress() foretells what act() then does.
    const TrackingPolicy::Progress ahead = policy.progress(readings[k]);
    EXPECT_EQ(ahead.state.angles, x.head<2>()) << k;
    EXPECT_EQ(ahead.state.rates, x.tail<2>()) << k;
    const Action action = policy.act(readings[k], true, rng);
    actions.push_back(action);
    const TrackingPolicy::Decision& decision = policy.last_decision();
    EXPECT_EQ(ahead.waypoint, policy.follower().index()) << k;
    EXPECT_FALSE(ahead.finished);
    EXPECT_EQ(recorder->states[k].angles, x.head<2>()) << k;
    EXPECT_EQ(recorder->states[k].rates, x.tail<2>()) << k;
    EXPECT_EQ(recorder->states[k].time_s, readings[k][2]) << k;
    EXPECT_EQ(decision.goal, recorder->goals[k]) << k;
    EXPECT_EQ(action, decision.throttles.cast<float>()) << k;
    EXPECT_TRUE(decision.on_path) << k;  // (2, 1) is within 10° of (0, 0)
  }
  // Goals: (0,0) reached at once → (15,0); filtered θx 6.8 is 8.2° from 15 → (30,0); filtered
  // θx 0.8·12 + 0.2·6.8 = 10.96 is 19° from 30 → stays.
  EXPECT_EQ(recorder->goals[0], Eigen::Vector2d(15, 0));
  EXPECT_EQ(recorder->goals[1], Eigen::Vector2d(30, 0));
  EXPECT_EQ(recorder->goals[2], Eigen::Vector2d(30, 0));
  // The time since the previous reading acted on; 0 on the first.
  EXPECT_EQ(recorder->dts, (std::vector<double>{0.0, 0.25, 0.25}));
  // Within 10° of (30, 0) the path is finished.
  EXPECT_TRUE(policy.progress(reading(25, 0, 0.75f)).finished);

  // A new episode forgets the estimate, the follower and the controller's memory (the PID's
  // integral): the same readings give the same decisions.
  policy.begin_episode(readings[0]);
  EXPECT_EQ(recorder->resets, 2);
  EXPECT_EQ(policy.follower().index(), 0);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(policy.act(readings[k], true, rng), actions[k]) << k;
    EXPECT_EQ(recorder->states[3 + k].angles, recorder->states[k].angles) << k;
    EXPECT_EQ(recorder->dts[3 + k], recorder->dts[k]) << k;
  }
  EXPECT_EQ(recorder->pid.integral(),
            Eigen::Vector2d(0.25 * (30 - recorder->states[1].angles.x()) +
                                0.25 * (30 - recorder->states[2].angles.x()),
                            0.25 * (0 - recorder->states[1].angles.y()) +
                                0.25 * (0 - recorder->states[2].angles.y())));
}

TEST(TrackingPolicy, RefusesALimbWithOtherSpacesAndAMissingController) {
  Eigen::Matrix2Xd path = Eigen::Matrix2Xd::Zero(2, 1);
  EXPECT_THROW(
      TrackingPolicy(LimbSpaces(3), std::make_shared<PidController>(), WaypointFollower(path)),
      Error);
  EXPECT_THROW(TrackingPolicy(LimbSpaces(), nullptr, WaypointFollower(path)), Error);
}

}  // namespace
}  // namespace tendril::control
