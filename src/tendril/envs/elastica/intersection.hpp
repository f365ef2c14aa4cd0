#pragma once

#include <vector>

#include "tendril/physics/contact/cylinder_contact.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::envs::elastica {

// The intersection check f(S) of case 3's penalty variant (seed 000, "Modeling obstacles with
// penalty term instead of contact force": R = −n² − φ f(S) + …, φ = 10 or 100).
//
// An element is the capsule of radius `element_radius` around the segment between its two
// nodes; a cylinder is the capsule of its radius around its axis segment (as in the contact
// model, physics::Cylinder). Two capsules intersect when the distance between their segments
// is below the sum of their radii (touching is not intersecting).
bool capsules_intersect(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1, double radius_a,
                        const physics::Cylinder& cylinder);

// Elements of `rod` (radius `element_radius`) that intersect at least one cylinder, 0 … n.
//
// f(S) is this count over the number of elements: the fraction of the arm inside obstacles,
// in [0, 1]. Reading of the seed: it names f only "an intersection checking function". A
// fraction is the reading under which its account of Fig. 8 holds: with φ = 10 the arm
// "intersects the obstacles to reach the target" (a few of 50 elements inside cost
// ≈ 10 · 0.06 = 0.6 per step, less than the 2.0 bonus it gains), while with φ = 100 the same
// cost (≈ 6) exceeds anything reaching earns and the arm "becomes unwilling to approach the
// obstacles". An indicator (0 or 1) or a plain count would make even φ = 10 outweigh the bonus.
int intersecting_elements(const physics::Rod& rod, double element_radius,
                          const std::vector<physics::Cylinder>& cylinders);

}  // namespace tendril::envs::elastica
