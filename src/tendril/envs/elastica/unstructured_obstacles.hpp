#pragma once

#include <cstdint>
#include <memory>

#include "tendril/core/config.hpp"
#include "tendril/envs/elastica/elastica_arm_env.hpp"
#include "tendril/envs/env_description.hpp"

namespace tendril::envs::elastica {

// Elastica/UnstructuredObstacles-v0 — case 4 of seed 000, "Underactuated maneuvering among
// unstructured obstacles" (SPEC M2). A fixed target at (−0.8, 0.5, 0.35) m behind a nest of 12
// thin cylinders (unstructured_nest()), drawn once from `obstacle_seed` when the environment is
// built and the same in every episode; the arm acts on them through soft-wall contact
// (k 8e4 N/m, γ 4 N·s/m).
//
// Arm as case 3: 50 elements, dt 0.1 ms, base (0, 0.5, 0) along +z, normal +y; 14 physics steps
// per action; 3571 actions (5 s); control points change by at most 0.01 per physics step.
// Action (4, in [−1, 1]): 2 equidistant normal (d1) control points (s = L/3, 2L/3), then 2
// binormal (d2) ones.
// Observation (220 floats), the seed's S = [x_a, v_a, x_t, x_obs] (its "100" is
// 40 + 12 × 5, one value per obstacle point; SPEC M2 takes the code's 3 coordinates per point):
//   [0, 33)    x_a: 11 arm nodes (every 5th node), coordinate-major
//   33         |v_tip|;   [34, 37) v_tip / |v_tip|
//   [37, 40)   target position
//   [40, 220)  12 obstacles × 15: 5 points along each axis (ends included), coordinate-major
//              per obstacle, in drawing order
// Reward: reach_reward(d); NaN: −100, ends.
// Info: distance, is_success (d ≤ 0.05 m), nan, contacts (element–cylinder pairs in contact
// during the last physics step).
//
// Parameters: obstacle_seed (unsigned integer, default 0): the nest's generator seed,
// independent of the episode seed passed to reset.
class UnstructuredObstacles : public ElasticaArmEnv {
 public:
  static constexpr int kObstacles = 12;
  static constexpr int kObservationSize =
      kRodBlock + kVelocityBlock + kPositionBlock + kObstacles * kObstacleBlock;  // 220
  static constexpr int kSubstepsPerAction = 14;
  static constexpr int kEpisodeSteps = 3571;  // 5 s / 1.4 ms
  static constexpr double kNanPenalty = -100.0;

  // Registry factory; params: obstacle_seed.
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  explicit UnstructuredObstacles(uint64_t obstacle_seed = 0);

  uint64_t obstacle_seed() const { return obstacle_seed_; }

 protected:
  void reset_target(Rng& rng) override;
  void write_observation(ObservationWriter& out) const override;
  double task_reward(double distance, Info& info) const override;

 private:
  uint64_t obstacle_seed_;
};

}  // namespace tendril::envs::elastica
