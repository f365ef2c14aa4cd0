#pragma once

#include <Eigen/Core>

#include "tendril/core/config.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::envs::ur5 {

// Where UR5/Reach-v0 puts its targets: behind the obstacle as seen from the arm's start, so that
// the straight path of the flange to the target runs through the box (seed 004 gives no
// geometry; the region is a documented choice, see ur5_reach.hpp). Lab frame, m.
struct TargetRegion {
  Eigen::Vector3d low{0.52, -0.25, 0.15};
  Eigen::Vector3d high{0.70, 0.25, 0.30};
  double obstacle_margin = 0.05;  // no target within this distance of the box
  double max_reach = 0.80;        // no target farther than this from the shoulder (0, 0, d₁)

  // Reads target_low, target_high, target_obstacle_margin, target_max_reach over the
  // defaults; raises Error naming the key of an invalid value.
  static TargetRegion from_config(const Config& params);
};

// Whether the segment from `from` to `to` meets the closed axis-aligned box (slab method).
bool segment_hits_box(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                      const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extents);

// Distance from `point` to the axis-aligned box (0 inside).
double distance_to_box(const Eigen::Vector3d& point, const Eigen::Vector3d& centre,
                       const Eigen::Vector3d& half_extents);

// Draws uniformly in the region until a target is farther than the margin from the box, within
// reach, and hidden behind it: segment_hits_box(start, target). Raises Error after 10 000
// rejections (a region the box cannot hide).
Eigen::Vector3d sample_target(const TargetRegion& region, const Eigen::Vector3d& start,
                              const Eigen::Vector3d& box_centre,
                              const Eigen::Vector3d& box_half_extents, Rng& rng);

}  // namespace tendril::envs::ur5
