#include "tendril/physics/rod/boundary.hpp"

#include <Eigen/LU>

#include "tendril/core/error.hpp"
#include "tendril/physics/rod/rod_jacobian.hpp"

namespace tendril::physics {

FixedEnd::FixedEnd(const Eigen::Vector3d& position, const Eigen::Matrix3d& directors)
    : given_(true), position_(position), directors_(directors) {
  require(position.allFinite(), "position must be finite", "FixedEnd");
  require(directors.allFinite() &&
              (directors * directors.transpose() - Eigen::Matrix3d::Identity()).norm() < 1e-9 &&
              directors.determinant() > 0,
          "directors must be a proper orthonormal frame", "FixedEnd");
}

void FixedEnd::attach(const RodModel&, const RodState& state) {
  if (given_) return;
  position_ = state.positions.col(0);
  directors_ = state.director(0);
}

void FixedEnd::constrain_values(const RodModel&, RodState& state) {
  state.positions.col(0) = position_;
  state.set_director(0, directors_);
}

void FixedEnd::constrain_rates(const RodModel&, RodState& state) {
  state.velocities.col(0).setZero();
  state.angular_velocities.col(0).setZero();
}

void FixedEnd::fix_rates(const RodModel&, RodJacobian& jacobian) const {
  for (int axis = 0; axis < 3; ++axis) {
    jacobian.fix_rate(RodJacobian::node(0) + axis);
    jacobian.fix_rate(RodJacobian::element(0) + axis);
  }
}

GeneralConstraint::GeneralConstraint(int node, std::array<bool, 3> translations, int element,
                                     std::array<bool, 3> rotations)
    : node_(node), translations_(translations), element_(element), rotations_(rotations) {}

void GeneralConstraint::attach(const RodModel& model, const RodState& state) {
  require(node_ >= 0 && node_ <= model.n_elements,
          "node " + std::to_string(node_) + " outside [0, " + std::to_string(model.n_elements) + "]",
          "GeneralConstraint");
  require(element_ >= 0 && element_ < model.n_elements,
          "element " + std::to_string(element_) + " outside [0, " +
              std::to_string(model.n_elements - 1) + "]",
          "GeneralConstraint");
  position_ = state.positions.col(node_);
  directors_ = state.director(element_);
}

void GeneralConstraint::constrain_values(const RodModel&, RodState& state) {
  for (int axis = 0; axis < 3; ++axis) {
    if (translations_[axis]) state.positions(axis, node_) = position_[axis];
  }
  if (rotations_[0] && rotations_[1] && rotations_[2]) state.set_director(element_, directors_);
}

void GeneralConstraint::constrain_rates(const RodModel&, RodState& state) {
  for (int axis = 0; axis < 3; ++axis) {
    if (translations_[axis]) state.velocities(axis, node_) = 0.0;
    if (rotations_[axis]) state.angular_velocities(axis, element_) = 0.0;
  }
}

void GeneralConstraint::fix_rates(const RodModel&, RodJacobian& jacobian) const {
  for (int axis = 0; axis < 3; ++axis) {
    if (translations_[axis]) jacobian.fix_rate(RodJacobian::node(node_) + axis);
    if (rotations_[axis]) jacobian.fix_rate(RodJacobian::element(element_) + axis);
  }
}

}  // namespace tendril::physics
