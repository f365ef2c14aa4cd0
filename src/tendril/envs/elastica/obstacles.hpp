#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "tendril/physics/contact/cylinder_contact.hpp"

namespace tendril::envs::elastica {

// Obstacle layouts of the Elastica control cases (SPEC M2), lab frame, m.

// Case 3: the fixed wall of ElasticaArmSpec::structured_obstacles() — 8 cylinders of radius
// 0.1 m and length 1 m along +y from y = 0, axes at (x, z) = (−0.6, 0.12), (−0.2, 0.12) and at
// x = −0.4: z = 0.37, 0.00, −0.20, −0.40, 0.57, 0.77 (one 0.17 m gap, between z = 0.00 and
// 0.37 less the radii).
std::vector<physics::Cylinder> structured_wall();

// Case 4: the unstructured nest, drawn once from `seed` and fixed afterwards (seed 000,
// case 4: "Obstacles and target locations are located in the same place … each episode").
// For each of 12 cylinders (radius 0.03 m, length 1 m), in this order from Rng(seed):
//   α, β ~ U(π/3, 2π/3);  axis = (cos α cos β, −sin α, cos α sin β)   (already unit length)
//   start x ~ U(−0.55, −0.40),  start z ~ U(t_z − 0.5, t_z + 0.5)
//   start y = t_y − ½·length·axis_y, so that the cylinder's midpoint is at the target's height.
// With α ∈ (60°, 120°) every axis points downwards (axis_y ≤ −sin 60°): the rods hang from
// y ≈ 0.93–1.0 m down through the target's height, between the arm's base and the target.
struct NestSpec {
  int cylinders = 12;
  double radius = 0.03;  // m
  double length = 1.0;   // m
};
std::vector<physics::Cylinder> unstructured_nest(const Eigen::Vector3d& target, uint64_t seed,
                                                 const NestSpec& spec = {});

}  // namespace tendril::envs::elastica
