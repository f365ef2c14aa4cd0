#pragma once

#include <memory>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/envs/elastica/elastica_arm_env.hpp"
#include "tendril/envs/env_description.hpp"

namespace tendril::envs::elastica {

// Elastica/StructuredObstacles-v0 — case 3 of seed 000, "Underactuated maneuvering among
// structured obstacles" (SPEC M2). A fixed target at (−0.8, 0.5, 0.15) m sits behind a wall of
// eight cylinders (structured_wall()) with one opening; the arm moves in its normal plane (x–z
// at y = 0.5 m) and must slide through the opening.
//
// Arm: 50 elements, dt 0.1 ms, base (0, 0.5, 0) along +z, normal +y; 14 physics steps per action
// (1.4 ms); 3571 actions (5 s). Control points change by at most 0.01 per physics step.
// Action (control_points, in [−1, 1]): normal (d1) control points only.
// Observation (160 floats), the seed's S = [x_a, v_a, x_t, x_obs] (its "80" is
// 40 + 8 × 5, one value per obstacle point; SPEC M2 takes the code's 3 coordinates per point):
//   [0, 33)    x_a: 11 arm nodes (every 5th node), coordinate-major
//   33         |v_tip|;   [34, 37) v_tip / |v_tip|
//   [37, 40)   target position
//   [40, 160)  8 obstacles × 15: 5 points along each axis (ends included), coordinate-major
//              per obstacle, in structured_wall() order
// Reward: reach_reward(d) (− φ·f(S) in penalty mode); NaN: −100, ends.
// Info: distance, is_success (d ≤ 0.05 m), nan, contacts (contact mode: element–cylinder
// pairs in contact during the last physics step; penalty mode: elements intersecting an
// obstacle), penalty (φ·f(S), 0 in contact mode).
//
// Parameters (the seed's variants):
//   control_points: 2 (default); the seed also trains 4, 6 and 8 equidistant ones.
//   control_point_positions: fractions of L, strictly increasing in (0, 1), one per control
//     point; default equidistant, s_j = j/(n + 1). The seed's hand-placed pair: [0.4, 0.9].
//   obstacle_mode: contact (default; soft walls k 8e4 N/m, γ 4 N·s/m) or penalty (no contact;
//     the reward pays −φ·f(S), f the fraction of the 50 elements, capsules of the arm's radius
//     0.05 m, that intersect an obstacle; see intersecting_elements).
//   penalty_weight: φ, default 10 (the seed runs 10 and 100); penalty mode only.
//   integrator: verlet (the paper's, default), backward_euler or bdf2 (one implicit step per
//     action; docs/results/implicit_rods.md).
class StructuredObstacles : public ElasticaArmEnv {
 public:
  enum class ObstacleMode { kContact, kPenalty };
  struct Params {
    int control_points = 2;
    std::vector<double> control_point_positions;  // empty: equidistant
    ObstacleMode obstacle_mode = ObstacleMode::kContact;
    double penalty_weight = 10.0;
    physics::RodIntegrator integrator = physics::RodIntegrator::kPositionVerlet;
  };

  static constexpr int kObstacles = 8;
  static constexpr int kObservationSize =
      kRodBlock + kVelocityBlock + kPositionBlock + kObstacles * kObstacleBlock;  // 160
  static constexpr int kSubstepsPerAction = 14;
  static constexpr int kEpisodeSteps = 3571;  // 5 s / 1.4 ms
  static constexpr double kNanPenalty = -100.0;
  static constexpr double kArmRadius = 0.05;  // m, Table 6; the intersection test's element radius

  // Registry factory; params: control_points, control_point_positions, obstacle_mode,
  // penalty_weight, integrator. Raises Error naming the key of an invalid value.
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  StructuredObstacles() : StructuredObstacles(Params{}) {}
  // Raises Error on an invalid parameter.
  explicit StructuredObstacles(Params params);

  const Params& params() const { return params_; }

 protected:
  void reset_target(Rng& rng) override;
  void write_observation(ObservationWriter& out) const override;
  double task_reward(double distance, Info& info) const override;

 private:
  Params params_;
};

}  // namespace tendril::envs::elastica
