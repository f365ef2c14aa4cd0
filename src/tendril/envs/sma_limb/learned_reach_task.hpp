#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "tendril/core/config.hpp"
#include "tendril/envs/sma_limb/power_proxy.hpp"

namespace tendril::envs::sma_limb {

// The goal tolerance δ of the reaching task (thesis §5.1.1, "dynamic goal tolerance"): large at
// first, shrinking linearly in the number of steps an environment has simulated (over all its
// episodes) to `end`, then constant. The thesis gives only the end, 1°; the start (5°) and the
// length are the author's code's intent — its own schedule took the max with itself and stayed
// at 5°. With `dynamic` off the tolerance is `end` throughout.
struct GoalTolerance {
  bool dynamic = true;
  double start_deg = 5.0;
  double end_deg = 1.0;
  // Steps of one environment until δ = end; 8000 × 10 envs = 80 % of Table A.1's 100k steps.
  int64_t steps = 8000;

  // δ in degrees after `simulated_steps` steps.
  double at(int64_t simulated_steps) const;
  void validate(const char* where) const;
};

// The settings of SmaLimb/LearnedReach-v0 (thesis §5.1.1, the spec's [CODE] values where the
// thesis is silent). Angles in degrees, angular velocities in degrees per second.
struct LearnedReachOptions {
  bool power_proxy = true;        // the four power values in the observation
  bool integer_throttles = true;  // actions rounded to whole throttles, as the firmware takes them
  GoalTolerance tolerance;
  double bound = 80.0;  // θx, θy, θ̇x, θ̇y ∈ [−bound, bound]
  double full_reset_probability = 0.01;
  double goal_angle_range = 75.0;      // θ_goal ~ U[−75, 75]²
  double goal_velocity_range = 50.0;   // θ̇_goal ~ U[−50, 50]²
  double start_angle_range = 75.0;     // full reset: θ ~ U[−75, 75]²
  double start_velocity_range = 10.0;  // full reset: θ̇ ~ U[−10, 10]²
  // Rows of the recent history appended to the observation (0: none), for policies that read
  // it (thesis §5.1.2: a window of 100 rows of state and previous throttles, continuing across
  // half resets). At most the model's window.
  int history = 0;
  PowerProxy::Params power;

  // Reads the optional keys power_proxy, integer_throttles, dynamic_tolerance,
  // tolerance_start, tolerance_end, tolerance_steps, bound, full_reset_probability,
  // goal_angle_range, goal_velocity_range, start_angle_range, start_velocity_range, history;
  // raises Error
  // naming the key on a bad value.
  static LearnedReachOptions from_config(const Config& params);
  void validate(const char* where) const;
};

// Reward and termination of one step (eqs. 5.5–5.8), for state x = [θx, θy, θ̇x, θ̇y] reached
// under throttles u, and goal g = [θx, θy, θ̇x, θ̇y]:
//   r_reach = −(‖θ − θ_goal‖ + ‖u/10‖²)     eq. 5.5; the thesis prints +‖u‖² of the policy's
//                                            action in [−1, 1] = u/10 — a penalty is meant
//   r_vel   = −sqrt(‖θ̇‖‖θ̇_goal‖ − θ̇·θ̇_goal)  eq. 5.6, only on reaching the goal
//   r_term  = +1000 at the goal (‖θ − θ_goal‖ < δ), −5000 out of bounds   eq. 5.7
//   r = r_reach + r_vel + r_term             eq. 5.8
// The goal is checked first: a state within δ of a goal is in bounds.
struct ReachOutcome {
  double reward = 0.0;
  double distance_deg = 0.0;  // ‖θ − θ_goal‖
  bool reached = false;
  bool out_of_bounds = false;
};

inline constexpr double kGoalReward = 1000.0;
inline constexpr double kBoundsPenalty = 5000.0;
inline constexpr double kMaxThrottle = 10.0;

ReachOutcome reach_outcome(const Eigen::Vector4d& state, const Eigen::Vector4d& goal,
                           const Eigen::Vector2d& throttles, double tolerance_deg, double bound);

}  // namespace tendril::envs::sma_limb
