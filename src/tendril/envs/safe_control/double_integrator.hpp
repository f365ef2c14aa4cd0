#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/env_description.hpp"
#include "tendril/envs/safety_task.hpp"

namespace tendril::envs::safe_control {

// The double integrator of seed 001 §6.4.1: a point mass on a line, position x (m), velocity
// ẋ (m/s), commanded acceleration a (m/s², |a| ≤ 2), integrated exactly over each step
// (zero-order hold):
//
//   x' = x + ẋ dt + a dt²/2,   ẋ' = ẋ + a dt.
//
// Safe set |x| < 2 m, |ẋ| < 3 m/s; the episode terminates only outside the absolute bounds
// (±4 m, ±5 m/s), so a task agent keeps acting after it entered the unsafe set (the gated
// safety buffer of §6.3.1 stops there, the task buffer does not). Task: reach x = 1.8 m,
// reward −|x' − 1.8| per step.
//
// The observation is [x, ẋ, t/T]: eq. (6.3) needs time in the state, given here as the
// fraction of the horizon T elapsed. Info: "safety_margin" d(x') (eq. 6.4, min over the two
// constraints, in their own units), "cost" and "unsafe" 1 where x' is unsafe (d ≤ 0).
//
// Values the thesis leaves open (dt, T, start states) follow the labelled suggestions of the
// seed's extraction and live in the config: dt = 0.05 s, T = 200 steps, starts uniform in the
// safe box.
class DoubleIntegrator : public Env, public SafetyTask {
 public:
  static constexpr const char* kId = "Safety/DoubleIntegrator-v0";

  struct Params {
    double position_limit = 2.0;           // m, safe |x|
    double velocity_limit = 3.0;           // m/s, safe |ẋ|
    double absolute_position_limit = 4.0;  // m, the episode ends beyond
    double absolute_velocity_limit = 5.0;  // m/s
    double max_acceleration = 2.0;         // m/s², |a|
    double goal_position = 1.8;            // m
    double dt = 0.05;                      // s per step
    int horizon = 200;                     // steps T; the episode is truncated there
    // 0: a Box action in m/s²; n ≥ 2: n accelerations evenly spaced over [−a_max, a_max].
    int discrete_actions = 0;
    // Starts uniform in [−start_position, start_position] × [−start_velocity, start_velocity].
    double start_position = 2.0;  // m
    double start_velocity = 3.0;  // m/s
    // The reward-penalty baseline of seed 001 Table 6.1: subtracted from the reward of every step
    // that ends in X_unsafe (the thesis gives no size; 0 leaves the task reward alone).
    double unsafe_penalty = 0.0;
  };
  // Registry factory; params are the fields of Params by name.
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  DoubleIntegrator() : DoubleIntegrator(Params{}) {}
  explicit DoubleIntegrator(Params params);

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  const Params& params() const { return params_; }
  // SafetyTask: the constraint and search space of the safety filter (double_integrator_safety.cpp:
  // observation [x, ẋ, t/T]; states (x, ẋ) over the safe bounds).
  std::unique_ptr<SafetyConstraint> safety_constraint() const override;
  std::unique_ptr<SafetySearchSpace> safety_search_space() const override;
  void set_state(double position, double velocity, int elapsed_steps = 0);
  double position() const { return position_; }
  double velocity() const { return velocity_; }
  // The acceleration an action commands (m/s²): the Box value, or the index's level.
  double acceleration(const Action& action) const;

  // d(x) of eq. (6.4): min(x_max − |x|, ẋ_max − |ẋ|); unsafe where ≤ 0.
  static double safety_margin(const Params& params, double position, double velocity);
  // max d over the safe set (at the origin): the normalizer of l(x).
  static double max_safety_margin(const Params& params);
  // The analytic viability kernel (Fig. 6.4's solid line): |ẋ| < ẋ_max and the state can brake
  // at a_max before the position limit, x + ẋ|ẋ|/(2 a_max) ∈ (−x_max, x_max).
  static bool in_analytic_safe_set(const Params& params, double position, double velocity);

 private:
  Observation observe() const;

  Params params_;
  Space observation_space_, action_space_;
  Rng rng_;
  double position_ = 0.0, velocity_ = 0.0;
  int elapsed_steps_ = 0;
};

}  // namespace tendril::envs::safe_control
