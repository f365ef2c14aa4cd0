#include "tendril/physics/twins/sma/sma_coil.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::physics {

void SmaCoilSpec::validate() const {
  thermal.validate();
  transformation.validate();
  const char* who = "SmaCoilSpec";
  auto non_negative = [&](double value, const char* field) {
    if (!(std::isfinite(value) && value >= 0.0)) {
      throw Error(
          std::string(field) + " must be finite and non-negative, got " + std::to_string(value),
          who);
    }
  };
  non_negative(martensite_stiffness, "martensite_stiffness");
  non_negative(austenite_stiffness, "austenite_stiffness");
  non_negative(memory_contraction, "memory_contraction");
  non_negative(prestretch, "prestretch");
  non_negative(damage_rate, "damage_rate");
  require(std::isfinite(damage_temperature), "damage_temperature must be finite", who);
}

SmaCoilState SmaCoilState::rested(const SmaCoilSpec& spec, double degradation) {
  require(degradation >= 0.0 && degradation <= 1.0, "degradation must lie in [0, 1]",
          "SmaCoilState");
  SmaCoilState state;
  state.wire_temperature = spec.thermal.ambient_temperature;
  state.body_temperature = spec.thermal.ambient_temperature;
  state.phase = PhaseState::rested(spec.thermal.ambient_temperature);
  state.degradation = degradation;
  return state;
}

CoilTensionLaw coil_tension_law(const SmaCoilSpec& spec, const SmaCoilState& state) {
  const double xi = state.phase.martensite;
  const double stiffness = xi * spec.martensite_stiffness + (1.0 - xi) * spec.austenite_stiffness;
  const double contraction = (1.0 - xi) * (1.0 - state.degradation) * spec.memory_contraction;
  return {stiffness * (spec.prestretch + contraction), stiffness};
}

void advance_coil(const SmaCoilSpec& spec, const CoilThermal& thermal, SmaCoilState& state,
                  double duty, double h) {
  thermal.advance(state.wire_temperature, state.body_temperature, spec.thermal.power(duty), h);
  update_phase(spec.transformation, state.phase, state.wire_temperature, spec.phase_reentry);
  const double excess = state.wire_temperature - spec.damage_temperature;
  if (excess > 0.0) {
    state.degradation = std::min(1.0, state.degradation + spec.damage_rate * excess * h);
  }
}

}  // namespace tendril::physics
