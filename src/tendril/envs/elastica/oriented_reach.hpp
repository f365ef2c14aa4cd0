#pragma once

#include <Eigen/Geometry>
#include <memory>

#include "tendril/core/config.hpp"
#include "tendril/envs/elastica/elastica_arm_env.hpp"
#include "tendril/envs/env_description.hpp"

namespace tendril::envs::elastica {

// Elastica/OrientedReach-v0 — case 2 of seed 000, "Reaching to random target location with
// defined orientation" (SPEC M2). Each reset draws a stationary target uniformly in the box
// [−0.6, 0.6] × [0.3, 0.9] × [−0.6, 0.6] m and a target frame the tip must match.
//
// Target frame (the seed: "the tangent direction of the arm tip should be pointed vertically
// upwards while the normal-binormal vectors are rotated away from the global coordinate frame
// (also the initial coordinating frame of the tip) by a random amount between −90° and 90°"):
// θ ~ U(−π/2, π/2) and q_target = R_y(θ) · q_tip(0), the arm's initial tip frame turned by θ
// about the lab's vertical +y. Its d3 is +y (up); its d1, d2 are the initial d1 = +z and
// d2 = +x rotated by θ about +y. θ = 0 is the arm's own initial frame. The sign of q_target is
// chosen with w ≥ 0 (as Rod::tip_quaternion), which the penalty below does not depend on.
//
// Arm as case 1 (20 elements, dt 0.2 ms, 7 physics steps per action); 1428 actions (2 s).
// Action (18, in [−1, 1]): 6 normal (d1), 6 binormal (d2), then 6 twist (d3) control points.
// Observation (52 floats), in the seed's order S = [x_a, v_a, q_a, x_t, v_t, q_t] (the seed's
// "48 elements" miscounts its own blocks: 33 + 4 + 4 + 3 + 4 + 4 = 52):
//   [0, 33)   x_a: 11 arm nodes, coordinate-major
//   33        |v_tip|;   [34, 37) v_tip / |v_tip|
//   [37, 41)  q_a: tip quaternion (w, x, y, z), material → lab (Rod::tip_quaternion)
//   [41, 44)  target position
//   44        target speed (always 0);   [45, 48) its direction (zeros: the target is still)
//   [48, 52)  q_t: target quaternion (w, x, y, z)
// Reward: oriented_reach_reward(d, p), p = 1 − (q_a · q_t)²; NaN: −10000, ends.
// Info: distance, is_success (d ≤ 0.05 m and p ≤ 0.05, the seed's best tier), nan,
// orientation (p).
class OrientedReach : public ElasticaArmEnv {
 public:
  static constexpr int kObservationSize = kRodBlock + kVelocityBlock + kQuaternionBlock +
                                          kPositionBlock + kVelocityBlock + kQuaternionBlock;  // 52
  static constexpr int kSubstepsPerAction = 7;
  static constexpr int kEpisodeSteps = 1428;  // 2 s / 1.4 ms
  static constexpr double kNanPenalty = -10000.0;

  // Registry factory; no parameters.
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  OrientedReach();

  // The target frame described above, from the tip's initial frame and θ (rad).
  static Eigen::Quaterniond target_frame(const Eigen::Quaterniond& initial_tip, double theta);

  const Eigen::Quaterniond& target_orientation() const { return target_orientation_; }
  double target_angle() const { return target_angle_; }  // θ of this episode, rad
  // Test hook.
  void set_target_orientation(const Eigen::Quaterniond& orientation);

 protected:
  void reset_target(Rng& rng) override;
  void write_observation(ObservationWriter& out) const override;
  double task_reward(double distance, Info& info) const override;
  void save_task_state(SnapshotWriter& out) const override;
  void load_task_state(SnapshotReader& in) override;

 private:
  Eigen::Quaterniond target_orientation_ = Eigen::Quaterniond::Identity();
  double target_angle_ = 0.0;
};

}  // namespace tendril::envs::elastica
