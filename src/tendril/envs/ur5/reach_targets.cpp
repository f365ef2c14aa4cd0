#include "tendril/envs/ur5/reach_targets.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/physics/rigid/ur5_parameters.hpp"

namespace tendril::envs::ur5 {

namespace {

std::string key_of(const Config& params, const std::string& key) {
  return params.source() + ": " + (params.path().empty() ? "" : params.path() + ".") + key;
}

Eigen::Vector3d read_point(const Config& params, const std::string& key,
                           const Eigen::Vector3d& fallback) {
  if (!params.has(key)) return fallback;
  const std::vector<double> values = params.get<std::vector<double>>(key);
  require(values.size() == 3,
          "expected 3 values (x, y, z in m), got " + std::to_string(values.size()),
          key_of(params, key));
  const Eigen::Vector3d point(values[0], values[1], values[2]);
  require(point.allFinite(), "values must be finite", key_of(params, key));
  return point;
}

}  // namespace

TargetRegion TargetRegion::from_config(const Config& params) {
  TargetRegion region;
  region.low = read_point(params, "target_low", region.low);
  region.high = read_point(params, "target_high", region.high);
  require((region.low.array() <= region.high.array()).all(),
          "target_low must not exceed target_high", key_of(params, "target_low"));
  region.obstacle_margin = params.get_or<double>("target_obstacle_margin", region.obstacle_margin);
  require(std::isfinite(region.obstacle_margin) && region.obstacle_margin >= 0.0,
          "must be finite and >= 0", key_of(params, "target_obstacle_margin"));
  region.max_reach = params.get_or<double>("target_max_reach", region.max_reach);
  require(std::isfinite(region.max_reach) && region.max_reach > 0.0, "must be finite and positive",
          key_of(params, "target_max_reach"));
  return region;
}

bool segment_hits_box(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                      const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extents) {
  double enter = 0.0, leave = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double low = centre[axis] - half_extents[axis];
    const double high = centre[axis] + half_extents[axis];
    const double delta = to[axis] - from[axis];
    if (delta == 0.0) {
      if (from[axis] < low || from[axis] > high) return false;
      continue;
    }
    double t_low = (low - from[axis]) / delta, t_high = (high - from[axis]) / delta;
    if (t_low > t_high) std::swap(t_low, t_high);
    enter = std::max(enter, t_low);
    leave = std::min(leave, t_high);
    if (enter > leave) return false;
  }
  return true;
}

double distance_to_box(const Eigen::Vector3d& point, const Eigen::Vector3d& centre,
                       const Eigen::Vector3d& half_extents) {
  return ((point - centre).cwiseAbs() - half_extents).cwiseMax(0.0).norm();
}

Eigen::Vector3d sample_target(const TargetRegion& region, const Eigen::Vector3d& start,
                              const Eigen::Vector3d& box_centre,
                              const Eigen::Vector3d& box_half_extents, Rng& rng) {
  const Eigen::Vector3d shoulder(0.0, 0.0, physics::ur5::kDhD[0]);
  for (int attempt = 0; attempt < 10000; ++attempt) {
    Eigen::Vector3d target;
    for (int axis = 0; axis < 3; ++axis)
      target[axis] = rng.uniform(region.low[axis], region.high[axis]);
    if (distance_to_box(target, box_centre, box_half_extents) <= region.obstacle_margin) continue;
    if ((target - shoulder).norm() > region.max_reach) continue;
    if (!segment_hits_box(start, target, box_centre, box_half_extents)) continue;
    return target;
  }
  throw Error("no target in the region is hidden behind the obstacle from the start position",
              "UR5/Reach-v0 target region");
}

}  // namespace tendril::envs::ur5
