#include "tendril/envs/sma_limb/learned_reach_task.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs::sma_limb {

double GoalTolerance::at(int64_t simulated_steps) const {
  if (!dynamic) return end_deg;
  const double progress = std::min(
      1.0, static_cast<double>(std::max<int64_t>(simulated_steps, 0)) / static_cast<double>(steps));
  return start_deg + (end_deg - start_deg) * progress;
}

void GoalTolerance::validate(const char* where) const {
  require(std::isfinite(end_deg) && end_deg > 0.0,
          "tolerance_end must be > 0 degrees, got " + std::to_string(end_deg), where);
  if (dynamic) {
    require(std::isfinite(start_deg) && start_deg >= end_deg,
            "tolerance_start must be >= tolerance_end, got " + std::to_string(start_deg), where);
    require(steps >= 1, "tolerance_steps must be >= 1, got " + std::to_string(steps), where);
  }
}

LearnedReachOptions LearnedReachOptions::from_config(const Config& params) {
  LearnedReachOptions options;
  options.power_proxy = params.get_or<bool>("power_proxy", options.power_proxy);
  options.integer_throttles = params.get_or<bool>("integer_throttles", options.integer_throttles);
  options.tolerance.dynamic = params.get_or<bool>("dynamic_tolerance", options.tolerance.dynamic);
  options.tolerance.start_deg =
      params.get_or<double>("tolerance_start", options.tolerance.start_deg);
  options.tolerance.end_deg = params.get_or<double>("tolerance_end", options.tolerance.end_deg);
  options.tolerance.steps = params.get_or<int64_t>("tolerance_steps", options.tolerance.steps);
  options.bound = params.get_or<double>("bound", options.bound);
  options.full_reset_probability =
      params.get_or<double>("full_reset_probability", options.full_reset_probability);
  options.goal_angle_range = params.get_or<double>("goal_angle_range", options.goal_angle_range);
  options.goal_velocity_range =
      params.get_or<double>("goal_velocity_range", options.goal_velocity_range);
  options.start_angle_range = params.get_or<double>("start_angle_range", options.start_angle_range);
  options.start_velocity_range =
      params.get_or<double>("start_velocity_range", options.start_velocity_range);
  options.history = params.get_or<int>("history", options.history);
  options.validate(params.path().empty() ? "env.params" : params.path().c_str());
  return options;
}

void LearnedReachOptions::validate(const char* where) const {
  tolerance.validate(where);
  require(std::isfinite(bound) && bound > 0.0, "bound must be > 0, got " + std::to_string(bound),
          where);
  require(full_reset_probability >= 0.0 && full_reset_probability <= 1.0,
          "full_reset_probability must be in [0, 1], got " + std::to_string(full_reset_probability),
          where);
  require(history >= 0, "history must be >= 0 rows, got " + std::to_string(history), where);
  for (const double range :
       {goal_angle_range, goal_velocity_range, start_angle_range, start_velocity_range}) {
    require(std::isfinite(range) && range >= 0.0 && range < bound,
            "goal and start ranges must lie in [0, bound), got " + std::to_string(range), where);
  }
}

ReachOutcome reach_outcome(const Eigen::Vector4d& state, const Eigen::Vector4d& goal,
                           const Eigen::Vector2d& throttles, double tolerance_deg, double bound) {
  ReachOutcome outcome;
  outcome.distance_deg = (state.head<2>() - goal.head<2>()).norm();
  outcome.reward = -(outcome.distance_deg + (throttles / kMaxThrottle).squaredNorm());
  if (outcome.distance_deg < tolerance_deg) {
    outcome.reached = true;
    const Eigen::Vector2d velocity = state.tail<2>();
    const Eigen::Vector2d goal_velocity = goal.tail<2>();
    // ‖a‖‖b‖ − a·b ≥ 0 by Cauchy–Schwarz; the max guards rounding just below 0.
    const double mismatch =
        std::max(0.0, velocity.norm() * goal_velocity.norm() - velocity.dot(goal_velocity));
    outcome.reward += -std::sqrt(mismatch) + kGoalReward;
  } else if (!(state.array().abs() <= bound).all()) {
    outcome.out_of_bounds = true;
    outcome.reward -= kBoundsPenalty;
  }
  return outcome;
}

}  // namespace tendril::envs::sma_limb
