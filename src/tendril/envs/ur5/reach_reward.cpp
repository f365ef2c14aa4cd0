#include "tendril/envs/ur5/reach_reward.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs::ur5 {

namespace {

double read_weight(const Config& params, const std::string& key, double fallback) {
  const double value = params.get_or<double>(key, fallback);
  if (!std::isfinite(value) || value < 0.0) {
    throw Error("must be finite and >= 0, got " + std::to_string(value),
                params.source() + ": " + (params.path().empty() ? "" : params.path() + ".") + key);
  }
  return value;
}

}  // namespace

ReachRewardWeights ReachRewardWeights::from_config(const Config& params) {
  ReachRewardWeights w;
  w.progress = read_weight(params, "progress_weight", w.progress);
  w.distance = read_weight(params, "distance_weight", w.distance);
  w.distance_sensitivity = read_weight(params, "distance_sensitivity", w.distance_sensitivity);
  w.orientation = read_weight(params, "orientation_weight", w.orientation);
  w.time = read_weight(params, "time_penalty", w.time);
  w.success = read_weight(params, "success_bonus", w.success);
  w.collision = read_weight(params, "collision_penalty", w.collision);
  return w;
}

ReachRewardTerms reach_reward(const ReachRewardWeights& weights, double previous_distance,
                              double distance, double orientation_error,
                              double action_penalty_weight, const Eigen::VectorXd& action,
                              bool success, bool collision) {
  ReachRewardTerms terms;
  terms.progress = weights.progress * (previous_distance - distance);
  terms.distance = weights.distance * std::exp(-weights.distance_sensitivity * distance);
  terms.orientation = weights.orientation * (1.0 - orientation_error / std::numbers::pi);
  terms.action = -action_penalty_weight * action.squaredNorm();
  terms.time = -weights.time;
  terms.success = success ? weights.success : 0.0;
  terms.collision = collision ? -weights.collision : 0.0;
  return terms;
}

}  // namespace tendril::envs::ur5
