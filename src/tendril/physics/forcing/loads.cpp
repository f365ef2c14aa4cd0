#include "tendril/physics/forcing/loads.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::physics {

Gravity::Gravity(const Eigen::Vector3d& acceleration) : acceleration_(acceleration) {
  require(acceleration.allFinite(), "acceleration must be finite", "Gravity");
}

void Gravity::add_loads(const RodModel& model, RodState& state) {
  state.external_forces.noalias() += acceleration_ * model.node_masses.transpose();
}

EndForces::EndForces(const Eigen::Vector3d& start_force, const Eigen::Vector3d& end_force,
                     double ramp_time)
    : start_force_(start_force), end_force_(end_force), ramp_time_(ramp_time) {
  require(start_force.allFinite() && end_force.allFinite(), "forces must be finite", "EndForces");
  require(std::isfinite(ramp_time) && ramp_time >= 0.0, "ramp_time must be finite and >= 0",
          "EndForces");
}

void EndForces::add_loads(const RodModel& model, RodState& state) {
  const double factor = ramp_time_ > 0.0 ? std::min(state.time / ramp_time_, 1.0) : 1.0;
  state.external_forces.col(0) += factor * start_force_;
  state.external_forces.col(model.n_elements) += factor * end_force_;
}

void NodeForces::attach(const RodModel& model, const RodState&) {
  forces_ = Vectors::Zero(3, model.n_nodes());
}

void NodeForces::add_loads(const RodModel&, RodState& state) { state.external_forces += forces_; }

void ElementForces::attach(const RodModel& model, const RodState&) {
  forces_ = Vectors::Zero(3, model.n_elements);
}

void ElementForces::add_loads(const RodModel& model, RodState& state) {
  const int n = model.n_elements;
  state.external_forces.leftCols(n) += 0.5 * forces_;
  state.external_forces.rightCols(n) += 0.5 * forces_;
}

void ElementCouples::attach(const RodModel& model, const RodState&) {
  couples_ = Vectors::Zero(3, model.n_elements);
}

void ElementCouples::add_loads(const RodModel&, RodState& state) {
  state.external_torques += couples_;
}

}  // namespace tendril::physics
