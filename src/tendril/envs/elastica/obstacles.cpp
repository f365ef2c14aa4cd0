#include "tendril/envs/elastica/obstacles.hpp"

#include <cmath>
#include <numbers>

#include "tendril/core/rng.hpp"
#include "tendril/physics/arms/elastica_arm.hpp"

namespace tendril::envs::elastica {

std::vector<physics::Cylinder> structured_wall() {
  return physics::ElasticaArmSpec::structured_obstacles().obstacles;
}

std::vector<physics::Cylinder> unstructured_nest(const Eigen::Vector3d& target, uint64_t seed,
                                                 const NestSpec& spec) {
  constexpr double kPi = std::numbers::pi;
  Rng rng(seed);
  std::vector<physics::Cylinder> nest;
  nest.reserve(spec.cylinders);
  for (int k = 0; k < spec.cylinders; ++k) {
    const double alpha = rng.uniform(kPi / 3.0, 2.0 * kPi / 3.0);
    const double beta = rng.uniform(kPi / 3.0, 2.0 * kPi / 3.0);
    const double start_x = rng.uniform(-0.55, -0.40);
    const double start_z = rng.uniform(target.z() - 0.5, target.z() + 0.5);
    physics::Cylinder cylinder;
    cylinder.axis = Eigen::Vector3d(std::cos(alpha) * std::cos(beta), -std::sin(alpha),
                                    std::cos(alpha) * std::sin(beta))
                        .normalized();
    cylinder.length = spec.length;
    cylinder.radius = spec.radius;
    cylinder.start =
        Eigen::Vector3d(start_x, target.y() - 0.5 * spec.length * cylinder.axis.y(), start_z);
    nest.push_back(cylinder);
  }
  return nest;
}

}  // namespace tendril::envs::elastica
