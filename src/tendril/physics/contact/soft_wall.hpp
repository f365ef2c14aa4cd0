#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "tendril/physics/rod/rod_model.hpp"
#include "tendril/physics/rod/rod_state.hpp"

namespace tendril::physics {

class RodJacobian;

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

// What add_wall_response applied to an element, as an implicit step's Jacobian needs it.
struct WallResponse {
  double magnitude = 0.0;         // of the response along the normal (both nodes together), N
  bool cancels_push = false;      // the −F_push term was active
  Eigen::Vector3d element_force;  // F, the element's total force before the response, N
  Eigen::Vector3d mean_velocity;  // v̄, m/s
};

// Whether a response cancels the element's push into the wall: by the sign of the push (as
// SoftWall::cancel_push allows), or as decided earlier in the step (WallContacts).
enum class PushRule { kBySign, kCancel, kLeave };

// Adds the wall response for element `i` (penetration ε, unit outward normal u) to the
// external forces of its two nodes, half each. The element's total force gives each end node's
// force in full to its single element, as in PyElastica.
inline WallResponse add_wall_response(const SoftWall& wall, const RodModel& model, RodState& state,
                                      int i, const Eigen::Vector3d& normal, double penetration,
                                      PushRule rule = PushRule::kBySign) {
  const int n = model.n_elements;
  const Eigen::Vector3d node_a = state.internal_forces.col(i) + state.external_forces.col(i);
  const Eigen::Vector3d node_b = state.internal_forces.col(i + 1) + state.external_forces.col(i + 1);
  const Eigen::Vector3d element_force =
      (i == 0 ? 1.0 : 0.5) * node_a + (i == n - 1 ? 1.0 : 0.5) * node_b;
  const double normal_force = element_force.dot(normal);
  double push = 0.0;
  if (rule == PushRule::kBySign) {
    push = wall.cancel_push && normal_force < 0.0 ? normal_force : 0.0;
  } else if (rule == PushRule::kCancel) {
    push = normal_force;
  }
  const double normal_velocity =
      0.5 * (state.velocities.col(i) + state.velocities.col(i + 1)).dot(normal);
  const double magnitude = -push + wall.stiffness * penetration - wall.damping * normal_velocity;
  const Eigen::Vector3d half_response = (0.5 * magnitude) * normal;
  state.external_forces.col(i) += half_response;
  state.external_forces.col(i + 1) += half_response;
  WallResponse response;
  response.magnitude = magnitude;
  response.cancels_push = rule == PushRule::kCancel || push != 0.0;
  response.element_force = element_force;
  response.mean_velocity = 0.5 * (state.velocities.col(i) + state.velocities.col(i + 1));
  return response;
}

// The contacts of a contact part. Their set is decided at a step's first evaluation of the
// loads — every element that touches a wall then, and whether its push is cancelled — and held
// for the step's other evaluations, the Newton iterates of an implicit step, as contact solvers
// hold their active set over a step (Wriggers, Computational Contact Mechanics, 2006, §6): the
// loads are then smooth within the step, where contacts switching on (with a jump: at ε = 0⁺ the
// response already cancels the push) and off between iterates would keep Newton's method from
// converging at any step. A held contact responds even if it separates within the step.
// Position Verlet evaluates the loads once per step, so for it nothing is held. The records of
// the last evaluation serve the Jacobian. Sized once; recording never allocates (beyond the
// reserved capacity).
class WallContacts {
 public:
  struct Held {
    int element;
    int wall;  // which of the part's walls
    bool cancels_push;
  };

  void reserve(int capacity);
  // A new step: its first evaluation decides the set.
  void start_step() { deciding_ = true; }
  bool deciding() const { return deciding_; }
  // Ends an evaluation: after the deciding one, the recorded contacts are the step's set.
  void finish_evaluation();
  const std::vector<Held>& held() const { return held_; }
  int held_count() const { return held_count_; }
  int count() const { return count_; }
  void clear() { count_ = 0; }
  // Element `element` touched the wall with outward unit `normal` at the point `fraction` of
  // the way from node i to node i + 1 (0 … 1); the normal turns with the nodes as ∂u/∂x_i and
  // ∂u/∂x_{i+1} (zero for a plane).
  void record(int element, int wall, const Eigen::Vector3d& normal, double fraction,
              const Eigen::Matrix3d& normal_change_first,
              const Eigen::Matrix3d& normal_change_second, const WallResponse& response);
  // Hands every recorded contact to the Jacobian (RodJacobian::add_wall_contact). On each node
  // the response is ½ m u with m = −min(0, F·u) + k ε − γ v̄·u, so
  //   ∂(½ m u) = ½ [k u ∂ε + (m I − u Fᵀ|push − γ u v̄ᵀ) ∂u]
  // (the element's force F and the velocity held fixed). The penetration ε = r_i + (wall
  // offset) − |p − wall| changes with the closest point p = (1 − s) x_i + s x_{i+1} as −u —
  // the closest point's own shift does not change the distance to first order — and through
  // the element's radius r = r̂ √(l̂/l) as ∓ r/(2 l) t.
  void add_derivatives(const SoftWall& wall, const RodState& state, RodJacobian& jacobian) const;

 private:
  struct Contact {
    int element;
    int wall;
    Eigen::Vector3d normal;
    double fraction;
    Eigen::Matrix3d normal_change_first, normal_change_second;
    WallResponse response;
  };
  std::vector<Contact> contacts_;
  int count_ = 0;
  std::vector<Held> held_;
  int held_count_ = 0;
  bool deciding_ = true;
};

}  // namespace tendril::physics
