#pragma once

#include "tendril/physics/rod/rod_model.hpp"
#include "tendril/physics/rod/rod_state.hpp"

namespace tendril::physics {

// From the current configuration (positions, velocities, directors, angular velocities), derives
// geometry, strains and stresses and the internal forces (lab frame, per node) and torques
// (material frame, per element) of the discrete Cosserat rod, Gazzola et al. 2018, eqs. 3.13–3.14:
//   forces:  Δʰ(Qᵀ S (σ − σ̂) / e)
//   torques: Δʰ(B(κ − κ̂)/ε³) + Aʰ(κ × B(κ − κ̂) D̂/ε³) + (Q t × n) l̂ + (J ω/e) × ω
//            + (J ω/e²) de/dt
// Allocation-free.
void compute_internal_loads(const RodModel& model, RodState& state);

// Only the geometric part (lengths, tangents, dilatations, radii, strains, curvatures); used by
// read-outs that must not disturb the loads of a step in progress.
void compute_strains(const RodModel& model, RodState& state);

}  // namespace tendril::physics
