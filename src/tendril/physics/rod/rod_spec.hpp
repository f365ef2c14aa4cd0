#pragma once

#include <Eigen/Core>
#include <string>

namespace tendril::physics {

// How a rod advances in time.
enum class RodIntegrator {
  // Position Verlet (Gazzola et al. 2018, §3.3): explicit, second order, symplectic; stable
  // only below the period of the rod's fastest mode (shear against rotation).
  kPositionVerlet,
  // Backward Euler with Newton's method on the rod's Jacobian: first order, unconditionally
  // stable, damps a mode of angular frequency ω by 1/√(1 + (ωh)²) per step.
  kBackwardEuler,
  // Two-step backward differentiation (BDF2), its first step backward Euler: second order,
  // unconditionally stable, far less numerical damping of the slow modes than backward Euler.
  kBdf2,
};

// Newton's method of the implicit integrators (ImplicitStepper).
struct NewtonSettings {
  // Converged when the configuration's change still to come, estimated from the contraction of
  // the last updates, is below this: node displacements relative to the rod's length and
  // element rotations in radians.
  double tolerance = 1e-9;
  int max_iterations = 30;
  // A step whose iteration fails (max_iterations, no contraction, a singular matrix) is taken
  // again as two steps of half its length, down to 2^−max_halvings of it; beyond that (or with
  // 0) the failure raises tendril::Error. Halvings are counted (NewtonStatistics).
  int max_halvings = 4;
};

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
  // s, fixed for the rod's lifetime; implicit rods may also take steps of other lengths
  // (Rod::advance_by).
  double time_step = 2.0e-4;
  RodIntegrator integrator = RodIntegrator::kPositionVerlet;
  NewtonSettings newton;  // implicit integrators only

  // Raises tendril::Error("<field> must be ...", "RodSpec") for the first invalid field.
  void validate() const;
};

// The shear modulus of an isotropic material with Poisson ratio ν: E / (2 (1 + ν)). The
// Elastica arm uses E / (1 + 0.5), i.e. this formula's doubled form; see RodSpec::shear_modulus.
// "verlet", "backward_euler", "bdf2" and back; parsing raises tendril::Error naming the value.
const char* integrator_name(RodIntegrator integrator);
RodIntegrator parse_integrator(const std::string& name);

inline double shear_modulus_from_poisson(double youngs_modulus, double poisson_ratio) {
  return youngs_modulus / (2.0 * (1.0 + poisson_ratio));
}

}  // namespace tendril::physics
