#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/elastica/observation_writer.hpp"
#include "tendril/envs/env_description.hpp"
#include "tendril/physics/arms/elastica_arm.hpp"

namespace tendril::envs::elastica {

// The observation entries every case begins with, the seed's x_a and v_a (rod_nodes, then
// speed_and_direction of the tip): kRodBlock + kVelocityBlock entries.
std::vector<EnvDescription::Entries> arm_state_entries();
// `count` control points of the torque spline in one direction ("normal (d1)"), in [−1, 1],
// scaled by the actuation's α_m.
EnvDescription::Entries control_point_entries(const std::string& direction, int count);

// What the four Elastica control cases (seed 000; SPEC M2) share: the soft arm, an RL step of
// `substeps_per_action` physics steps under muscle targets held fixed (the seed: "The selected
// actuation torque is applied at each of the multiple Elastica timesteps that occur between RL
// controller updates"), the tip–target distance, NaN handling, and what a viewer reads.
//
// One step:
//   1. check the action (size, finite; Error otherwise) and hand it to the spline muscles as
//      control-point targets — values outside [−1, 1] are saturated there, by the actuator;
//   2. advance the rod `substeps_per_action` steps (1.4 ms in every case);
//   3. move the target (case 1 only), then observe and reward at the new time.
// If the rod's state became non-finite, or the observation would not be finite in float, the
// episode terminates: reward = the case's NaN penalty, info "nan" = 1, and the observation
// returned is the last finite one (that of the previous step). Episode lengths are left to the
// registry's TimeLimit.
//
// Info, every step: "distance" (m; the last finite one after a NaN), "is_success", "nan", and
// each case's own keys. The environment allocates nothing per step beyond the returned
// observation and one copy of the info entries (what the muscles' set_targets costs is the
// physics layer's; see elastica_arm_env_allocation_test).
class ElasticaArmEnv : public Env {
 public:
  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  // Seeds the environment's generator when `seed` is given, rebuilds the arm at rest and
  // draws the case's target.
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  // step() in two halves around the rod's advance, for a vector env that advances the rods of
  // many arms together (PooledArmVecEnv): begin_step is step 1 above and returns the muscle
  // targets it set; the caller then advances the rod by substeps_per_action() steps (or puts
  // there the state such an advance gives) and calls finish_step with whether the rod's state
  // is finite, which does step 3 and the NaN handling. begin_step + rod().advance +
  // finish_step is step(), bit for bit.
  const Eigen::VectorXd& begin_step(const Action& action);
  Step finish_step(bool finite);
  // Snapshots hold the rod with its muscles, the target, the random stream and the last finite
  // observation; stepping on from a loaded snapshot repeats the original steps exactly.
  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;
  // The rod (centreline and radii), the target sphere and the obstacles.
  bool describe_scene(Scene& scene) const override;

  // What a viewer needs; lab frame, m.
  Eigen::Matrix3Xd node_positions() const;  // all n + 1 nodes, base first
  const Eigen::Vector3d& target_position() const { return target_position_; }
  static constexpr double kTargetRadius = 0.05;  // m, the target sphere drawn by a viewer
  // Cylinders of the case (empty in cases 1–2), whether they act by contact or by penalty.
  const std::vector<physics::Cylinder>& obstacles() const { return obstacles_; }
  double time() const { return arm_.rod.time(); }  // s since reset
  int substeps_per_action() const { return substeps_per_action_; }

  // Test hooks. Moves the target (its velocity, if any, is kept).
  virtual void set_target(const Eigen::Vector3d& position);
  // The simulated arm: rod, muscles and contact, e.g. to plant a state.
  physics::ElasticaArm& arm() { return arm_; }
  const physics::ElasticaArm& arm() const { return arm_; }

 protected:
  struct Setup {
    std::string id;                // names the environment in errors
    physics::ElasticaArmSpec arm;  // geometry, numerics, muscles, contact obstacles
    int substeps_per_action = 7;
    int observation_size = 0;
    double nan_penalty = 0.0;
    std::vector<physics::Cylinder> obstacles;  // observed (and drawn); contact is in `arm`
  };
  explicit ElasticaArmEnv(Setup setup);

  // Draws the episode's target after the arm was rebuilt.
  virtual void reset_target(Rng& rng) = 0;
  // Moves the target by one RL step (after the physics of that step).
  virtual void advance_target(Rng& /*rng*/) {}
  // Writes exactly observation_size values.
  virtual void write_observation(ObservationWriter& out) const = 0;
  // The reward of a finite step; sets "is_success" and the case's own info keys in `info`.
  virtual double task_reward(double distance, Info& info) const = 0;
  // A case's own evolving state (target motion, target orientation) in and out of snapshots;
  // `load_task_state` reads everything before it changes anything.
  virtual void save_task_state(SnapshotWriter& /*out*/) const {}
  virtual void load_task_state(SnapshotReader& /*in*/) {}

  // The seed's [x_a, v_a, x_t] that cases 1, 3 and 4 start with: 11 arm nodes, tip speed and
  // direction, target position (kRodBlock + kVelocityBlock + kPositionBlock = 40 values).
  void write_arm_and_target(ObservationWriter& out) const;
  // Every obstacle's kObstacleBlock, in order (cases 3 and 4).
  void write_obstacles(ObservationWriter& out) const;

  const physics::Rod& rod() const { return arm_.rod; }
  const std::string& id() const { return id_; }
  // The info entries; a case adds its keys in its constructor so that every step reports the
  // same keys in the same order.
  Info& info() { return info_; }

  Eigen::Vector3d target_position_ = Eigen::Vector3d::Zero();

 private:
  Observation observe() const;

  std::string id_;
  physics::ElasticaArmSpec arm_spec_;
  physics::ElasticaArm arm_;
  int substeps_per_action_;
  int observation_size_;
  double nan_penalty_;
  std::vector<physics::Cylinder> obstacles_;
  Space observation_space_;
  Space action_space_;
  Rng rng_;
  Eigen::VectorXd muscle_targets_;  // the action in double, reused
  Observation last_observation_;    // last finite observation, returned after a NaN
  double last_distance_ = 0.0;
  Info info_;
};

}  // namespace tendril::envs::elastica
