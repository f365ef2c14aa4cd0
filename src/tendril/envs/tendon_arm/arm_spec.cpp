#include "tendril/envs/tendon_arm/arm_spec.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs::tendon_arm {

namespace {

constexpr const char* kWhere = "tendon_arm::ArmSpec";

double positive(const Config& params, const std::string& key, double fallback) {
  const double value = params.get_or<double>(key, fallback);
  if (!(std::isfinite(value) && value > 0.0)) {
    throw Error("must be finite and positive, got " + std::to_string(value), params.where(key));
  }
  return value;
}

}  // namespace

physics::RodSpec ArmSpec::rod_spec() const {
  physics::RodSpec spec;
  spec.n_elements = elements;
  spec.length = length;
  spec.radius = radius;
  spec.density = density;
  spec.youngs_modulus = youngs_modulus;
  spec.shear_modulus = youngs_modulus / 3.0;
  spec.direction = -Eigen::Vector3d::UnitZ();
  spec.normal = Eigen::Vector3d::UnitX();
  spec.time_step = time_step;
  return spec;
}

std::vector<Eigen::Vector3d> ArmSpec::tendon_offsets() const {
  std::vector<Eigen::Vector3d> offsets;
  for (int k = 0; k < tendons; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / tendons;
    offsets.emplace_back(tendon_offset * std::cos(angle), tendon_offset * std::sin(angle), 0.0);
  }
  return offsets;
}

double ArmSpec::bending_stiffness() const {
  return youngs_modulus * std::numbers::pi * std::pow(radius, 4) / 4.0;
}

int ArmSpec::substeps() const { return static_cast<int>(std::lround(control_period / time_step)); }

void ArmSpec::validate() const {
  for (const auto& [name, value] : {std::pair{"length", length},
                                    {"radius", radius},
                                    {"density", density},
                                    {"youngs_modulus", youngs_modulus},
                                    {"tendon_offset", tendon_offset},
                                    {"max_tension", max_tension},
                                    {"time_step", time_step},
                                    {"control_period", control_period}}) {
    require(std::isfinite(value) && value > 0.0, std::string(name) + " must be positive", kWhere);
  }
  require(std::isfinite(damping_rate) && damping_rate >= 0.0, "damping_rate must be >= 0", kWhere);
  require(tendon_offset < radius, "tendon_offset must lie inside the body (< radius)", kWhere);
  require(tendons == 3 || tendons == 4, "tendons must be 3 or 4", kWhere);
  require(elements >= 2, "elements must be at least 2", kWhere);
  const double steps = control_period / time_step;
  require(std::abs(steps - std::round(steps)) < 1e-6 && steps >= 1.0 - 1e-9,
          "control_period must be a whole number of time steps", kWhere);
}

ArmSpec arm_spec_from(const Config& params) {
  ArmSpec spec;
  spec.length = positive(params, "length_m", spec.length);
  spec.radius = positive(params, "radius_m", spec.radius);
  spec.density = positive(params, "density_kg_m3", spec.density);
  spec.youngs_modulus = positive(params, "youngs_modulus_pa", spec.youngs_modulus);
  spec.tendon_offset = positive(params, "tendon_offset_m", spec.tendon_offset);
  spec.tendons = params.get_or<int>("tendons", spec.tendons);
  spec.max_tension = positive(params, "max_tension_n", spec.max_tension);
  spec.damping_rate = params.get_or<double>("damping_per_s", spec.damping_rate);
  spec.gravity = params.get_or<bool>("gravity", spec.gravity);
  spec.elements = params.get_or<int>("elements", spec.elements);
  spec.time_step = positive(params, "time_step_s", spec.time_step);
  spec.control_period = positive(params, "control_period_s", spec.control_period);
  try {
    spec.validate();
  } catch (const Error& e) {
    throw Error(e.what_wrong(),
                params.source() + (params.path().empty() ? "" : ": " + params.path()));
  }
  return spec;
}

std::vector<EnvDescription::Parameter> arm_parameters(const std::string& prefix) {
  return {{prefix + "length_m", "m", "the arm's length"},
          {prefix + "radius_m", "m", "the body's radius"},
          {prefix + "density_kg_m3", "kg/m³", "the body's density (silicone)"},
          {prefix + "youngs_modulus_pa", "Pa", "the body's Young's modulus"},
          {prefix + "tendon_offset_m", "m", "the tendons' distance from the centreline"},
          {prefix + "tendons", "", "3 (at 120°) or 4 (at 90°); sets the action's size"},
          {prefix + "max_tension_n", "N", "the largest tension a motor pulls"},
          {prefix + "damping_per_s", "1/s", "lumped damping rate of the body"},
          {prefix + "gravity", "", "whether the arm hangs under gravity"},
          {prefix + "elements", "", "rod elements along the arm"},
          {prefix + "time_step_s", "s", "the rod's explicit time step"},
          {prefix + "control_period_s", "s", "how long a step holds the tensions"}};
}

}  // namespace tendril::envs::tendon_arm
