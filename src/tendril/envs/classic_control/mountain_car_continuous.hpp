#pragma once

#include <memory>
#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/env_description.hpp"

namespace tendril::envs {

// Gymnasium's MountainCarContinuous-v0 (gymnasium/envs/classic_control/continuous_mountain_car.py),
// after Moore (1990): an under-powered car in the valley y = sin(3x) must rock itself up to the
// flag at x = 0.45. Units are Gymnasium's own (position in track units, velocity per step).
//
//   v' = clip(v + clip(a, −1, 1) · 0.0015 − 0.0025 cos(3x), −0.07, 0.07)
//   x' = clip(x + v', −1.2, 0.6);  v' = 0 if x' hits −1.2 while moving left
//   terminated = x' ≥ 0.45 and v' ≥ goal_velocity
//   reward = 100 · terminated − 0.1 a²   (a unclipped, as in Gymnasium)
//
// Gymnasium stores the state as float32 after every step; so does this class, so that long
// rollouts follow the same rounding.
class MountainCarContinuous : public Env {
 public:
  static constexpr double kPower = 0.0015;
  static constexpr double kMinPosition = -1.2;
  static constexpr double kMaxPosition = 0.6;
  static constexpr double kMaxSpeed = 0.07;
  static constexpr double kGoalPosition = 0.45;

  struct Params {
    double goal_velocity = 0.0;  // Gymnasium's `goal_velocity`
  };
  // Registry factory; params: {goal_velocity}.
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  MountainCarContinuous() : MountainCarContinuous(Params{}) {}
  explicit MountainCarContinuous(Params params);

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  // Position ~ U(−0.6, −0.4), velocity 0.
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  // The state, the random stream and the episode flags: exact snapshots.
  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  void set_state(double position, double velocity);
  double position() const { return position_; }
  double velocity() const { return velocity_; }

 private:
  Params params_;
  Space observation_space_;
  Space action_space_;
  Rng rng_;
  double position_ = 0.0;
  double velocity_ = 0.0;
};

}  // namespace tendril::envs
