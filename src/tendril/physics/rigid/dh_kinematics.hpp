#pragma once

#include <Eigen/Geometry>
#include <span>
#include <vector>

namespace tendril::physics {

// One link of a serial chain in standard (distal) Denavit–Hartenberg form (Craig's "classic"
// convention, as Universal Robots publishes it): the transform from frame i−1 to frame i is
//   Rz(θ) · Tz(d) · Tx(a) · Rx(α),  θ = the joint angle.
struct DhLink {
  double a = 0.0;      // m, along x_i
  double d = 0.0;      // m, along z_{i−1}
  double alpha = 0.0;  // rad, about x_i
};

// The transform of one link at joint angle `theta` (rad).
Eigen::Isometry3d dh_transform(const DhLink& link, double theta);

// Frames 1…n of the chain in the base frame at joint angles `q` (one per link, rad); the last
// is the flange. Raises Error if `q` does not have one angle per link.
std::vector<Eigen::Isometry3d> dh_frames(std::span<const DhLink> links, const Eigen::VectorXd& q);

// The last frame of dh_frames.
Eigen::Isometry3d dh_forward_kinematics(std::span<const DhLink> links, const Eigen::VectorXd& q);

// The UR5's links (ur5_parameters.hpp).
std::vector<DhLink> ur5_dh_links();

}  // namespace tendril::physics
