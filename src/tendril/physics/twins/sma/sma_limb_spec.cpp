#include "tendril/physics/twins/sma/sma_limb_spec.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::physics {

void SmaLimbSpec::validate() const {
  const std::string who = "SmaLimbSpec " + name;
  auto positive = [&](double value, const char* field) {
    if (!(std::isfinite(value) && value > 0.0)) {
      throw Error(std::string(field) + " must be finite and positive, got " + std::to_string(value),
                  who);
    }
  };
  positive(length, "length");
  positive(radius, "radius");
  positive(density, "density");
  positive(youngs_modulus, "youngs_modulus");
  require(n_elements >= 2, "n_elements must be at least 2", who);
  require(steps_per_millisecond >= 1, "steps_per_millisecond must be at least 1", who);
  positive(rotary_inertia_scale, "rotary_inertia_scale");
  positive(implicit_step, "implicit_step");
  require(std::isfinite(damping_rate) && damping_rate >= 0.0,
          "damping_rate must be finite and non-negative", who);
  require(std::isfinite(tip_mass) && tip_mass >= 0.0, "tip_mass must be finite and non-negative",
          who);
  actuator.validate();
  require(actuator.tendon_offset < radius, "the coils must lie inside the limb", who);
  sensor.validate();
}

SmaLimbSpec SmaLimbSpec::stiff() {
  SmaLimbSpec spec;
  spec.name = "stiff";
  spec.density = 1240.0;          // Smooth-Sil 945: specific gravity 1.24
  spec.youngs_modulus = 1.793e6;  // 260 psi
  spec.sensor.zero_offset = Eigen::Vector2d(-10.0, -12.0);
  return spec;
}

SmaLimbSpec SmaLimbSpec::soft() {
  SmaLimbSpec spec;
  spec.name = "soft";
  spec.density = 1180.0;          // Mold Star 30: specific gravity 1.18
  spec.youngs_modulus = 0.662e6;  // 96 psi
  spec.sensor.zero_offset = Eigen::Vector2d(4.5, -7.0);
  return spec;
}

SmaLimbSpec SmaLimbSpec::variant(const std::string& name) {
  if (name == "stiff") return stiff();
  if (name == "soft") return soft();
  throw Error("unknown limb '" + name + "' (expected stiff or soft)", "SmaLimbSpec");
}

}  // namespace tendril::physics
