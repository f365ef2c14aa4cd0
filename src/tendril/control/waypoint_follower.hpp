#pragma once

#include <Eigen/Core>
#include <vector>

namespace tendril::control {

// Seed 001's waypoint controller (thesis §5.2, §5.3.2): the goal handed to the low-level
// controller is the current point of a path in bend-angle space; once the limb is within the
// tolerance of it (10° in all of the thesis' experiments) the goal advances to the next point,
// and the path is finished when the last point has been reached.
class WaypointFollower {
 public:
  static constexpr double kThesisTolerance = 10.0;  // deg

  // `points`: 2 × N angles (deg), N >= 1, visited in order. Raises Error on an empty path, a
  // non-finite point or a tolerance <= 0.
  explicit WaypointFollower(Eigen::Matrix2Xd points, double tolerance_deg = kThesisTolerance);

  // Advances past every point within the tolerance of `angles` (at most one per call, as each
  // control step checks the current goal once) and returns the goal to steer to now.
  const Eigen::Vector2d& update(const Eigen::Vector2d& angles);
  // The index update(angles) would move to, without moving; points().cols() once finished.
  int index_after(const Eigen::Vector2d& angles) const;
  const Eigen::Vector2d& goal() const { return goal_; }
  int index() const { return index_; }
  bool finished() const { return index_ >= points_.cols(); }
  const Eigen::Matrix2Xd& points() const { return points_; }
  void restart();

 private:
  Eigen::Matrix2Xd points_;
  double tolerance_;
  int index_ = 0;
  Eigen::Vector2d goal_;
};

}  // namespace tendril::control
