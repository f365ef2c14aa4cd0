#pragma once

#include <memory>
#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/env_description.hpp"

namespace tendril::envs {

// Gymnasium's Pendulum-v1 (gymnasium/envs/classic_control/pendulum.py): swing a rigid pendulum
// up and hold it upright. θ = 0 is upright, measured in radians; θdot in rad/s; torque u in N·m.
//
//   θdot' = clip(θdot + (3g/(2l) sin θ + 3/(m l²) u) dt, −8, 8),   θ' = θ + θdot' dt
//   reward = −(normalize(θ)² + 0.1 θdot² + 0.001 u²),               obs = [cos θ, sin θ, θdot]
//
// with u first saturated to ±2 N·m: the saturation is part of Gymnasium's dynamics (the reward
// uses the saturated torque), so it stays here rather than in an action wrapper. The task never
// terminates; the registry adds Gymnasium's 200-step time limit.
class Pendulum : public Env {
 public:
  static constexpr double kMaxSpeed = 8.0;   // rad/s
  static constexpr double kMaxTorque = 2.0;  // N·m
  static constexpr double kDt = 0.05;        // s per step
  static constexpr double kMass = 1.0;       // kg
  static constexpr double kLength = 1.0;     // m

  struct Params {
    double gravity = 10.0;  // m/s², Gymnasium's `g`; read from the config key `g`
  };
  // Registry factory; params: {g}.
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  Pendulum() : Pendulum(Params{}) {}
  explicit Pendulum(Params params);

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  // θ ~ U(−π, π), θdot ~ U(−1, 1).
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  // The state, the random stream and the episode flags: exact snapshots.
  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  // State access for tests and scripted starts.
  void set_state(double theta, double theta_dot);
  double theta() const { return theta_; }
  double theta_dot() const { return theta_dot_; }

  // Gymnasium's angle_normalize: x mapped into [−π, π).
  static double normalize_angle(double x);

 private:
  Observation observe() const;

  Params params_;
  Space observation_space_;
  Space action_space_;
  Rng rng_;
  double theta_ = 0.0;
  double theta_dot_ = 0.0;
};

}  // namespace tendril::envs
