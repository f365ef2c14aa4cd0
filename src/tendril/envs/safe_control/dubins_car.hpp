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

// The Dubins car of seed 001 §6.4.1: a unicycle at constant speed v = 1.2 m/s steered by its
// turn rate ω (rad/s), lab frame (x, y) in m, heading ψ from the x axis:
//
//   ẋ = v cos ψ,  ẏ = v sin ψ,  ψ̇ = ω,
//
// integrated exactly over each step with ω held (arcs of radius v/ω). Safe: |x|, |y| < 2 m and
// outside the keep-out disc of radius 1 m at the origin; the episode terminates only beyond the
// absolute box. Task: reach the goal disc at (1.8, 1.8) m of radius 0.5 m, whose shortest path
// from the lower-left starts crosses the keep-out disc: reward −w_d ‖p' − g‖ + bonus inside it.
//
// Observation [x, y, cos ψ, sin ψ, t/T] (time in the state for eq. 6.3), with observe_margin
// also d (below). Info: "safety_margin"
// d = min(2 − |x|, 2 − |y|, ‖p‖ − 1) (m), "cost"/"unsafe" 1 where d ≤ 0, "is_success" 1 in the
// goal disc.
//
// Not in the thesis (labelled suggestions, in config): the dynamics form above, |ω| ≤ 2 rad/s,
// dt = 0.05 s, T = 200, absolute box ±3 m, starts in the lower-left quadrant heading up-right.
//
// The thesis' sentence on the car is garbled ("the absolute maximum bounds are defined with an
// input velocity of 1.2 m/s"). Two readings, both in config: the speed is fixed at 1.2 m/s and
// ω is the only input (default; the spec's suggestion), or the speed is an input too, v ∈
// [min_speed, 1.2] m/s (`speed_control`; the action is then [ω, v]). With a fixed speed the
// turning radius of 0.6 m exceeds the 1 m corridor between disc and walls halfway, so the safe
// set is a thin orbit; with a speed input the car can stop, every safe state is recoverable, and
// a filter that keeps stopping short of the disc can deadlock against the task — the conflict
// the thesis' discussion (§6.6) names.
class DubinsCar : public Env, public SafetyTask {
 public:
  static constexpr const char* kId = "Safety/DubinsCar-v0";

  struct Params {
    double speed = 1.2;                 // m/s
    double max_turn_rate = 2.0;         // rad/s, |ω|
    double box_limit = 2.0;             // m, safe |x|, |y|
    double obstacle_radius = 1.0;       // m, keep-out disc at the origin
    double absolute_limit = 3.0;        // m, the episode ends beyond
    double goal_x = 1.8, goal_y = 1.8;  // m
    double goal_radius = 0.5;           // m
    double goal_bonus = 1.0;            // reward inside the goal disc
    double distance_weight = 0.1;       // 1/m
    double dt = 0.05;                   // s per step
    int horizon = 200;                  // steps T
    int discrete_actions = 0;           // 0: Box ω; n ≥ 2: n turn rates over [−ω_max, ω_max]
    // With speed_control and n discrete turn rates: m ≥ 2 speeds over [min_speed, speed], the
    // action index k meaning turn rate k mod n and speed k div n (n·m actions, for a DQN agent).
    int discrete_speeds = 0;
    // Starts: x, y uniform in [start_low, start_high], ψ uniform in [heading_low, heading_high].
    double start_low = -1.8, start_high = -1.3;                   // m
    double heading_low = 0.0, heading_high = 1.5707963267948966;  // rad
    // Training starts over the whole safe set instead (position uniform over the box outside the
    // disc, heading uniform), so that a safety critic learned from the rollouts sees all of it;
    // evaluations (safety::evaluate_safety_run) switch it off and judge the task's starts.
    bool start_anywhere = false;
    // The reward-penalty baseline of seed 001 Table 6.1: subtracted from the reward of every step
    // that ends in X_unsafe (the thesis gives no size; 0 leaves the task reward alone).
    double unsafe_penalty = 0.0;
    bool speed_control = false;  // the action is [ω, v] with v in [min_speed, speed]
    double min_speed = 0.0;      // m/s
    // A sixth observation entry: the safety margin d (m, below), so that a critic can read the
    // distance to the constraint instead of learning the disc and the walls from (x, y). Not in
    // the thesis; an input feature tried against its parked filter (docs/results/safety_filter.md).
    bool observe_margin = false;
  };
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  DubinsCar() : DubinsCar(Params{}) {}
  explicit DubinsCar(Params params);

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  const Params& params() const { return params_; }
  // SafetyTask: the constraint and search space of the safety filter (dubins_car_safety.cpp: states
  // (x, y, ψ) over (box, box, π)).
  std::unique_ptr<SafetyConstraint> safety_constraint() const override;
  std::unique_ptr<SafetySearchSpace> safety_search_space() const override;
  void set_state(double x, double y, double heading, int elapsed_steps = 0);
  Eigen::Vector3d state() const { return {x_, y_, heading_}; }
  double turn_rate(const Action& action) const;
  // The speed an action commands (m/s): `speed`, or with speed_control its clamped second entry
  // (Box) or its speed level (Discrete).
  double commanded_speed(const Action& action) const;

  // d of eq. (6.4), m: the smallest distance to the box walls and to the disc.
  static double safety_margin(const Params& params, double x, double y);
  // The observation [x, y, cos ψ, sin ψ, t/T] (and d with observe_margin) of a state.
  static Observation observation_of(const Params& params, double x, double y, double heading,
                                    float time_fraction);
  // max d over the safe set. For |x| ≥ |y| the wall distance is x_max − |x| and the disc
  // distance at most √2|x| − r, reached on the diagonal; equal there at a = (x_max + r)/(1 + √2),
  // so max d = x_max − a (0.757 m for the default geometry).
  static double max_safety_margin(const Params& params);

 private:
  Observation observe() const;
  int64_t discrete_index(const Action& action) const;

  Params params_;
  Space observation_space_, action_space_;
  Rng rng_;
  double x_ = 0.0, y_ = 0.0, heading_ = 0.0;
  int elapsed_steps_ = 0;
};

}  // namespace tendril::envs::safe_control
