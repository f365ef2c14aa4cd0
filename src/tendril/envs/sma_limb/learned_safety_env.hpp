#pragma once

#include <Eigen/Core>
#include <cmath>
#include <memory>
#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/env_description.hpp"
#include "tendril/envs/learned/dynamics_model.hpp"
#include "tendril/envs/learned/history_windows.hpp"
#include "tendril/envs/safety_task.hpp"

namespace tendril::envs::sma_limb {

// SmaLimb/LearnedSafety-v0: the safety agent's environment of seed 001's limb experiment
// (thesis §6.5.2) inside a learned model of the limb: keep the bend within ‖θ‖ < 30°.
//
// Observation [θx, θy, θ̇x, θ̇y, t/T] (degrees, degrees per second; the time in the state as eq.
// 6.3 needs). Action Discrete(4), the diagonal moves of Fig. 3.1 at full throttle, as the
// author's code maps them: u1 upper right (+10, +10), u2 upper left (−10, +10), u3 lower left
// (−10, −10), u4 lower right (+10, −10). One step is one of the model's sampling periods.
// Reward 0 (the nominal policy is a scripted sequence; the safety agent learns r_safe through
// safety::SafetyCoTrainer). Info: "safety_margin" d = R − ‖θ‖ (degrees), "unsafe" and "cost" 1
// where d ≤ 0.
// Resets (the author's SafeLimbEnv): θ uniform in the safe disc, θ̇ uniform in
// ±start_velocity, the model's window at rest in that state. The episode terminates when the
// bend leaves the disc (terminate_on_unsafe), when a velocity exceeds ±velocity_limit (the
// model's range, the author's code) or on a non-finite prediction; truncated at T steps.
//
// Parameters: model (a model file or a `tendril model fit` run; default LinearLimbModel, a
// torch-free stand-in for tests), seed, safe_radius (30°), start_velocity (30 °/s),
// velocity_limit (100 °/s), horizon (T, 500 steps as the author's code), terminate_on_unsafe
// (true).
class LearnedSafetyEnv : public Env, public SafetyTask {
 public:
  static constexpr const char* kId = "SmaLimb/LearnedSafety-v0";
  static constexpr double kThrottle = 10.0;

  struct Params {
    double safe_radius = 30.0;      // degrees
    double start_velocity = 30.0;   // degrees per second
    double velocity_limit = 100.0;  // degrees per second
    int horizon = 500;
    bool terminate_on_unsafe = true;
  };

  LearnedSafetyEnv(std::shared_ptr<DynamicsModel> model, Params params, uint64_t seed);
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;

  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  const Params& params() const { return params_; }
  // SafetyTask: the constraint and search space of the safety filter
  // (learned_safety_env_safety.cpp: states (θx, θy, θ̇x, θ̇y) over the safe radius).
  std::unique_ptr<SafetyConstraint> safety_constraint() const override;
  std::unique_ptr<SafetySearchSpace> safety_search_space() const override;
  // The throttles (u_x, u_y) of action index 0–3.
  static Eigen::Vector2d throttles(int action);
  // d of eq. (6.4): R − ‖θ‖ in degrees.
  static double safety_margin(const Params& params, double theta_x, double theta_y) {
    return params.safe_radius - std::hypot(theta_x, theta_y);
  }
  // Puts the model at rest in `state` (θx, θy, θ̇x, θ̇y) at time step `elapsed_steps`.
  void set_state(const Eigen::Vector4d& state, int elapsed_steps = 0);
  Eigen::Vector4d state() const { return windows_.state(0).cast<double>(); }

 private:
  Observation observe() const;

  std::shared_ptr<DynamicsModel> model_;
  Params params_;
  HistoryWindows windows_;
  Space observation_space_, action_space_;
  Rng rng_;
  BatchMatrix inputs_, next_states_;
  int elapsed_steps_ = 0;
};

}  // namespace tendril::envs::sma_limb
