#include "tendril/physics/rod/damping.hpp"

#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/physics/rod/rod_jacobian.hpp"

namespace tendril::physics {

InternalDamping::InternalDamping(double coefficient) : coefficient_(coefficient) {
  require(std::isfinite(coefficient) && coefficient >= 0.0,
          "coefficient must be finite and non-negative", "InternalDamping");
}

void InternalDamping::add_loads(const RodModel& model, RodState& state) {
  const int n = model.n_elements;
  const double nu = coefficient_;
  const double* length = state.lengths.data();
  for (int k = 0; k < 3; ++k) {
    const double* v = state.velocities.row(k).data();
    const double* w = state.angular_velocities.row(k).data();
    double* force = state.external_forces.row(k).data();
    double* torque = state.external_torques.row(k).data();
    // Node j receives half the force ν l v̄ of each element it bounds.
    force[0] -= 0.25 * nu * length[0] * (v[0] + v[1]);
#pragma omp simd
    for (int j = 1; j < n; ++j) {
      force[j] -= 0.25 * nu * (length[j - 1] * (v[j - 1] + v[j]) + length[j] * (v[j] + v[j + 1]));
    }
    force[n] -= 0.25 * nu * length[n - 1] * (v[n - 1] + v[n]);
#pragma omp simd
    for (int i = 0; i < n; ++i) torque[i] -= nu * length[i] * w[i];
  }
}

// ∂/∂v of the force on node j: −¼ ν (l_{j−1} (δv_{j−1} + δv_j) + l_j (δv_j + δv_{j+1}));
// through l_i = |x_{i+1} − x_i|, −¼ ν (v_i + v_{i+1}) t_iᵀ (δx_{i+1} − δx_i) on both nodes of
// element i; the torque −ν l_i ω_i likewise.
void InternalDamping::add_load_derivatives(const RodModel& model, const RodState& state,
                                           RodJacobian& jacobian) const {
  const double nu = coefficient_;
  for (int i = 0; i < model.n_elements; ++i) {
    const double length = state.lengths[i];
    const Eigen::Vector3d t = state.tangents.col(i);
    const Eigen::Matrix3d rate_block = -0.25 * nu * length * Eigen::Matrix3d::Identity();
    const Eigen::Vector3d mean = state.velocities.col(i) + state.velocities.col(i + 1);
    const Eigen::Matrix3d stretch_block = -0.25 * nu * mean * t.transpose();
    const int a = RodJacobian::node(i), b = RodJacobian::node(i + 1);
    const int self = RodJacobian::element(i);
    for (int row : {a, b}) {
      jacobian.add_damping(row, a, rate_block);
      jacobian.add_damping(row, b, rate_block);
      jacobian.add_stiffness(row, a, -stretch_block);
      jacobian.add_stiffness(row, b, stretch_block);
    }
    jacobian.add_damping(self, self, -nu * length * Eigen::Matrix3d::Identity());
    const Eigen::Matrix3d torque_block =
        -nu * Eigen::Vector3d(state.angular_velocities.col(i)) * t.transpose();
    jacobian.add_stiffness(self, a, -torque_block);
    jacobian.add_stiffness(self, b, torque_block);
  }
}

AnalyticalLinearDamping::AnalyticalLinearDamping(double translational, double rotational)
    : translational_(translational), rotational_(rotational) {
  require(std::isfinite(translational) && translational >= 0.0,
          "translational constant must be finite and non-negative", "AnalyticalLinearDamping");
  require(std::isfinite(rotational) && rotational >= 0.0,
          "rotational constant must be finite and non-negative", "AnalyticalLinearDamping");
}

void AnalyticalLinearDamping::attach(const RodModel& model, const RodState&) {
  const int n = model.n_elements;
  const double dt = model.time_step;
  velocity_factors_.resize(n + 1);
  for (int j = 0; j <= n; ++j) {
    // m_j dv/dt = −γ_t D_j v with D_j the node's share of rest length.
    const double share = 0.5 * ((j > 0 ? model.rest_lengths[j - 1] : 0.0) +
                                (j < n ? model.rest_lengths[j] : 0.0));
    velocity_factors_[j] = std::exp(-translational_ * share * dt * model.inverse_node_masses[j]);
  }
  node_coefficients_.resize(n + 1);
  for (int j = 0; j <= n; ++j) {
    node_coefficients_[j] =
        translational_ * 0.5 *
        ((j > 0 ? model.rest_lengths[j - 1] : 0.0) + (j < n ? model.rest_lengths[j] : 0.0));
  }
  element_coefficients_ = rotational_ * model.rest_lengths;
  angular_factors_.resize(3, n);
  for (int i = 0; i < n; ++i) {
    // J dω/dt = −γ_r l̂ ω, per material axis.
    angular_factors_.col(i) =
        (-rotational_ * model.rest_lengths[i] * dt * model.inverse_inertia.col(i).array()).exp();
  }
}

void AnalyticalLinearDamping::damp_rates(const RodModel&, RodState& state) {
  state.velocities.array().rowwise() *= velocity_factors_.transpose().array();
  state.angular_velocities.array() *= angular_factors_.array();
}

void AnalyticalLinearDamping::add_damping_loads(const RodModel&, RodState& state) {
  state.external_forces.array() -=
      state.velocities.array().rowwise() * node_coefficients_.transpose().array();
  state.external_torques.array() -=
      state.angular_velocities.array().rowwise() * element_coefficients_.transpose().array();
}

void AnalyticalLinearDamping::add_load_derivatives(const RodModel& model, const RodState&,
                                                   RodJacobian& jacobian) const {
  for (int j = 0; j <= model.n_elements; ++j) {
    jacobian.add_damping_diagonal(RodJacobian::node(j),
                                  Eigen::Vector3d::Constant(node_coefficients_[j]));
  }
  for (int i = 0; i < model.n_elements; ++i) {
    jacobian.add_damping_diagonal(RodJacobian::element(i),
                                  Eigen::Vector3d::Constant(element_coefficients_[i]));
  }
}

}  // namespace tendril::physics
