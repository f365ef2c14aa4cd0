#include "tendril/physics/rod/rod_spec.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::physics {

namespace {

void require_positive(double value, const char* field) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw Error(std::string(field) + " must be finite and positive, got " + std::to_string(value),
                "RodSpec");
  }
}

void require_unit(const Eigen::Vector3d& v, const char* field) {
  if (!v.allFinite() || std::abs(v.norm() - 1.0) > 1e-9) {
    throw Error(std::string(field) + " must be a finite unit vector", "RodSpec");
  }
}

}  // namespace

void RodSpec::validate() const {
  if (n_elements < 1) {
    throw Error("n_elements must be at least 1, got " + std::to_string(n_elements), "RodSpec");
  }
  require_positive(length, "length");
  require_positive(radius, "radius");
  require_positive(density, "density");
  require_positive(youngs_modulus, "youngs_modulus");
  require_positive(shear_modulus, "shear_modulus");
  require_positive(shear_coefficient, "shear_coefficient");
  require_positive(time_step, "time_step");
  require_positive(rotary_inertia_scale, "rotary_inertia_scale");
  if (!base_position.allFinite()) throw Error("base_position must be finite", "RodSpec");
  require_unit(direction, "direction");
  require_unit(normal, "normal");
  if (std::abs(direction.dot(normal)) > 1e-9) {
    throw Error("normal must be perpendicular to direction", "RodSpec");
  }
  if (!rest_curvature.allFinite()) throw Error("rest_curvature must be finite", "RodSpec");
  if (!(std::isfinite(tip_mass) && tip_mass >= 0.0)) {
    throw Error("tip_mass must be finite and non-negative, got " + std::to_string(tip_mass),
                "RodSpec");
  }
  require_positive(newton.tolerance, "newton.tolerance");
  if (newton.max_halvings < 0 || newton.max_halvings > 20) {
    throw Error(
        "newton.max_halvings must lie in [0, 20], got " + std::to_string(newton.max_halvings),
        "RodSpec");
  }
  if (newton.max_iterations < 1) {
    throw Error(
        "newton.max_iterations must be at least 1, got " + std::to_string(newton.max_iterations),
        "RodSpec");
  }
}

const char* integrator_name(RodIntegrator integrator) {
  switch (integrator) {
    case RodIntegrator::kPositionVerlet:
      return "verlet";
    case RodIntegrator::kBackwardEuler:
      return "backward_euler";
    case RodIntegrator::kBdf2:
      return "bdf2";
  }
  return "?";
}

RodIntegrator parse_integrator(const std::string& name) {
  for (RodIntegrator integrator :
       {RodIntegrator::kPositionVerlet, RodIntegrator::kBackwardEuler, RodIntegrator::kBdf2}) {
    if (name == integrator_name(integrator)) return integrator;
  }
  throw Error("unknown integrator '" + name + "' (expected verlet, backward_euler or bdf2)",
              "RodSpec");
}

}  // namespace tendril::physics
