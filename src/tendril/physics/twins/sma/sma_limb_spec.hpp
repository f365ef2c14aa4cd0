#pragma once

#include <string>

#include "tendril/physics/rod/rod_spec.hpp"
#include "tendril/physics/twins/sma/bend_sensor.hpp"
#include "tendril/physics/twins/sma/sma_actuator.hpp"

namespace tendril::physics {

// The thesis' SMA-actuated silicone limb (seed 001, Ch. 3): a cantilevered silicone cylinder
// with four SMA coils at the cardinal directions and a two-axis bend sensor along its centre.
// The thesis gives the materials and not the geometry; the geometry is ours (docs/results/
// sma_limb.md): 100 mm long below its mount (which holds one more element), 10 mm in diameter,
// coils 3.5 mm off the centreline, hanging from the mount (z up; a 50 g load would buckle the
// soft limb standing upright). Two variants:
//   stiff: Smooth-Sil 945, 40A, modulus 260 psi ≈ 1.79 MPa (the thesis' Limb 2, purple);
//   soft:  Mold Star 30, 30A, modulus 96 psi ≈ 0.66 MPa (Limb 1, blue).
// Silicone is nearly incompressible: G = E / 3.
struct SmaLimbSpec {
  std::string name = "stiff";
  double length = 0.10;            // m, free length below the mount
  double radius = 0.005;           // m
  double density = 1240.0;         // kg/m³
  double youngs_modulus = 1.79e6;  // Pa
  // Rod discretisation: elements, and rod steps per millisecond (Δt = 1 ms / steps); see
  // docs/results/sma_limb.md for the convergence study behind the defaults.
  int n_elements = 10;
  int steps_per_millisecond = 5;
  double rotary_inertia_scale = 4.0;  // RodSpec::rotary_inertia_scale
  // Position Verlet at steps_per_millisecond is the reference. An implicit rod instead takes,
  // from one reading to the next, the fewest equal steps of at most implicit_step (s), so every
  // reading lands on its millisecond (docs/results/implicit_rods.md for the accuracy).
  RodIntegrator integrator = RodIntegrator::kPositionVerlet;
  double implicit_step = 0.005;
  // Viscous loss of the silicone as Rayleigh damping: every rate decays at this rate, 1/s.
  double damping_rate = 15.0;
  bool hanging = true;    // base up, limb along −z; false: upright along +z
  double tip_mass = 0.0;  // kg, a load fixed to the tip (the thesis: 10 g and 50 g)
  SmaActuatorSpec actuator;
  BendSensorSpec sensor;

  double time_step() const { return 1e-3 / steps_per_millisecond; }
  // Raises tendril::Error naming the first invalid field.
  void validate() const;

  static SmaLimbSpec stiff();
  static SmaLimbSpec soft();
  // "stiff" or "soft"; Error otherwise.
  static SmaLimbSpec variant(const std::string& name);
};

}  // namespace tendril::physics
