#pragma once

#include <Eigen/Core>

#include "tendril/core/rng.hpp"

namespace tendril::envs::elastica {

// Case 1's moving target (seed 000, case 1: "constant velocity of 0.5 m/s while randomly
// changing directions every 0.7 seconds"; SPEC M2: a box it reflects off). Lab frame, SI.
//
// - reset: position uniform in the box, direction uniform on the unit sphere.
// - advance (once per RL step of `time_step` s): every `steps_per_direction` updates a new
//   direction uniform on the sphere is drawn first (updates 0 … 499 use the reset direction,
//   500 … 999 the next one, …); then x += v·Δt; a coordinate that crossed a wall while moving
//   outwards is mirrored back into the box at that wall and its velocity component flips sign
//   (specular reflection). The speed never changes.
//
// Invariant: a target inside the box (low ≤ position ≤ high component-wise) stays inside.
// Only `set_state` can place it elsewhere; it then drifts with its velocity until it enters.
class TargetMotion {
 public:
  struct Params {
    Eigen::Vector3d box_low{-0.6, 0.3, -0.6};  // m
    Eigen::Vector3d box_high{0.6, 0.9, 0.6};   // m
    double speed = 0.5;                        // m/s
    double time_step = 1.4e-3;                 // s per update: one RL step (7 × 0.2 ms)
    int steps_per_direction = 500;             // 0.7 s
  };

  TargetMotion() : TargetMotion(Params{}) {}
  // Raises Error on an empty box, a negative speed or time step, or steps_per_direction < 1.
  explicit TargetMotion(Params params);

  void reset(Rng& rng);
  void advance(Rng& rng);

  // Places the target anywhere with any velocity (tests, scripted starts); a zero velocity
  // holds it still until the next direction change. Raises Error on non-finite values.
  void set_state(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity);
  // The same with the count of updates (which times the direction changes): a restored state.
  void set_state(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, long updates);

  const Eigen::Vector3d& position() const { return position_; }
  const Eigen::Vector3d& velocity() const { return velocity_; }
  long updates() const { return updates_; }
  const Params& params() const { return params_; }

 private:
  Eigen::Vector3d random_direction(Rng& rng) const;

  Params params_;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_ = Eigen::Vector3d::Zero();
  long updates_ = 0;
};

}  // namespace tendril::envs::elastica
