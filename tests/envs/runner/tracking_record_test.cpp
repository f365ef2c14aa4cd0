// Waypoint tracking run by the policy runner: the TrackingPolicy on a scripted limb, its record
// (TrackingRecord through track_path) and the path's pushes (PathPushes).
#include "tendril/envs/runner/tracking_record.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "tendril/control/reference_patterns.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/runner/path_pushes.hpp"
#include "tendril/envs/wrappers/time_limit.hpp"

namespace tendril::envs {
namespace {

using control::PidController;
using control::StateFilter;
using control::TrackingPolicy;
using control::WaypointFollower;

// A scripted limb: each 0.1 s step moves the angles by gain × throttles, in degrees; its
// readings are (θx, θy, t), so every step can be computed by hand. It can be pushed (a push is
// only counted, with the number of steps taken before it) and terminates, as a limb whose state
// became non-finite, at step `terminate_at` (never if 0).
class StepPlant final : public Env, public PushableRobot {
 public:
  explicit StepPlant(double gain = 1.0, Eigen::Vector2d start = Eigen::Vector2d::Zero(),
                     int terminate_at = 0)
      : gain_(gain),
        start_(start),
        terminate_at_(terminate_at),
        readings_(Space::box(3, -std::numeric_limits<float>::infinity(),
                             std::numeric_limits<float>::infinity())),
        throttles_(Space::box(2, -10.0f, 10.0f)) {}
  const Space& observation_space() const override { return readings_; }
  const Space& action_space() const override { return throttles_; }
  Observation reset(std::optional<uint64_t> = std::nullopt) override {
    angles_ = start_;
    steps_ = 0;
    return reading();
  }
  Step step(const Action& throttles) override {
    ++steps_;
    angles_ += gain_ * throttles.cast<double>();
    Step step;
    step.observation = reading();
    step.terminated = steps_ == terminate_at_;
    return step;
  }
  int push_dim() const override { return 2; }
  void push_tip(const Eigen::VectorXd& force_n, double duration_s) override {
    EXPECT_EQ(force_n, Eigen::Vector2d(0.05, 0.0));
    EXPECT_EQ(duration_s, 0.2);
    pushed_before_step.push_back(steps_);
  }
  std::vector<int> pushed_before_step;

 private:
  Observation reading() const {
    return Eigen::Vector3f(static_cast<float>(angles_.x()), static_cast<float>(angles_.y()),
                           static_cast<float>(0.1 * steps_));
  }
  double gain_;
  Eigen::Vector2d start_, angles_;
  int terminate_at_;
  int steps_ = 0;
  Space readings_, throttles_;
};

// The plant is quasi-static, so the PID here has no derivative term (the rates the policy
// estimates do not enter), and the policy passes the readings through (α = 1): every number
// below is the plant's.
TrackingPolicy pid_tracking(const Env& plant, const Eigen::Matrix2Xd& path) {
  return TrackingPolicy(
      plant,
      std::make_shared<PidController>(control::Pid::Gains{.kp = 2.0, .ki = 0.001, .kd = 0.0}),
      WaypointFollower(path), StateFilter(1.0));
}

// Path (0,0) → (15,0) → (30,0): at the start (0,0) is reached, goal (15,0), saturated to 10 →
// (10,0); within 10° of (15,0) → goal (30,0) → (20,0); 10° away is not within → (30,0); done.
TEST(TrackingRecord, PidAndWaypointsOnAScriptedPlant) {
  Eigen::Matrix2Xd path(2, 3);
  path << 0, 15, 30, 0, 0, 0;
  StepPlant plant;
  const TrackingPolicy policy = pid_tracking(plant, path);
  const TrackingRun run = track_path(policy, plant, 100, 0);
  ASSERT_EQ(run.angles.cols(), 3);
  EXPECT_TRUE(run.finished);
  EXPECT_EQ(run.angles.row(0), Eigen::RowVector3d(10, 20, 30));
  EXPECT_EQ(run.goals.row(0), Eigen::RowVector3d(15, 30, 30));
  EXPECT_EQ(run.throttles.row(0), Eigen::RowVector3d(10, 10, 10));
  EXPECT_NEAR(run.times[2], 0.3, 1e-6);
  EXPECT_EQ(run.first_on_path, 0);  // (0, 0) is reached before the first step
  EXPECT_NEAR(run.rmse_deg, 0.0, 1e-12);
}

TEST(TrackingRecord, StopsAtTheStepBudgetAndScoresOnlyTheStepsOnThePath) {
  const Eigen::Matrix2Xd circle = control::reference_pattern("circle");
  StepPlant plant;
  const TrackingRun budget = track_path(pid_tracking(plant, circle), plant, 5, 0);
  EXPECT_EQ(budget.angles.cols(), 5);
  EXPECT_FALSE(budget.finished);
  // From the circle's start, at most 2° per axis and step, the whole circle is tracked: the
  // saturated PID moves along the eight compass directions, so the limb zig-zags, but it is
  // never farther from the path than the 10° tolerance plus one diagonal step (2√2°).
  StepPlant slow(0.2, Eigen::Vector2d(40, 0));
  const TrackingRun full = track_path(pid_tracking(slow, circle), slow, 1000, 0);
  EXPECT_TRUE(full.finished);
  for (Eigen::Index k = 0; k < full.angles.cols(); ++k)
    EXPECT_LT(control::distance_to_path(full.angles.col(k), circle), 10.0 + 2.0 * std::sqrt(2.0));
  EXPECT_LT(full.rmse_deg, 5.0);
  // From rest at 0 the limb first travels 30° to the circle: those steps are not scored.
  StepPlant from_rest(0.2);
  const TrackingRun lead_in = track_path(pid_tracking(from_rest, circle), from_rest, 1000, 0);
  EXPECT_GT(lead_in.first_on_path, 10);
  EXPECT_LT(lead_in.rmse_deg, 5.0);
  // Stopped before the circle was reached, nothing was tracked: no RMSE, not a perfect one.
  StepPlant stopped(0.2);
  const TrackingRun short_of_it = track_path(pid_tracking(stopped, circle), stopped, 5, 0);
  EXPECT_EQ(short_of_it.first_on_path, 5);
  EXPECT_TRUE(std::isnan(short_of_it.rmse_deg));
}

// The record's angles are the policy's estimate of each reading after a step (by default the
// thesis' filter, α = 0.8), not the raw readings.
TEST(TrackingRecord, RecordsTheEstimatedState) {
  Eigen::Matrix2Xd path(2, 2);
  path << 0, 60, 0, 0;
  StepPlant plant;
  const TrackingPolicy policy(plant, std::make_shared<PidController>(), WaypointFollower(path));
  const TrackingRun run = track_path(policy, plant, 4, 0);
  ASSERT_EQ(run.angles.cols(), 4);
  StateFilter filter;
  StepPlant replay;
  const Observation first = replay.reset();
  filter.update(first[2], Eigen::Vector2d(first[0], first[1]));
  for (Eigen::Index k = 0; k < 4; ++k) {
    const Observation r = replay.step(run.throttles.col(k).cast<float>()).observation;
    const Eigen::Vector4d x = filter.update(r[2], Eigen::Vector2d(r[0], r[1]));
    EXPECT_EQ(run.angles.col(k), x.head<2>()) << k;
  }
  EXPECT_NE(run.angles(0, 1), 20.0) << "filtered, not raw";
}

// Pushes at waypoints 4 and 8 of a line of 5° spacing: each lands before the first step that
// steers to its waypoint, once.
TEST(PathPushes, PushBeforeTheStepThatSteersToTheirWaypoint) {
  Eigen::Matrix2Xd line(2, 12);
  for (int i = 0; i < 12; ++i) line.col(i) = Eigen::Vector2d(5.0 * i, 0.0);
  StepPlant plant(0.1);
  const TrackingPolicy policy = pid_tracking(plant, line);
  PathPushes pushes(policy, plant, Eigen::Vector2d(0.05, 0.0), 0.2, {4, 8}, 1000);
  const TrackingRun run = track_path(policy, plant, 1000, 0, {&pushes});
  ASSERT_TRUE(run.finished);
  EXPECT_EQ(pushes.pushes(), 2u);
  std::vector<int> expected;
  for (int waypoint : {4, 8}) {
    Eigen::Index k = 0;
    while (k < run.goals.cols() && run.goals.col(k) != line.col(waypoint)) ++k;
    ASSERT_LT(k, run.goals.cols()) << waypoint;
    expected.push_back(static_cast<int>(k));
  }
  EXPECT_EQ(plant.pushed_before_step, expected);
  EXPECT_GT(expected[0], 0);
  // A budget that ends just before the step steering to waypoint 8: its push is not given.
  StepPlant cut(0.1);
  PathPushes first_only(policy, cut, Eigen::Vector2d(0.05, 0.0), 0.2, {4, 8}, expected[1]);
  const TrackingRun shorter = track_path(policy, cut, expected[1], 0, {&first_only});
  EXPECT_EQ(shorter.angles.cols(), expected[1]);
  EXPECT_EQ(first_only.pushes(), 1u);
  EXPECT_EQ(cut.pushed_before_step, std::vector<int>{expected[0]});
}

TEST(PathPushes, RefusesARobotThatCannotBePushed) {
  class Unpushable final : public Env {
   public:
    const Space& observation_space() const override { return plant.observation_space(); }
    const Space& action_space() const override { return plant.action_space(); }
    Observation reset(std::optional<uint64_t> seed) override { return plant.reset(seed); }
    Step step(const Action& action) override { return plant.step(action); }
    StepPlant plant;
  } limb;
  const TrackingPolicy policy = pid_tracking(limb, control::reference_pattern("circle"));
  EXPECT_THROW(PathPushes(policy, limb, Eigen::Vector2d(0.05, 0.0), 0.2, {1}, 100), Error);
}

// A time limit ends the run (the runner does not start another episode on the step budget); a
// limb whose state became non-finite (a terminated step) and a budget of no steps are errors.
TEST(TrackingRecord, ATimeLimitEndsTheRunAndANonFiniteLimbIsAnError) {
  TimeLimit limited(std::make_unique<StepPlant>(0.2), 7);
  const TrackingPolicy policy = pid_tracking(limited, control::reference_pattern("circle"));
  const TrackingRun run = track_path(policy, limited, 100, 0);
  EXPECT_EQ(run.angles.cols(), 7);
  EXPECT_FALSE(run.finished);
  StepPlant breaks(0.2, Eigen::Vector2d::Zero(), 3);
  EXPECT_THROW(track_path(policy, breaks, 100, 0), Error);
  StepPlant plant;
  EXPECT_THROW(track_path(policy, plant, 0, 0), Error);
}

}  // namespace
}  // namespace tendril::envs
