#pragma once

#include "tendril/physics/twins/sma/coil_thermal.hpp"
#include "tendril/physics/twins/sma/phase_transformation.hpp"

namespace tendril::physics {

// One SMA coil embedded along the limb: its heat balance, its phase and the force it pulls with.
//
// The coil is a spring between the limb's base and tip whose stiffness and free length depend on
// the martensite fraction ξ: austenite is stiffer (Flexinol: E_A ≈ 83 GPa, E_M ≈ 28 GPa) and
// remembers a shorter shape. Stretched by s (m) beyond its martensite free length, it pulls with
//   T = max(0, k(ξ) (s + (1 − ξ)(1 − d) δ)),   k(ξ) = ξ k_M + (1 − ξ) k_A,
// δ the memory contraction (how much shorter a fully austenite coil is) and d ∈ [0, 1] its
// degradation. Along the limb s = s₀ + (l − l̂): the pre-stretch at rest plus the tendon's change
// of length, so a coil on the inside of a bend slackens and one on the outside is stretched —
// the antagonist resists. A coil only pulls.
//
// Over-heating destroys the shape memory (seed 001, §4.2.1: "prolonged exposure to high current
// can generate excessive heat ... the material ... unable to contract"): above damage_temperature
// the degradation grows at damage_rate per kelvin of excess per second, and never heals. The
// default, 150 °C, lies above what bending to the 100° cut-off takes (the wire finishes
// transforming at 125 °C): long holds at high duty that do not reach the cut-off — a loaded or
// blocked limb — wear the coils, normal exploration does not.
struct SmaCoilSpec {
  CoilThermalSpec thermal;
  TransformationTemperatures transformation;
  double martensite_stiffness = 75.0;  // k_M, N/m
  double austenite_stiffness = 200.0;  // k_A, N/m
  double memory_contraction = 0.038;   // δ, m
  double prestretch = 0.0;             // s₀, m
  double damage_temperature = 150.0;   // °C
  double damage_rate = 2.5e-4;         // 1/(K·s)
  // How a re-entered phase branch continues (phase_transformation.hpp); the twin's data sets
  // were made with kResume.
  PhaseReentry phase_reentry = PhaseReentry::kResume;

  void validate() const;
};

struct SmaCoilState {
  double wire_temperature = 22.0;  // °C
  double body_temperature = 22.0;  // °C
  PhaseState phase;
  double degradation = 0.0;  // d

  static SmaCoilState rested(const SmaCoilSpec& spec, double degradation = 0.0);
};

// The coil's tension law in the form Tendons takes: T = max(0, at_rest + stiffness (l − l̂)).
struct CoilTensionLaw {
  double at_rest = 0.0;    // N
  double stiffness = 0.0;  // N/m
};
CoilTensionLaw coil_tension_law(const SmaCoilSpec& spec, const SmaCoilState& state);

// Advances the coil by `h` seconds at PWM duty `duty` ∈ [0, 1]: exact heat balance, then the
// phase at the new wire temperature, then the damage of the step (at its final temperature).
void advance_coil(const SmaCoilSpec& spec, const CoilThermal& thermal, SmaCoilState& state,
                  double duty, double h);

}  // namespace tendril::physics
