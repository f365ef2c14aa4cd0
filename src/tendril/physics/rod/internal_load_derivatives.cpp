#include "tendril/physics/rod/internal_load_derivatives.hpp"

#include <cmath>

#include "tendril/physics/rod/rotation.hpp"

namespace tendril::physics {

Eigen::Matrix3d inverse_left_jacobian(const Eigen::Vector3d& psi) {
  const double phi2 = psi.squaredNorm();
  // J_l⁻¹ = I − ½ [ψ]× + (1/φ² − (1 + cos φ)/(2 φ sin φ)) [ψ]×²; the coefficient's series
  // 1/12 + φ²/720 + φ⁴/30240 is exact to double precision below φ² = 10⁻².
  double coefficient;
  if (phi2 < 1e-2) {
    coefficient = 1.0 / 12.0 + phi2 * (1.0 / 720.0 + phi2 / 30240.0);
  } else {
    const double phi = std::sqrt(phi2);
    coefficient = 1.0 / phi2 - (1.0 + std::cos(phi)) / (2.0 * phi * std::sin(phi));
  }
  const Eigen::Matrix3d cross = skew(psi);
  return Eigen::Matrix3d::Identity() - 0.5 * cross + coefficient * cross * cross;
}

namespace {

// The terms common to the internal loads and to fixed-stress loads: element stresses through
// the lab-frame stress and the shear couple, Voronoi couples through the bend and quadrature
// terms. `material` adds the stiffness terms S and B (the stresses' own change with strain).
void add_stress_terms(const RodModel& model, const RodState& state, const Vectors& stresses,
                      const Vectors& couples, bool material, RodJacobian& jacobian) {
  const int n = model.n_elements;
  const Eigen::Vector3d d3 = Eigen::Vector3d::UnitZ();
  for (int i = 0; i < n; ++i) {
    const Eigen::Matrix3d q = state.director(i);
    const double rest_length = model.rest_lengths[i];
    const double epsilon = state.dilatations[i];
    const Eigen::Vector3d t = state.tangents.col(i);
    const Eigen::Vector3d m = Eigen::Vector3d(state.shear_strains.col(i)) + d3;
    const Eigen::Vector3d stress = stresses.col(i);
    const Eigen::Matrix3d m_cross = skew(m);
    const Eigen::Matrix3d n_cross = skew(stress);
    const Eigen::Vector3d lab_stress = q.transpose() * stress;

    Eigen::Matrix3d d_lab_d_edge =
        -(lab_stress / (epsilon * epsilon * rest_length)) * t.transpose();
    Eigen::Matrix3d stress_rotation = -n_cross;   // S [m]× − [n]×
    Eigen::Matrix3d couple_stiffness = -n_cross;  // G = [m]× S − [n]×
    if (material) {
      const Eigen::DiagonalMatrix<double, 3> s(Eigen::Vector3d(model.shear_stiffness.col(i)));
      d_lab_d_edge += q.transpose() * s * q / (epsilon * rest_length);
      stress_rotation += s * m_cross;
      couple_stiffness += m_cross * s;
    }
    const Eigen::Matrix3d d_lab_d_rotation = q.transpose() * stress_rotation / epsilon;
    const Eigen::Matrix3d d_couple_d_edge =
        couple_stiffness * q / epsilon - (m.cross(stress) / (epsilon * epsilon)) * t.transpose();
    const Eigen::Matrix3d d_couple_d_rotation =
        (rest_length / epsilon) * couple_stiffness * m_cross;

    const int a = RodJacobian::node(i), b = RodJacobian::node(i + 1);
    const int self = RodJacobian::element(i);
    // Node i receives +s, node i + 1 receives −s; e = x_{i+1} − x_i.
    jacobian.add_stiffness(a, a, -d_lab_d_edge);
    jacobian.add_stiffness(a, b, d_lab_d_edge);
    jacobian.add_stiffness(b, a, d_lab_d_edge);
    jacobian.add_stiffness(b, b, -d_lab_d_edge);
    jacobian.add_stiffness(a, self, d_lab_d_rotation);
    jacobian.add_stiffness(b, self, -d_lab_d_rotation);
    jacobian.add_stiffness(self, a, -d_couple_d_edge);
    jacobian.add_stiffness(self, b, d_couple_d_edge);
    jacobian.add_stiffness(self, self, d_couple_d_rotation);
  }

  for (int j = 0; j + 1 < n; ++j) {
    const double rest_voronoi = model.rest_voronoi_lengths[j];
    const Eigen::Vector3d kappa = state.curvatures.col(j);
    const Eigen::Vector3d couple = couples.col(j);
    const double epsilon = state.voronoi_dilatations[j];
    const double inv_eps3 = 1.0 / (epsilon * epsilon * epsilon);
    // δκ = J_l⁻¹(ψ)(δθ_{j+1} − R δθ_j)/D̂ with ψ = −D̂ κ the rotation vector of R = Q_{j+1} Q_jᵀ.
    const Eigen::Matrix3d inverse_jacobian = inverse_left_jacobian(-rest_voronoi * kappa);
    const Eigen::Matrix3d relative = state.director(j + 1) * state.director(j).transpose();
    const Eigen::Matrix3d d_kappa_next = inverse_jacobian / rest_voronoi;
    const Eigen::Matrix3d d_kappa_this = -d_kappa_next * relative;

    Eigen::Matrix3d quadrature = -skew(couple);  // [κ]× B − [τ]×
    Eigen::Matrix3d bend = Eigen::Matrix3d::Zero();
    if (material) {
      const Eigen::DiagonalMatrix<double, 3> b(Eigen::Vector3d(model.bend_stiffness.col(j)));
      quadrature += skew(kappa) * b;
      bend = Eigen::Matrix3d(b) * inv_eps3;
    }
    quadrature *= 0.5 * rest_voronoi * inv_eps3;
    // Element j gets b + a, element j + 1 gets −b + a.
    const Eigen::Matrix3d on_this = bend + quadrature;
    const Eigen::Matrix3d on_next = quadrature - bend;
    const int this_element = RodJacobian::element(j), next_element = RodJacobian::element(j + 1);
    jacobian.add_stiffness(this_element, next_element, on_this * d_kappa_next);
    jacobian.add_stiffness(this_element, this_element, on_this * d_kappa_this);
    jacobian.add_stiffness(next_element, next_element, on_next * d_kappa_next);
    jacobian.add_stiffness(next_element, this_element, on_next * d_kappa_this);

    // Through ε: b and a scale as ε⁻³; δε = (t_jᵀ δe_j + t_{j+1}ᵀ δe_{j+1})/(l̂_j + l̂_{j+1}).
    const Eigen::Vector3d bend_couple = couple * inv_eps3;
    const Eigen::Vector3d quadrature_couple = 0.5 * rest_voronoi * inv_eps3 * kappa.cross(couple);
    const double scale = -3.0 / (epsilon * (model.rest_lengths[j] + model.rest_lengths[j + 1]));
    const Eigen::Vector3d t_this = state.tangents.col(j), t_next = state.tangents.col(j + 1);
    for (int side = 0; side < 2; ++side) {
      const Eigen::Vector3d g =
          scale * (quadrature_couple + (side == 0 ? 1.0 : -1.0) * bend_couple);
      const int row = side == 0 ? this_element : next_element;
      jacobian.add_stiffness(row, RodJacobian::node(j), -g * t_this.transpose());
      jacobian.add_stiffness(row, RodJacobian::node(j + 1), g * (t_this - t_next).transpose());
      jacobian.add_stiffness(row, RodJacobian::node(j + 2), g * t_next.transpose());
    }
  }
}

}  // namespace

void add_internal_load_derivatives(const RodModel& model, const RodState& state,
                                   RodJacobian& jacobian) {
  add_stress_terms(model, state, state.internal_stresses, state.internal_couples, true, jacobian);
  // Inertial torques of element i: G = (J ω/ε) × ω and U = J ω ε̇/ε², with
  // ε̇ = tᵀ (v_{i+1} − v_i)/l̂; through the edge e, ∂ε/∂e = tᵀ/l̂ and
  // ∂ε̇/∂e = (v_{i+1} − v_i)ᵀ (I − t tᵀ)/(l l̂).
  for (int i = 0; i < model.n_elements; ++i) {
    const double epsilon = state.dilatations[i];
    const double rest_length = model.rest_lengths[i];
    const Eigen::Vector3d omega = state.angular_velocities.col(i);
    const Eigen::Vector3d inertia = model.inertia.col(i);
    const Eigen::Vector3d momentum = inertia.cwiseProduct(omega);
    const Eigen::Vector3d t = state.tangents.col(i);
    const double rate = state.dilatation_rates[i];
    Eigen::Matrix3d d_omega = (skew(momentum) - skew(omega) * inertia.asDiagonal()) / epsilon;
    d_omega.diagonal() += inertia * (rate / (epsilon * epsilon));
    const int self = RodJacobian::element(i);
    jacobian.add_damping(self, self, d_omega);
    const Eigen::Vector3d d_unsteady_d_rate = momentum / (epsilon * epsilon);
    const Eigen::Matrix3d d_velocity = (d_unsteady_d_rate / rest_length) * t.transpose();
    jacobian.add_damping(self, RodJacobian::node(i + 1), d_velocity);
    jacobian.add_damping(self, RodJacobian::node(i), -d_velocity);
    const Eigen::Vector3d gyroscopic = momentum.cross(omega) / epsilon;
    const Eigen::Vector3d unsteady = d_unsteady_d_rate * rate;
    const Eigen::Vector3d relative = state.velocities.col(i + 1) - state.velocities.col(i);
    const Eigen::Matrix3d d_edge =
        (-(gyroscopic + 2.0 * unsteady) / (epsilon * rest_length)) * t.transpose() +
        (d_unsteady_d_rate / (state.lengths[i] * rest_length)) *
            (relative - t * t.dot(relative)).transpose();
    jacobian.add_stiffness(self, RodJacobian::node(i + 1), d_edge);
    jacobian.add_stiffness(self, RodJacobian::node(i), -d_edge);
  }
}

void add_fixed_stress_derivatives(const RodModel& model, const RodState& state,
                                  const Vectors& stresses, const Vectors& couples,
                                  RodJacobian& jacobian) {
  add_stress_terms(model, state, stresses, couples, false, jacobian);
}

}  // namespace tendril::physics
