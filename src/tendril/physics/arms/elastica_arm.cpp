#include "tendril/physics/arms/elastica_arm.hpp"

#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/damping.hpp"

namespace tendril::physics {

ElasticaArmSpec ElasticaArmSpec::tracking() { return ElasticaArmSpec{}; }

ElasticaArmSpec ElasticaArmSpec::structured_obstacles() {
  ElasticaArmSpec spec;
  spec.n_elements = 50;
  spec.time_step = 1.0e-4;
  spec.base_position = Eigen::Vector3d(0.0, 0.5, 0.0);
  spec.direction = Eigen::Vector3d::UnitZ();
  spec.normal = Eigen::Vector3d::UnitY();
  spec.actuation.control_points = 2;
  spec.actuation.directions = {true, false, false};
  spec.actuation.max_change_per_step = 0.01;
  // (x, z) of the axes: two posts, then a wall at x = −0.4 with one gap (SPEC M2, case 3).
  const double xz[8][2] = {{-0.6, 0.12}, {-0.2, 0.12}, {-0.4, 0.37}, {-0.4, 0.00},
                           {-0.4, -0.20}, {-0.4, -0.40}, {-0.4, 0.57}, {-0.4, 0.77}};
  for (const auto& position : xz) {
    spec.obstacles.push_back(
        Cylinder{Eigen::Vector3d(position[0], 0.0, position[1]), Eigen::Vector3d::UnitY(), 1.0, 0.1});
  }
  return spec;
}

ElasticaArm build_elastica_arm(const ElasticaArmSpec& spec) {
  RodSpec rod_spec;
  rod_spec.n_elements = spec.n_elements;
  rod_spec.length = 1.0;
  rod_spec.radius = 0.05;
  rod_spec.density = 1000.0;
  rod_spec.youngs_modulus = 1.0e7;
  rod_spec.shear_modulus = rod_spec.youngs_modulus / (1.0 + 0.5);
  rod_spec.shear_coefficient = 4.0 / 3.0;
  rod_spec.base_position = spec.base_position;
  rod_spec.direction = spec.direction;
  rod_spec.normal = spec.normal;
  rod_spec.time_step = spec.time_step;
  rod_spec.integrator = spec.integrator;
  SplineActuationSpec actuation = spec.actuation;
  if (spec.integrator != RodIntegrator::kPositionVerlet) {
    rod_spec.time_step = spec.implicit_step;
    actuation.max_change_per_step *= spec.implicit_step / spec.time_step;
  }
  ElasticaArm arm{Rod(rod_spec), nullptr, nullptr};
  arm.rod.add<FixedEnd>();
  arm.rod.add<InternalDamping>(spec.damping);
  arm.muscles = &arm.rod.add<SplineActuation>(actuation);
  if (!spec.obstacles.empty()) arm.contact = &arm.rod.add<CylinderContact>(spec.obstacles, spec.wall);
  return arm;
}

}  // namespace tendril::physics
