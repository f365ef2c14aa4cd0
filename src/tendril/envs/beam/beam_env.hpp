#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>

#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/beam/follow_reward.hpp"
#include "tendril/envs/beam/target_path.hpp"
#include "tendril/envs/curriculum_task.hpp"
#include "tendril/physics/lattice/beam_lattice.hpp"

namespace tendril::envs::beam {

// What the beam's state shows the policy (seed 003), lab frame, m and m/s:
//   kTip        (4)  Model 1: [x_tip, y_tip, x_t, y_t]
//   kSixPoints  (14) Model 2: [x_1, y_1, …, x_5, y_5, x_tip, y_tip, x_t, y_t] — the centres of
//                    the five torque rows ("the points of application of torque") and the tip
//   kTrajectory (18) Model 3: [the 12 of kSixPoints, v_tip (2), x_t, y_t, v_t (2)]
enum class BeamObservation { kTip, kSixPoints, kTrajectory };

int observation_size(BeamObservation observation);

struct BeamTaskSpec {
  std::string id;  // names the environment in errors and snapshots
  physics::BeamLatticeSpec lattice;
  double control_period = 0.05;  // s, one RL step (20 Hz)
  double torque_scale = 4.5;     // N·m per unit action (±8 for the ellipse)
  BeamObservation observation = BeamObservation::kTip;
  FollowWeights weights;
  // r_E with τ_i in N·m (true) or in the policy's [−1, 1] units (false).
  bool energy_in_newton_metres = true;
  // End the episode (terminated) when the tip is farther than this from the target; 0: never.
  double max_distance = 0.0;       // m
  double success_distance = 0.05;  // m, "is_success"
  double nan_penalty = -100.0;     // reward of a step whose state became non-finite
  // Raises Error naming the field.
  void validate() const;
};

// Seed 003's tasks on the mass-spring beam (SPEC M4): the tip of the beam follows a target that
// moves along a TargetPath (arcs, an ellipse).
//
// One step:
//   1. the action (5 values; Error on a wrong size or non-finite value) is saturated at ±1 by
//      the actuator and scaled to torques τ = torque_scale · a (N·m), applied as the row
//      couples of the beam (physics::RowCouples);
//   2. the lattice advances one control period (control_period / time_step implicit steps);
//   3. the target moves on by one control period; observation, reward and info at the new
//      time.
// Reward: follow_reward of the spec's weights with r_d, r_v (tip = centroid of the last row)
// and r_E = |Σ τ_i θ_i|, θ_i the unwrapped rotation of torque row i from its rest direction
// (rad, BeamLattice::row_angle), τ_i this step's torques. The seed does not define θ_i; this is
// the work Σ τ_i θ_i a constant couple does turning its row from rest.
// A non-finite lattice ends the episode: reward nan_penalty, info "nan" = 1, the observation of
// the previous step. Episode lengths are the registry's time limits.
// Info, every step: "distance" (m), "velocity_error" (m/s), "energy" (r_E), "is_success"
// (distance ≤ success_distance), "nan", "inverted_cells" (BeamLattice::inverted_cells).
//
// Levels (CurriculumTask) are the target path's; without a curriculum the task runs at the
// last one.
class BeamEnv : public Env, public CurriculumTask {
 public:
  static constexpr int kActions = 5;

  BeamEnv(BeamTaskSpec spec, std::unique_ptr<TargetPath> target);

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  // Seeds the environment's generator when `seed` is given, rebuilds the beam straight and at
  // rest, and draws the target's episode.
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;
  // The lattice (nodes, springs), the target, the target's path, and the step's metrics.
  bool describe_scene(Scene& scene) const override;

  int curriculum_levels() const override { return target_->levels(); }
  int curriculum_level() const override { return target_->level(); }
  void set_curriculum_level(int level) override { target_->set_level(level); }

  const BeamTaskSpec& spec() const { return spec_; }
  const physics::BeamLattice& beam() const { return beam_; }
  physics::BeamLattice& beam() { return beam_; }  // test hook, e.g. to plant a state
  const TargetPath& target() const { return *target_; }
  TargetPath& target() { return *target_; }               // test hook
  double time() const { return beam_.lattice().time(); }  // s since reset

 private:
  Observation observe() const;
  double energy_term() const;

  BeamTaskSpec spec_;
  std::unique_ptr<TargetPath> target_;
  physics::BeamLattice beam_;
  int substeps_;
  Space observation_space_, action_space_;
  Rng rng_;
  Eigen::VectorXd torques_, actions_;  // this step's, N·m and [−1, 1]
  Observation last_observation_;
  double distance_ = 0.0, velocity_error_ = 0.0, energy_ = 0.0;
  Info info_;
};

}  // namespace tendril::envs::beam
