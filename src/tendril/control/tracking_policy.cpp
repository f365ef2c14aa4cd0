#include "tendril/control/tracking_policy.hpp"

#include <string>
#include <utility>

#include "tendril/core/error.hpp"

namespace tendril::control {

namespace {

LimbState estimate(const Observation& reading, const Eigen::Vector4d& x) {
  return LimbState{.time_s = reading[2], .angles = x.head<2>(), .rates = x.tail<2>()};
}

}  // namespace

TrackingPolicy::TrackingPolicy(const Env& limb, std::shared_ptr<TrackingController> controller,
                               WaypointFollower follower, StateFilter filter)
    : readings_(limb.observation_space()),
      throttles_(limb.action_space()),
      controller_(std::move(controller)),
      follower_(std::move(follower)),
      filter_(filter) {
  require(controller_ != nullptr, "needs a controller", "control::TrackingPolicy");
  require(readings_.size() == 3 && throttles_.size() == 2,
          "tracks on readings (θx, θy, t) with 2 throttles; the limb has " +
              std::to_string(readings_.size()) + " values and " +
              std::to_string(throttles_.size()) + " actions",
          "control::TrackingPolicy");
}

void TrackingPolicy::begin_episode(const Observation& /*reading*/) const {
  controller_->reset();
  follower_.restart();
  filter_.reset();
  started_ = false;
  decision_ = Decision{};
}

TrackingPolicy::Progress TrackingPolicy::progress(const Observation& reading) const {
  Progress progress;
  progress.state =
      estimate(reading, filter_.next(reading[2], Eigen::Vector2d(reading[0], reading[1])));
  progress.waypoint = follower_.index_after(progress.state.angles);
  progress.finished = progress.waypoint >= follower_.points().cols();
  return progress;
}

Action TrackingPolicy::act(const Observation& reading, bool /*deterministic*/, Rng& /*rng*/) const {
  const LimbState state =
      estimate(reading, filter_.update(reading[2], Eigen::Vector2d(reading[0], reading[1])));
  const Eigen::Vector2d goal = follower_.update(state.angles);
  // The integral of a controller runs over the real time between readings acted on.
  const double dt_s = started_ ? state.time_s - previous_time_s_ : 0.0;
  started_ = true;
  previous_time_s_ = state.time_s;
  decision_ = Decision{.state = state,
                       .goal = goal,
                       .throttles = controller_->throttles(state, goal, dt_s),
                       .on_path = follower_.index() >= 1};
  return decision_.throttles.cast<float>();
}

}  // namespace tendril::control
