#pragma once

#include <memory>

#include "tendril/core/config.hpp"
#include "tendril/envs/elastica/elastica_arm_env.hpp"
#include "tendril/envs/elastica/target_motion.hpp"
#include "tendril/envs/env_description.hpp"

namespace tendril::envs::elastica {

// Elastica/Tracking3D-v0 — case 1 of seed 000, "3D tracking of a randomly moving target"
// (SPEC M2). The tip of the soft arm follows a target moving at 0.5 m/s inside the box
// [−0.6, 0.6] × [0.3, 0.9] × [−0.6, 0.6] m, changing direction every 500 RL steps (0.7 s) and
// reflecting off the walls (TargetMotion).
//
// Arm: 20 elements, dt 0.2 ms, base at the origin along +y, normal +z; 7 physics steps per
// action (1.4 ms); 7142 actions per 10 s episode (the registry's time limit).
// Action (12, in [−1, 1]): 6 equidistant control points (s_j = j/7 · L) of the normal (d1)
// torque spline, then 6 of the binormal (d2) one, scaled by 75 N·m.
// Observation (44 floats), the seed's S = [x_a, v_a, x_t, v_t]:
//   [0, 33)   x_a: 11 arm nodes (every 2nd node), coordinate-major (x0…x10, y0…y10, z0…z10)
//   33        |v_tip|;   [34, 37) v_tip / |v_tip| (zeros at rest)
//   [37, 40)  target position
//   40        target speed (0.5 m/s);   [41, 44) target direction of motion (unit)
// Reward: reach_reward (−d² + 0.5 if d ≤ 0.1 m, + 1.5 more if d ≤ 0.05 m); NaN: −1000, ends.
// Info: distance, is_success (d ≤ 0.05 m), nan.
class Tracking3D : public ElasticaArmEnv {
 public:
  static constexpr int kObservationSize =
      kRodBlock + kVelocityBlock + kPositionBlock + kVelocityBlock;  // 33 + 4 + 3 + 4 = 44
  static constexpr int kSubstepsPerAction = 7;
  static constexpr int kEpisodeSteps = 7142;  // 10 s / 1.4 ms
  static constexpr double kNanPenalty = -1000.0;

  // The registry's parameters: integrator (verlet, the paper's and the default; backward_euler
  // or bdf2: one implicit step per action, docs/results/implicit_rods.md) and lockstep_rods
  // (false by default; true: make_vector advances the n_envs rods together, PooledArmVecEnv;
  // one env alone is the same either way).
  struct Options {
    physics::RodIntegrator integrator = physics::RodIntegrator::kPositionVerlet;
    bool lockstep_rods = false;
    // Raises Error naming the key for a malformed value.
    static Options from_config(const Config& params);
  };
  // Registry factory (Options).
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  explicit Tracking3D(physics::RodIntegrator integrator = physics::RodIntegrator::kPositionVerlet);

  // Test hooks: places the target keeping its velocity, or sets both (a zero velocity holds
  // it still until the next direction change).
  void set_target(const Eigen::Vector3d& position) override;
  void set_target_state(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity);
  const TargetMotion& target_motion() const { return motion_; }

 protected:
  void reset_target(Rng& rng) override;
  void advance_target(Rng& rng) override;
  void write_observation(ObservationWriter& out) const override;
  double task_reward(double distance, Info& info) const override;
  void save_task_state(SnapshotWriter& out) const override;
  void load_task_state(SnapshotReader& in) override;

 private:
  TargetMotion motion_;
};

}  // namespace tendril::envs::elastica
