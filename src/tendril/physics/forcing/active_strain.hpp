#pragma once

#include "tendril/physics/rod/rod_model.hpp"
#include "tendril/physics/rod/rod_state.hpp"

namespace tendril::physics {

class RodJacobian;

// The loads of an active (spontaneous) strain: a rod whose rest strains are shifted by
// σ̂ → σ̂ + δσ (per element) and κ̂ → κ̂ + δκ (per interior Voronoi point), both in the material
// frame, feels exactly the internal loads of the unshifted rod plus these, because the kernel
// (Gazzola et al. 2018, eqs. 3.13–3.14) is linear in the stresses n = S(σ − σ̂) and couples
// τ = B(κ − κ̂). With δn = −S δσ and δτ = −B δκ they are
//   forces on nodes:     Δʰ(Qᵀ δn / e)
//   torques on elements: (Q t × δn) l̂ + Δʰ(δτ / ε³) + Aʰ(κ × δτ D̂ / ε³)
// added to the external forces (lab frame) and torques (material frame). This is how actuators
// that lengthen or curve the body itself — pressurised chambers, shape-memory coils, muscle
// fibres — enter a rod: the loads are internal (no net force; no net moment, exactly for δσ and,
// like the kernel's own bending couples, to second order in the angle between neighbouring
// elements for δκ) and do not grow with the number of elements. Must run at the kLoads stage
// (it reads the strains, dilatations and tangents of the current step's internal-load pass).
// Allocation-free.
//
// `stretch` is 3 × n (δσ per element: shear along d1, d2, stretch along d3); `curvature` is
// 3 × (n − 1) (δκ per Voronoi point, 1/m, about d1, d2, d3). The object holds the scratch of
// the computation, sized by `resize` for one rod.
class ActiveStrainLoads {
 public:
  void resize(const RodModel& model);
  void add(const RodModel& model, RodState& state, const Vectors& stretch,
           const Vectors& curvature);
  // The derivatives of the loads of the last `add` (with its shifts held fixed) for an implicit
  // step: the geometric terms of the internal loads' derivatives with the stresses δn and
  // couples δτ (internal_load_derivatives.hpp).
  void add_derivatives(const RodModel& model, const RodState& state, RodJacobian& jacobian) const;

 private:
  Vectors stresses_;      // δn = −S δσ per element
  Vectors couples_;       // δτ = −B δκ per Voronoi point
  Vectors lab_stresses_;  // Qᵀ δn / e per element
  Vectors bend_;          // δτ / ε³ per Voronoi point
  Vectors quadrature_;    // ½ (κ × δτ) D̂ / ε³ per Voronoi point
};

}  // namespace tendril::physics
