#pragma once

#include "tendril/physics/rod/rod_jacobian.hpp"
#include "tendril/physics/rod/rod_model.hpp"
#include "tendril/physics/rod/rod_state.hpp"

namespace tendril::physics {

// Derivatives of the internal loads of the discrete Cosserat rod (internal_loads.hpp; Gazzola
// et al. 2018, eqs. 3.13–3.14) with respect to node displacements and velocities (lab frame) and
// element rotations and angular velocities (material frame), added to an implicit step's
// Newton matrix. With e = x_{i+1} − x_i, ε = |e|/l̂, t = e/|e|, m = Q e/l̂ = σ + d3 and the
// stress n = S (σ − σ̂) of element i, and Q → exp(−[δθ]×) Q:
//   lab stress s = Qᵀ n/ε:  ∂s/∂e = Qᵀ S Q/(ε l̂) − Qᵀ n tᵀ/(ε² l̂),  ∂s/∂θ = Qᵀ (S [m]× − [n]×)/ε
//   shear couple l̂ (m/ε) × n:  ∂/∂e = G Q/ε − (m × n) tᵀ/ε²,  ∂/∂θ = l̂ G [m]×/ε,
//     G = [m]× S − [n]×;
// at Voronoi point j, κ = −log(Q_{j+1} Q_jᵀ)^∨/D̂ changes by
//   δκ = J_l⁻¹(D̂ κ) (δθ_{j+1} − Q_{j+1} Q_jᵀ δθ_j)/D̂   (J_l the left Jacobian of SO(3)),
// and the couples τ/ε³ and ½ D̂ (κ × τ)/ε³ with τ = B (κ − κ̂) follow by the chain rule through
// κ and through ε = (l_j + l_{j+1})/(l̂_j + l̂_{j+1}). The element's inertial torques
// (J ω/e) × ω and (J ω/e²) de/dt enter through their rates and their edge. Requires the
// state's internal loads to be current (compute_internal_loads).
void add_internal_load_derivatives(const RodModel& model, const RodState& state,
                                   RodJacobian& jacobian);

// The same for loads of the internal-load form whose stresses n (3 × n) and couples τ
// (3 × (n − 1)) are held fixed — the loads of an active strain, n = −S δσ and τ = −B δκ
// (active_strain.hpp): only the geometric terms, without S and B.
void add_fixed_stress_derivatives(const RodModel& model, const RodState& state,
                                  const Vectors& stresses, const Vectors& couples,
                                  RodJacobian& jacobian);

// The inverse of SO(3)'s left Jacobian at the rotation vector ψ: log(exp([a]×) exp([ψ]×)) =
// ψ + J_l⁻¹(ψ) a + O(|a|²).
Eigen::Matrix3d inverse_left_jacobian(const Eigen::Vector3d& psi);

}  // namespace tendril::physics
