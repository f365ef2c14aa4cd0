#include "tendril/envs/elastica/intersection.hpp"

#include "tendril/envs/elastica/rod_readout.hpp"
#include "tendril/physics/contact/segment_distance.hpp"

namespace tendril::envs::elastica {

bool capsules_intersect(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1, double radius_a,
                        const physics::Cylinder& cylinder) {
  const physics::ClosestPoints closest =
      physics::closest_points_between_segments(a0, a1, cylinder.start, cylinder.end());
  const double reach = radius_a + cylinder.radius;
  return (closest.on_first - closest.on_second).squaredNorm() < reach * reach;
}

int intersecting_elements(const physics::Rod& rod, double element_radius,
                          const std::vector<physics::Cylinder>& cylinders) {
  int count = 0;
  Eigen::Vector3d proximal = node_position(rod, 0);
  for (int i = 0; i < rod.n_elements(); ++i) {
    const Eigen::Vector3d distal = node_position(rod, i + 1);
    for (const physics::Cylinder& cylinder : cylinders) {
      if (capsules_intersect(proximal, distal, element_radius, cylinder)) {
        ++count;
        break;
      }
    }
    proximal = distal;
  }
  return count;
}

}  // namespace tendril::envs::elastica
