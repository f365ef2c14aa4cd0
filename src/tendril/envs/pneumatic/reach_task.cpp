#include "tendril/envs/pneumatic/reach_task.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs::pneumatic {

ReachTaskSpec ReachTaskSpec::preset(std::string_view name, std::string_view where) {
  ReachTaskSpec spec;
  const auto plate = [](double z_top) {
    return Eigen::AlignedBox3d(Eigen::Vector3d(-60.0, -55.0, -700.0),
                               Eigen::Vector3d(60.0, -50.0, z_top));
  };
  if (name == "main") {
    spec.goal = {-30.0, -120.0, -620.0};
    spec.obstacle = plate(-570.0);
  } else if (name == "G1") {
    spec.goal = {50.0, -100.0, -620.0};
    spec.obstacle = plate(-610.0);
  } else if (name == "G2") {
    spec.goal = {-50.0, -100.0, -625.0};
    spec.obstacle = plate(-610.0);
  } else if (name == "G3") {
    spec.goal = {-45.0, -100.0, -645.0};
    spec.obstacle = plate(-570.0);
  } else {
    throw Error("unknown task '" + std::string(name) + "' (expected main, G1, G2 or G3)",
                std::string(where));
  }
  return spec;
}

Eigen::AlignedBox3d ReachTaskSpec::relaxed_boundary() {
  return Eigen::AlignedBox3d(Eigen::Vector3d(-170.0, -170.0, -700.0),
                             Eigen::Vector3d(80.0, 50.0, -570.0));
}

void ReachTaskSpec::validate() const {
  const char* where = "ReachTaskSpec";
  require(goal.allFinite(), "goal must be finite", where);
  require(obstacle.min().allFinite() && obstacle.max().allFinite() &&
              (obstacle.max().array() > obstacle.min().array()).all(),
          "obstacle must be a finite box with max > min on every axis", where);
  require(boundary.min().allFinite() && boundary.max().allFinite() &&
              (boundary.max().array() > boundary.min().array()).all(),
          "boundary must be a finite box with max > min on every axis", where);
  require(std::isfinite(success_distance) && success_distance > 0.0,
          "success_distance must be positive", where);
  require(std::isfinite(collision_distance) && collision_distance >= 0.0 &&
              std::isfinite(warning_distance) && warning_distance >= collision_distance,
          "need 0 <= collision_distance <= warning_distance", where);
  require(std::isfinite(warning_gain) && std::isfinite(step_penalty) &&
              std::isfinite(boundary_penalty) && std::isfinite(collision_penalty),
          "penalties must be finite", where);
}

double obstacle_distance(const ReachTaskSpec& spec, const Eigen::Vector3d& point) {
  if (spec.obstacle_distance == ReachTaskSpec::ObstacleDistance::kBox) {
    return spec.obstacle.exteriorDistance(point);
  }
  const Eigen::Vector3d sizes = spec.obstacle.sizes();
  int normal = 0;
  sizes.minCoeff(&normal);
  const double centre = spec.obstacle.center()[normal];
  return std::max(0.0, std::abs(point[normal] - centre) - 0.5 * sizes[normal]);
}

bool segment_meets_box(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& from,
                       const Eigen::Vector3d& to) {
  // Slab test: the parameter interval [t0, t1] ⊂ [0, 1] of from + t (to − from) inside each
  // axis' slab must stay non-empty.
  double t0 = 0.0, t1 = 1.0;
  const Eigen::Vector3d direction = to - from;
  for (int axis = 0; axis < 3; ++axis) {
    if (direction[axis] == 0.0) {
      if (from[axis] < box.min()[axis] || from[axis] > box.max()[axis]) return false;
      continue;
    }
    double enter = (box.min()[axis] - from[axis]) / direction[axis];
    double leave = (box.max()[axis] - from[axis]) / direction[axis];
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
    if (t0 > t1) return false;
  }
  return true;
}

ReachOutcome evaluate_reach_step(const ReachTaskSpec& spec, const Eigen::Vector3d& previous_tip,
                                 const Eigen::Vector3d& tip) {
  ReachOutcome out;
  out.goal_distance = (tip - spec.goal).norm();
  out.obstacle_distance = obstacle_distance(spec, tip);
  out.outside = !spec.boundary.contains(tip);
  out.collision = segment_meets_box(spec.obstacle, previous_tip, tip) ||
                  out.obstacle_distance <= spec.collision_distance;
  out.warning = !out.collision && out.obstacle_distance <= spec.warning_distance;
  out.success = !out.collision && out.goal_distance <= spec.success_distance;

  double reward = spec.step_penalty;
  if (out.outside) reward += spec.boundary_penalty;
  if (out.warning) reward -= spec.warning_gain * (spec.warning_distance - out.obstacle_distance);
  if (out.collision) reward += spec.collision_penalty;
  if (out.goal_distance > spec.success_distance) reward -= out.goal_distance;
  out.reward = reward;
  out.ends_episode =
      out.success || out.collision || (out.outside && spec.terminate_outside_boundary);
  return out;
}

}  // namespace tendril::envs::pneumatic
