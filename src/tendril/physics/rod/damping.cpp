#include "tendril/physics/rod/damping.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::physics {

InternalDamping::InternalDamping(double coefficient) : coefficient_(coefficient) {
  require(std::isfinite(coefficient) && coefficient >= 0.0,
          "coefficient must be finite and non-negative", "InternalDamping");
}

void InternalDamping::add_loads(const RodModel& model, RodState& state) {
  for (int i = 0; i < model.n_elements; ++i) {
    const double scale = coefficient_ * state.lengths[i];
    const Eigen::Vector3d half_force =
        (0.25 * scale) * (state.velocities.col(i) + state.velocities.col(i + 1));
    state.external_forces.col(i) -= half_force;
    state.external_forces.col(i + 1) -= half_force;
    state.external_torques.col(i) -= scale * state.angular_velocities.col(i);
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

}  // namespace tendril::physics
