#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <memory>
#include <string>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/env_description.hpp"
#include "tendril/envs/step_schedule.hpp"
#include "tendril/envs/ur5/reach_reward.hpp"
#include "tendril/envs/ur5/reach_targets.hpp"
#include "tendril/physics/rigid/ur5_arm.hpp"

namespace tendril::envs::ur5 {

// UR5/Reach-v0 — seed 004 (SPEC M10): a UR5 in MuJoCo reaches a target position with its tool
// pointing down, past an obstacle box that hides the target from the straight path.
//
// Scene (the seed gives none; choices, all parameters): the UR5 of physics/rigid on a table
// (z = 0); the obstacle box centred at (0.40, 0, 0.10) m with half extents (0.05, 0.20, 0.10) m,
// a wall 0.2 m tall in front of the arm. Every episode starts at the home pose (tool down,
// flange at (0.25, 0, 0.10) m) plus U(±0.05) rad on each joint, and draws the target in
// x ∈ [0.52, 0.70], y ∈ [−0.25, 0.25], z ∈ [0.15, 0.30] m, rejecting targets within 0.05 m of
// the box, beyond 0.80 m of the shoulder, or not hidden by the box (sample_target). The box is
// lower than the seed spec's suggested 0.30 m because the UR5's wrist hangs 0.08 m above the
// flange and reaches 0.13 m sideways: with a 0.30 m box most targets behind it cannot be
// reached tool-down without touching it.
//
// Action (6, in [−1, 1]): joint-position deltas, Δq = a·max_delta (0.05 rad), q_target =
// clip(q + Δq, joint limits) for the position servos, then frame_skip (10) physics steps of
// 2 ms: control at 50 Hz, 1000 steps = 20 s. Components beyond ±1 are saturated (the wrapper's
// clipping, done here too so that `action_space: unbounded` behaves the same); non-finite
// actions raise Error. `action_space: unbounded` declares the Box as (−∞, ∞) — what Gymnasium's
// ClipAction reports to an agent, the cause of the seed's NaN actions in SAC.
//
// Observation (19 floats, seed Sec. 2.1): joint angles q (6, rad), joint velocities (6, rad/s),
// flange position (3, m), target position (3, m), collision flag (1: this step collided).
//
// Orientation: the target orientation is fixed — the tool axis (the flange's z axis) pointing
// straight down — since the observation holds no orientation; θ is the angle between the tool
// axis and −z, and the rotation about the tool axis is free.
//
// Reward: reach_reward (reach_reward.hpp), λ_u from the `action_penalty` StepSchedule counted in
// this instance's steps. Success: d ≤ success_distance (0.05 m) and θ ≤ success_angle (0.3 rad);
// it ends the episode. A collision (any arm contact, physics/rigid) ends it too. If MuJoCo finds
// the state unstable the episode ends with −collision_penalty, info "nan" = 1 and the last
// finite observation. The registry's time limit is 1000 steps.
//
// Info, every step: distance (m), is_success, collision, contacts, orientation_error (rad),
// action_penalty_weight (λ_u of the step), nan.
//
// Parameters (env.params), all optional: max_delta, frame_skip, timestep, joint_noise, home
// (6 angles), action_space (bounded | unbounded), success_distance, success_angle,
// obstacle_centre, obstacle_half_extents, the target region (reach_targets.hpp), the reward
// weights (reach_reward.hpp), action_penalty or action_penalty_schedule {start, end, steps}
// (StepSchedule; default constant 0.05), model_file (an MJCF with the names of ur5_mjcf.hpp).
class Ur5Reach : public Env {
 public:
  static constexpr const char* kId = "UR5/Reach-v0";
  static constexpr int kObservationSize = 19;
  static constexpr int kEpisodeSteps = 1000;

  struct Params {
    double max_delta = 0.05;  // rad per step at |a| = 1
    int frame_skip = 10;
    double joint_noise = 0.05;  // rad, uniform, on every joint at reset
    physics::Ur5Arm::Joints home =
        (physics::Ur5Arm::Joints() << 2.69, -1.80, 2.76, -2.53, -1.571, 0.0).finished();
    bool unbounded_action_space = false;
    double success_distance = 0.05;  // m
    double success_angle = 0.3;      // rad
    physics::Ur5SceneSpec scene;
    std::filesystem::path model_file;
    TargetRegion targets;
    ReachRewardWeights reward;
    StepSchedule action_penalty = StepSchedule::constant(0.05);

    // Raises Error naming the first invalid value.
    void validate() const;
  };

  // Registry factory; reads the parameters above and raises Error naming a bad key.
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  Ur5Reach() : Ur5Reach(Params{}) {}
  explicit Ur5Reach(Params params);

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;

  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;
  // The arm's capsules, the obstacle, the table and the target (a sphere of the success radius).
  bool describe_scene(Scene& scene) const override;

  const Params& params() const { return params_; }
  const physics::Ur5Arm& arm() const { return arm_; }
  const Eigen::Vector3d& target() const { return target_; }
  int64_t total_steps() const { return total_steps_; }  // over all episodes of this instance
  // The angle between the tool axis and straight down (rad).
  double orientation_error() const;

  // Test hooks: put the arm at rest at `q` and the target at `target` (the episode continues
  // from there; the progress term's previous distance is the new one).
  void plant(const physics::Ur5Arm::Joints& q, const Eigen::Vector3d& target);
  void set_total_steps(int64_t steps) { total_steps_ = steps; }

 private:
  Observation observe(bool collided) const;

  Params params_;
  physics::Ur5Arm arm_;
  Space observation_space_;
  Space action_space_;
  Rng rng_;
  Eigen::Vector3d target_ = Eigen::Vector3d::Zero();
  double previous_distance_ = 0.0;
  int64_t total_steps_ = 0;
  Observation last_observation_;
  Info info_;
};

}  // namespace tendril::envs::ur5
