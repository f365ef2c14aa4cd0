#pragma once

#include <Eigen/Core>
#include <vector>

#include "tendril/physics/contact/segment_distance.hpp"
#include "tendril/physics/contact/soft_wall.hpp"
#include "tendril/physics/rod/rod_part.hpp"

namespace tendril::physics {

// A rigid, fixed, finite cylinder: the points within `radius` of the axis segment from
// `start` to `start + length · axis` (its ends are rounded, as a capsule).
struct Cylinder {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  // m, lab frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();  // unit
  double length = 1.0;                              // m
  double radius = 0.1;                              // m

  Eigen::Vector3d end() const { return start + length * axis; }
};

// Soft-wall contact between the rod's elements and a set of fixed cylinders. For each element
// the contact point is the pair of closest points between the element's centreline segment and
// the cylinder's axis segment; the interpenetration is ε = r_element + r_cylinder − distance and
// the normal points from the axis to the element.
class CylinderContact final : public RodPart {
 public:
  CylinderContact(std::vector<Cylinder> cylinders, SoftWall wall = {});
  // kStartStep: the step's set of contacts is decided anew (WallContacts).
  uint32_t stages() const override { return kStartStep | kContact; }
  void attach(const RodModel& model, const RodState& state) override;
  void start_step(const RodModel& model, RodState& state, double step) override;
  void add_contact_loads(const RodModel& model, RodState& state) override;
  void add_load_derivatives(const RodModel& model, const RodState& state,
                            RodJacobian& jacobian) const override;

  const std::vector<Cylinder>& cylinders() const { return cylinders_; }
  // Element–cylinder pairs in contact during the last step.
  int contacts() const { return contacts_; }

 private:
  void find_contacts(const RodModel& model, RodState& state);
  void respond(const RodModel& model, RodState& state, int element, int wall,
               const ClosestPoints& closest, PushRule rule);

  std::vector<Cylinder> cylinders_;
  SoftWall wall_;
  int contacts_ = 0;
  // Broad phase, per step: element midpoints and how far from its midpoint an element reaches.
  Vectors midpoints_;
  Eigen::VectorXd element_reach_;
  Eigen::VectorXd near_;  // 1 where an element's midpoint is within reach of the current axis
  WallContacts recorded_;
};

// Soft-wall contact with a fixed plane through `point` with outward unit `normal`: an element
// whose centre lies closer to the plane than its radius is pushed out along the normal.
class PlaneContact final : public RodPart {
 public:
  PlaneContact(const Eigen::Vector3d& point, const Eigen::Vector3d& normal, SoftWall wall = {});
  uint32_t stages() const override { return kStartStep | kContact; }
  void attach(const RodModel& model, const RodState& state) override;
  void start_step(const RodModel& model, RodState& state, double step) override;
  void add_contact_loads(const RodModel& model, RodState& state) override;
  void add_load_derivatives(const RodModel& model, const RodState& state,
                            RodJacobian& jacobian) const override;

 private:
  Eigen::Vector3d point_, normal_;
  SoftWall wall_;
  WallContacts recorded_;
};

}  // namespace tendril::physics
