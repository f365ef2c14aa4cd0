#include "tendril/physics/rod/internal_loads.hpp"

#include <cmath>

#include "tendril/physics/rod/rotation.hpp"

namespace tendril::physics {

namespace {

// Element geometry and shear/stretch strain, σ_i = e_i Q_i t_i − d3 = Q_i (x_{i+1} − x_i)/l̂_i − ẑ.
inline void element_geometry(const RodModel& model, RodState& state, int i) {
  const Eigen::Vector3d edge = state.positions.col(i + 1) - state.positions.col(i);
  const double length = edge.norm();
  const double rest_length = model.rest_lengths[i];
  const double dilatation = length / rest_length;
  state.lengths[i] = length;
  state.tangents.col(i) = edge / length;
  state.dilatations[i] = dilatation;
  state.radii[i] = model.rest_radii[i] / std::sqrt(dilatation);
  Eigen::Vector3d sigma = state.directors[i] * edge / rest_length;
  sigma.z() -= 1.0;
  state.shear_strains.col(i) = sigma;
}

// Curvature at Voronoi point j: Q_{j+1} = exp(−D̂ [κ]×) Q_j, so κ_j = −log(Q_{j+1} Q_jᵀ)^∨ / D̂_j.
inline void voronoi_geometry(const RodModel& model, RodState& state, int j) {
  const Eigen::Matrix3d relative = state.directors[j + 1] * state.directors[j].transpose();
  state.curvatures.col(j) = -log_rotation(relative) / model.rest_voronoi_lengths[j];
  state.voronoi_dilatations[j] = (state.lengths[j] + state.lengths[j + 1]) /
                                 (model.rest_lengths[j] + model.rest_lengths[j + 1]);
}

}  // namespace

void compute_strains(const RodModel& model, RodState& state) {
  const int n = model.n_elements;
  for (int i = 0; i < n; ++i) element_geometry(model, state, i);
  for (int j = 0; j + 1 < n; ++j) voronoi_geometry(model, state, j);
}

void compute_internal_loads(const RodModel& model, RodState& state) {
  const int n = model.n_elements;
  state.internal_forces.setZero();

  // Shear/stretch: stress, nodal forces, shear couple, and the rate-dependent torque terms.
  for (int i = 0; i < n; ++i) {
    element_geometry(model, state, i);
    const Eigen::Matrix3d& q = state.directors[i];
    const double e = state.dilatations[i];
    const Eigen::Vector3d stress =
        model.shear_stiffness.col(i).cwiseProduct(state.shear_strains.col(i) -
                                                  model.rest_shear_strains.col(i));
    state.internal_stresses.col(i) = stress;
    const Eigen::Vector3d lab_stress = q.transpose() * stress / e;
    state.internal_forces.col(i) += lab_stress;
    state.internal_forces.col(i + 1) -= lab_stress;

    // de/dt = (x_{i+1} − x_i)·(v_{i+1} − v_i) / (l l̂).
    const Eigen::Vector3d edge = state.positions.col(i + 1) - state.positions.col(i);
    const Eigen::Vector3d edge_rate = state.velocities.col(i + 1) - state.velocities.col(i);
    const double dilatation_rate = edge.dot(edge_rate) / (state.lengths[i] * model.rest_lengths[i]);
    state.dilatation_rates[i] = dilatation_rate;

    const Eigen::Vector3d omega = state.angular_velocities.col(i);
    const Eigen::Vector3d j_omega_over_e = model.inertia.col(i).cwiseProduct(omega) / e;
    const Eigen::Vector3d material_tangent = q * state.tangents.col(i);
    state.internal_torques.col(i) = material_tangent.cross(stress) * model.rest_lengths[i]  // shear
                                    + j_omega_over_e.cross(omega)        // Lagrangian transport
                                    + j_omega_over_e * dilatation_rate / e;  // unsteady dilatation
  }

  // Bend/twist: couples at Voronoi points, distributed to the two neighbouring elements by the
  // difference operator Δʰ, and the trapezoidal quadrature Aʰ of κ × τ.
  for (int j = 0; j + 1 < n; ++j) {
    voronoi_geometry(model, state, j);
    const Eigen::Vector3d kappa = state.curvatures.col(j);
    const Eigen::Vector3d couple =
        model.bend_stiffness.col(j).cwiseProduct(kappa - model.rest_curvatures.col(j));
    state.internal_couples.col(j) = couple;
    const double eps = state.voronoi_dilatations[j];
    const double inv_eps3 = 1.0 / (eps * eps * eps);
    const Eigen::Vector3d bend = couple * inv_eps3;
    const Eigen::Vector3d half_quadrature =
        0.5 * kappa.cross(couple) * (model.rest_voronoi_lengths[j] * inv_eps3);
    state.internal_torques.col(j) += bend + half_quadrature;
    state.internal_torques.col(j + 1) += -bend + half_quadrature;
  }
}

}  // namespace tendril::physics
