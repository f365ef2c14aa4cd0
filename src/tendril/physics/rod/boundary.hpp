#pragma once

#include <Eigen/Core>
#include <array>

#include "tendril/physics/rod/rod_part.hpp"

namespace tendril::physics {

// One end clamped: node 0 keeps its position and element 0 its directors (those at attach
// time, or given), with zero velocity and angular velocity — the base of the Elastica arm.
class FixedEnd final : public RodPart {
 public:
  FixedEnd() = default;
  FixedEnd(const Eigen::Vector3d& position, const Eigen::Matrix3d& directors);

  uint32_t stages() const override { return kConstrainValues | kConstrainRates; }
  void attach(const RodModel& model, const RodState& state) override;
  void constrain_values(const RodModel& model, RodState& state) override;
  void constrain_rates(const RodModel& model, RodState& state) override;
  void fix_rates(const RodModel& model, RodJacobian& jacobian) const override;

  // The held values (those captured at attach time unless given).
  const Eigen::Vector3d& position() const { return position_; }
  const Eigen::Matrix3d& directors() const { return directors_; }

 private:
  bool given_ = false;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d directors_ = Eigen::Matrix3d::Identity();
};

// Constrains chosen degrees of freedom of one node and one element: translations along the lab
// axes x, y, z of `node`, and rotations about the material axes d1, d2, d3 of `element`.
// Constrained translations keep the value they had at attach time and have zero velocity;
// constrained rotation rates are zero (all three: the element's directors are held fixed too).
class GeneralConstraint final : public RodPart {
 public:
  GeneralConstraint(int node, std::array<bool, 3> translations, int element,
                    std::array<bool, 3> rotations);

  uint32_t stages() const override { return kConstrainValues | kConstrainRates; }
  void attach(const RodModel& model, const RodState& state) override;
  void constrain_values(const RodModel& model, RodState& state) override;
  void constrain_rates(const RodModel& model, RodState& state) override;
  void fix_rates(const RodModel& model, RodJacobian& jacobian) const override;

 private:
  int node_;
  std::array<bool, 3> translations_;
  int element_;
  std::array<bool, 3> rotations_;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d directors_ = Eigen::Matrix3d::Identity();
};

}  // namespace tendril::physics
