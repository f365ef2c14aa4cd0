#include "tendril/physics/forcing/active_strain.hpp"

#include <Eigen/Geometry>

namespace tendril::physics {

void add_active_strain_loads(const RodModel& model, RodState& state, const Vectors& stretch,
                             const Vectors& curvature) {
  const int n = model.n_elements;

  // Stretch and shear: δn_i = −S_i δσ_i (material frame). Node j receives δs_j − δs_{j−1} with
  // δs_i = Q_iᵀ δn_i / e_i (zero ghosts beyond the ends), element i the couple (Q t × δn) l̂.
  Eigen::Vector3d previous = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d dn(-model.shear_stiffness(0, i) * stretch(0, i),
                             -model.shear_stiffness(1, i) * stretch(1, i),
                             -model.shear_stiffness(2, i) * stretch(2, i));
    const Eigen::Matrix3d q = state.director(i);
    const Eigen::Vector3d lab = q.transpose() * dn / state.dilatations[i];
    state.external_forces.col(i) += lab - previous;
    previous = lab;
    const Eigen::Vector3d material_tangent = q * state.tangents.col(i);
    state.external_torques.col(i) += material_tangent.cross(dn) * model.rest_lengths[i];
  }
  state.external_forces.col(n) -= previous;

  // Bending and twist: δτ_j = −B_j δκ_j at Voronoi point j, between elements j and j + 1;
  // element i receives b_i − b_{i−1} + a_i + a_{i−1} with b = δτ/ε³ and a = ½ (κ × δτ) D̂/ε³.
  const int count = model.n_voronoi();
  for (int j = 0; j < count; ++j) {
    const Eigen::Vector3d dtau(-model.bend_stiffness(0, j) * curvature(0, j),
                               -model.bend_stiffness(1, j) * curvature(1, j),
                               -model.bend_stiffness(2, j) * curvature(2, j));
    const double eps = state.voronoi_dilatations[j];
    const double inv_eps3 = 1.0 / (eps * eps * eps);
    const Eigen::Vector3d bend = dtau * inv_eps3;
    const Eigen::Vector3d kappa = state.curvatures.col(j);
    const Eigen::Vector3d quadrature =
        kappa.cross(dtau) * (0.5 * model.rest_voronoi_lengths[j] * inv_eps3);
    state.external_torques.col(j) += bend + quadrature;
    state.external_torques.col(j + 1) += -bend + quadrature;
  }
}

}  // namespace tendril::physics
