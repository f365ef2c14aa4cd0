#include "tendril/control/tracking_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tendril/control/reference_patterns.hpp"

namespace tendril::control {
namespace {

// A scripted plant: each 0.1 s step moves the angles by gain × throttles, in degrees, and
// reports rate 0 (quasi-static), so every step can be computed by hand.
class StepPlant : public TrackedLimb {
 public:
  explicit StepPlant(double gain = 1.0, Eigen::Vector2d start = Eigen::Vector2d::Zero())
      : gain_(gain), start_(start) {}
  LimbState reset() override {
    state_ = LimbState{.angles = start_};
    return state_;
  }
  LimbState apply(const Eigen::Vector2d& throttles) override {
    state_.time_s += 0.1;
    state_.angles += gain_ * throttles;
    return state_;
  }

 private:
  double gain_;
  Eigen::Vector2d start_;
  LimbState state_;
};

// Records what the loop hands the controller.
class Recorder : public TrackingController {
 public:
  Eigen::Vector2d throttles(const LimbState& state, const Eigen::Vector2d& goal,
                            double dt_s) override {
    dts.push_back(dt_s);
    return pid.throttles(state.angles, state.rates, goal, dt_s);
  }
  Pid pid;
  std::vector<double> dts;
};

// Path (0,0) → (15,0) → (30,0): at the start (0,0) is reached, goal (15,0), saturated to 10 →
// (10,0); within 10° of (15,0) → goal (30,0) → (20,0); 10° away is not within → (30,0); done.
TEST(TrackingLoop, PidAndWaypointsOnAScriptedPlant) {
  Eigen::Matrix2Xd path(2, 3);
  path << 0, 15, 30, 0, 0, 0;
  WaypointFollower follower(path);
  StepPlant plant;
  Recorder controller;
  const TrackingRun run = track(plant, controller, follower, 100);
  ASSERT_EQ(run.angles.cols(), 3);
  EXPECT_TRUE(run.finished);
  EXPECT_EQ(run.angles.row(0), Eigen::RowVector3d(10, 20, 30));
  EXPECT_EQ(run.goals.row(0), Eigen::RowVector3d(15, 30, 30));
  EXPECT_EQ(run.first_on_path, 0);  // (0, 0) is reached before the first step
  EXPECT_NEAR(run.rmse_deg, 0.0, 1e-12);
  EXPECT_EQ(controller.dts.front(), 0.0);
  EXPECT_NEAR(controller.dts.back(), 0.1, 1e-12);
}

TEST(TrackingLoop, StopsAtTheStepBudgetAndCallsTheHookEachStep) {
  WaypointFollower follower(reference_pattern("circle"));
  StepPlant plant;
  PidController pid;
  int calls = 0;
  const TrackingRun run =
      track(plant, pid, follower, 5, [&calls](int, const WaypointFollower&) { ++calls; });
  EXPECT_EQ(run.angles.cols(), 5);
  EXPECT_EQ(calls, 5);
  EXPECT_FALSE(run.finished);
  // From the circle's start, at most 2° per axis and step, the whole circle is tracked: the
  // saturated PID moves along the eight compass directions, so the limb zig-zags, but it is
  // never farther from the path than the 10° tolerance plus one diagonal step (2√2°).
  StepPlant slow(0.2, Eigen::Vector2d(40, 0));
  const TrackingRun full = track(slow, pid, follower, 1000);
  EXPECT_TRUE(full.finished);
  for (Eigen::Index k = 0; k < full.angles.cols(); ++k)
    EXPECT_LT(distance_to_path(full.angles.col(k), follower.points()), 10.0 + 2.0 * std::sqrt(2.0));
  EXPECT_LT(full.rmse_deg, 5.0);
  // From rest at 0 the limb first travels 30° to the circle: those steps are not scored.
  StepPlant from_rest(0.2);
  const TrackingRun lead_in = track(from_rest, pid, follower, 1000);
  EXPECT_GT(lead_in.first_on_path, 10);
  EXPECT_LT(lead_in.rmse_deg, 5.0);
  // Stopped before the circle was reached, nothing was tracked: no RMSE, not a perfect one.
  StepPlant stopped(0.2);
  const TrackingRun short_of_it = track(stopped, pid, follower, 5);
  EXPECT_EQ(short_of_it.first_on_path, 5);
  EXPECT_TRUE(std::isnan(short_of_it.rmse_deg));
}

}  // namespace
}  // namespace tendril::control
