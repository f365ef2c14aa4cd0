#pragma once

#include <Eigen/Core>

#include "tendril/physics/rod/rod_part.hpp"

namespace tendril::physics::pneumatic {

// An imbalanced morphology (seed 002 §III-B: "manufacturing inaccuracies … leading to an
// imbalanced morphology" whose moments of inertia vary along the arm): each element's centre of
// mass sits off the centreline by `offsets` (material frame, m; one column per element, the
// third component ignored), so gravity, which the Gravity part applies at the nodes, also
// exerts the couple e × (Q m g) on the element (material frame). Stateless.
class MassEccentricity final : public RodPart {
 public:
  MassEccentricity(Vectors offsets, const Eigen::Vector3d& gravity);

  uint32_t stages() const override { return kLoads; }
  void attach(const RodModel& model, const RodState& state) override;
  void add_loads(const RodModel& model, RodState& state) override;
  // e × (Q w) changes with the element's rotation as [e]× [Q w]× δθ.
  void add_load_derivatives(const RodModel& model, const RodState& state,
                            RodJacobian& jacobian) const override;

 private:
  Vectors offsets_;
  Eigen::Vector3d gravity_;
  Eigen::VectorXd masses_;  // per element, kg
};

}  // namespace tendril::physics::pneumatic
