#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/envs/env_description.hpp"
#include "tendril/physics/rod/rod_spec.hpp"

namespace tendril::envs::tendon_arm {

// The tendon-driven continuum arm's twin parameters (SI units, lab frame: z up, the arm clamped at
// the origin and hanging along −z under gravity, its first tendon on the +x side).
//
// The arm is a cast silicone body of the kind many soft tendon-driven arms are made of, with
// straight tendons routed through channels at a fixed offset from its centreline (Rucker & Webster
// 2011's straight routing), pulled by motors that set their tensions. Numbers ([A]: chosen as a
// representative build, not one measured prototype):
//   body     Dragon Skin 30 class platinum silicone: density 1080 kg/m³ and a tensile modulus of
//            0.59 MPa (the maker's data sheet: specific gravity 1.08, 100 % modulus 86 psi);
//            shear modulus E/3 (incompressible rubber)
//   shape    0.30 m long, 12 mm radius (0.147 kg): bending stiffness E I = 9.6e-3 N m²
//   tendons  3, at 120° (0°, 120°, 240° from +x about the axis), 9 mm from the centreline
//   tensions 0 … 6 N each (a small geared DC motor on a 5 mm spool): one tendon alone bends the
//            arm, gravity off, to κ = T r / (E I) = 5.6 1/m, 97° over its length
//   damping  velocities decay at 8 1/s (a lumped, linear stand-in for the silicone's internal
//            losses and the air, so that a step response settles within about half a second)
// Numerics: 20 elements, position Verlet at 0.2 ms (the fastest mode, shear against rotation,
// allows about 0.7 ms).
struct ArmSpec {
  double length = 0.30;            // m
  double radius = 0.012;           // m
  double density = 1080.0;         // kg/m³
  double youngs_modulus = 0.59e6;  // Pa
  double tendon_offset = 0.009;    // m from the centreline
  int tendons = 3;                 // evenly spaced about the axis, the first towards +x
  double max_tension = 6.0;        // N, each
  double damping_rate = 8.0;       // 1/s
  bool gravity = true;             // 9.80665 m/s² along −z
  int elements = 20;
  double time_step = 2.0e-4;    // s
  double control_period = 0.1;  // s, a whole number of time steps

  // The rod this spec describes: base at the origin, hanging along −z, d1 = +x.
  physics::RodSpec rod_spec() const;
  // Tendon k's offset in the material frame (d1, d2 components; m).
  std::vector<Eigen::Vector3d> tendon_offsets() const;
  double bending_stiffness() const;  // E I, N m²
  int substeps() const;              // rod steps per control period
  // Raises tendril::Error naming the first invalid field.
  void validate() const;
};

// The spec from an environment's parameters (every key optional; defaults as above):
//   length_m, radius_m, density_kg_m3, youngs_modulus_pa, tendon_offset_m, tendons (3 or 4),
//   max_tension_n, damping_per_s, gravity (true/false), elements, time_step_s, control_period_s.
// Raises tendril::Error naming the key of a bad value.
ArmSpec arm_spec_from(const Config& params);

// ArmSpec's keys for an environment's description, each behind `prefix` ("" or "robot.").
std::vector<EnvDescription::Parameter> arm_parameters(const std::string& prefix);

}  // namespace tendril::envs::tendon_arm
