#include "tendril/physics/twins/pneumatic/pneumatic_arm_spec.hpp"

#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::physics::pneumatic {

namespace {

void require_positive(double value, const char* field, const char* where) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw Error(std::string(field) + " must be finite and positive, got " + std::to_string(value),
                where);
  }
}

void require_non_negative(double value, const char* field, const char* where) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw Error(
        std::string(field) + " must be finite and non-negative, got " + std::to_string(value),
        where);
  }
}

}  // namespace

void StochasticEffects::validate() const {
  const char* where = "StochasticEffects";
  require_non_negative(drift_step, "drift_step", where);
  require_non_negative(drift_cap, "drift_cap", where);
  require_non_negative(hysteresis_width, "hysteresis_width", where);
  if (!(gain_spread >= 0.0 && gain_spread < 1.0)) {
    throw Error("gain_spread must lie in [0, 1), got " + std::to_string(gain_spread), where);
  }
  require_non_negative(eccentricity, "eccentricity", where);
  require_non_negative(marker_noise, "marker_noise", where);
  if (!(elasticity_sigma >= 0.0 && elasticity_sigma < 0.5)) {
    throw Error("elasticity_sigma must lie in [0, 0.5), got " + std::to_string(elasticity_sigma),
                where);
  }
}

int PneumaticArmSpec::steps_per_sample() const {
  return static_cast<int>(std::lround(sensor.sample_period / time_step));
}

void PneumaticArmSpec::validate() const {
  const char* where = "PneumaticArmSpec";
  require_positive(length, "length", where);
  if (elements_per_module < 1) {
    throw Error(
        "elements_per_module must be at least 1, got " + std::to_string(elements_per_module),
        where);
  }
  require_positive(radius, "radius", where);
  require_positive(density, "density", where);
  require_positive(youngs_modulus, "youngs_modulus", where);
  if (!(poisson_ratio > -1.0 && poisson_ratio <= 0.5)) {
    throw Error("poisson_ratio must lie in (-1, 0.5], got " + std::to_string(poisson_ratio), where);
  }
  require_non_negative(translational_damping, "translational_damping", where);
  require_non_negative(rotational_damping, "rotational_damping", where);
  require_non_negative(gravity, "gravity", where);
  require_positive(time_step, "time_step", where);
  require_non_negative(bend_per_bar, "bend_per_bar", where);
  require_non_negative(extension_per_bar, "extension_per_bar", where);
  for (double rotation : chamber_rotation) {
    if (!std::isfinite(rotation)) throw Error("chamber_rotation must be finite", where);
  }
  regulators.validate();
  if (damaged_chamber < 0 || damaged_chamber >= kChambersPerModule) {
    throw Error("damaged_chamber must be 0, 1 or 2, got " + std::to_string(damaged_chamber), where);
  }
  sensor.validate();
  const double steps = sensor.sample_period / time_step;
  if (steps < 1.0 - 1e-9 || std::abs(steps - std::round(steps)) > 1e-6) {
    throw Error("time_step (" + std::to_string(time_step) +
                    " s) must divide the sensor's sample period (" +
                    std::to_string(sensor.sample_period) + " s)",
                where);
  }
  effects.validate();
  require_non_negative(settle_time, "settle_time", where);
}

}  // namespace tendril::physics::pneumatic
