#pragma once

#include <Eigen/Core>
#include <string>

namespace tendril::physics {

// What a user specifies to build a straight Cosserat rod (SI units, lab frame). Validated by
// `validate()` when a rod is built: a bad value raises tendril::Error naming the field.
struct RodSpec {
  int n_elements = 20;
  double length = 1.0;                      // m
  double radius = 0.05;                     // m, uniform at rest
  double density = 1000.0;                  // kg/m³
  double youngs_modulus = 1.0e7;            // Pa
  // Shear modulus, Pa. Paper-era engine: E / (1 + ν) with ν = 0.5; modern default: E / 3.
  double shear_modulus = 1.0e7 / 1.5;
  // Timoshenko shear coefficient α_c in S = diag(α_c G A, α_c G A, E A); 4/3 in the paper-era
  // engine, 27/28 in modern PyElastica.
  double shear_coefficient = 4.0 / 3.0;
  Eigen::Vector3d base_position = Eigen::Vector3d::Zero();  // node 0
  Eigen::Vector3d direction = Eigen::Vector3d::UnitY();     // d3 at rest, unit
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();        // d1 at rest, unit, ⊥ direction
  // Intrinsic curvature κ̂ (material frame, 1/m), the same on every Voronoi point.
  Eigen::Vector3d rest_curvature = Eigen::Vector3d::Zero();
  // A point mass carried by the last node (a load fixed to the tip), kg; adds to that node's
  // mass, hence to its inertia and, with Gravity, to its weight.
  double tip_mass = 0.0;
  // Factor on the elements' rotary inertia ρ l̂ I. Its fastest mode (shear against rotation,
  // ω² ≈ 4 α_c G / (ρ r²), whatever the mesh) often bounds the explicit time step; the rotary
  // inertia of a slender rod hardly affects its bending (a correction of order (r/L)²), so
  // scaling it up is the usual way to afford a larger step. 1: the physical inertia.
  double rotary_inertia_scale = 1.0;
  double time_step = 2.0e-4;  // s, fixed for the rod's lifetime (position Verlet)

  // Raises tendril::Error("<field> must be ...", "RodSpec") for the first invalid field.
  void validate() const;
};

// The shear modulus of an isotropic material with Poisson ratio ν: E / (2 (1 + ν)). The
// Elastica arm uses E / (1 + 0.5), i.e. this formula's doubled form; see RodSpec::shear_modulus.
inline double shear_modulus_from_poisson(double youngs_modulus, double poisson_ratio) {
  return youngs_modulus / (2.0 * (1.0 + poisson_ratio));
}

}  // namespace tendril::physics
