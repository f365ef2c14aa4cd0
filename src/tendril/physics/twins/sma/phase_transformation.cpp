#include "tendril/physics/twins/sma/phase_transformation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::physics {

namespace {

// H(T): the fraction of the martensite present at As that is left at T on heating.
double heating_curve(const TransformationTemperatures& t, double temperature) {
  if (temperature <= t.austenite_start) return 1.0;
  if (temperature >= t.austenite_finish) return 0.0;
  const double phase = (temperature - t.austenite_start) / (t.austenite_finish - t.austenite_start);
  return 0.5 * (1.0 + std::cos(std::numbers::pi * phase));
}

// C(T): the fraction of the austenite present at Ms that has turned back by T on cooling.
double cooling_curve(const TransformationTemperatures& t, double temperature) {
  if (temperature >= t.martensite_start) return 0.0;
  if (temperature <= t.martensite_finish) return 1.0;
  const double phase =
      (t.martensite_start - temperature) / (t.martensite_start - t.martensite_finish);
  return 0.5 * (1.0 - std::cos(std::numbers::pi * phase));
}

}  // namespace

void TransformationTemperatures::validate() const {
  const char* who = "TransformationTemperatures";
  require(std::isfinite(austenite_start) && std::isfinite(austenite_finish) &&
              std::isfinite(martensite_start) && std::isfinite(martensite_finish),
          "transformation temperatures must be finite", who);
  require(austenite_start < austenite_finish, "austenite_start must be below austenite_finish",
          who);
  require(martensite_finish < martensite_start, "martensite_finish must be below martensite_start",
          who);
}

PhaseState PhaseState::rested(double temperature) {
  PhaseState state;
  state.temperature = temperature;
  state.heating_anchor = {temperature, 1.0, 1.0};
  state.cooling_anchor = {temperature, 1.0, 1.0};
  return state;
}

void update_phase(const TransformationTemperatures& t, PhaseState& state, double temperature,
                  PhaseReentry reentry) {
  if (temperature == state.temperature) return;
  const double before = state.martensite;
  const bool heating = temperature > state.temperature;
  if (heating != state.heating) {
    PhaseState::Anchor& left = state.heating ? state.heating_anchor : state.cooling_anchor;
    left.left_at = state.martensite;
    PhaseState::Anchor& entered = heating ? state.heating_anchor : state.cooling_anchor;
    if (state.martensite != entered.left_at) {
      entered.temperature = state.temperature;
      entered.martensite = state.martensite;
    }
    state.heating = heating;
  }
  if (heating) {
    const PhaseState::Anchor& anchor = state.heating_anchor;
    const double at_anchor = heating_curve(t, anchor.temperature);
    state.martensite =
        at_anchor > 0.0 ? anchor.martensite * heating_curve(t, temperature) / at_anchor : 0.0;
  } else {
    const PhaseState::Anchor& anchor = state.cooling_anchor;
    const double at_anchor = cooling_curve(t, anchor.temperature);
    state.martensite = at_anchor < 1.0
                           ? anchor.martensite + (1.0 - anchor.martensite) *
                                                     (cooling_curve(t, temperature) - at_anchor) /
                                                     (1.0 - at_anchor)
                           : 1.0;
  }
  if (reentry == PhaseReentry::kContinuous) {
    state.martensite =
        heating ? std::min(before, state.martensite) : std::max(before, state.martensite);
  }
  state.temperature = temperature;
}

}  // namespace tendril::physics
