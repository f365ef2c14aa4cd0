#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "tendril/physics/rod/rod_model.hpp"
#include "tendril/physics/rod/rod_state.hpp"

namespace tendril::physics {

// The soft-wall response of the Elastica RL paper ("Contact with solid boundaries"):
//   F_w = H(ε) (−F_push + k ε − γ v·u) u
// with ε the interpenetration, u the wall's outward normal at the contact point, F_push the
// part of the element's total force that pushes it into the wall, and v the element's velocity.
// `cancel_push = false` drops the −F_push term, leaving a pure penalty wall (k ε balances the
// push at rest).
struct SoftWall {
  double stiffness = 8.0e4;  // k, N/m (the paper's obstacle cases)
  double damping = 4.0;      // γ, N·s/m
  bool cancel_push = true;

  void validate(const char* who) const;
};

// Adds the wall response for element `i` (penetration ε ≥ 0, unit outward normal u) to the
// external forces of its two nodes, half each. The element's total force gives each end node's
// force in full to its single element, as in PyElastica.
inline void add_wall_response(const SoftWall& wall, const RodModel& model, RodState& state, int i,
                              const Eigen::Vector3d& normal, double penetration) {
  const int n = model.n_elements;
  const Eigen::Vector3d node_a = state.internal_forces.col(i) + state.external_forces.col(i);
  const Eigen::Vector3d node_b = state.internal_forces.col(i + 1) + state.external_forces.col(i + 1);
  const Eigen::Vector3d element_force =
      (i == 0 ? 1.0 : 0.5) * node_a + (i == n - 1 ? 1.0 : 0.5) * node_b;
  const double normal_force = element_force.dot(normal);
  const double push = wall.cancel_push && normal_force < 0.0 ? normal_force : 0.0;
  const double normal_velocity =
      0.5 * (state.velocities.col(i) + state.velocities.col(i + 1)).dot(normal);
  const double magnitude = -push + wall.stiffness * penetration - wall.damping * normal_velocity;
  const Eigen::Vector3d half_response = (0.5 * magnitude) * normal;
  state.external_forces.col(i) += half_response;
  state.external_forces.col(i + 1) += half_response;
}

}  // namespace tendril::physics
