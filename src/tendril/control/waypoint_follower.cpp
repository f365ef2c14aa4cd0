#include "tendril/control/waypoint_follower.hpp"

#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::control {

WaypointFollower::WaypointFollower(Eigen::Matrix2Xd points, double tolerance_deg)
    : points_(std::move(points)), tolerance_(tolerance_deg) {
  require(points_.cols() >= 1 && points_.allFinite(), "needs at least one finite waypoint",
          "control::WaypointFollower");
  require(std::isfinite(tolerance_deg) && tolerance_deg > 0.0,
          "tolerance must be > 0 degrees, got " + std::to_string(tolerance_deg),
          "control::WaypointFollower");
  restart();
}

void WaypointFollower::restart() {
  index_ = 0;
  goal_ = points_.col(0);
}

int WaypointFollower::index_after(const Eigen::Vector2d& angles) const {
  return !finished() && (angles - goal_).norm() < tolerance_ ? index_ + 1 : index_;
}

const Eigen::Vector2d& WaypointFollower::update(const Eigen::Vector2d& angles) {
  const int next = index_after(angles);
  if (next != index_) {
    index_ = next;
    // After the last point the goal stays there: the limb holds the path's end.
    if (!finished()) goal_ = points_.col(index_);
  }
  return goal_;
}

}  // namespace tendril::control
