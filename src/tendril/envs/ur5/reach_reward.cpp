#include "tendril/envs/ur5/reach_reward.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs::ur5 {

namespace {

std::string key_of(const Config& params, const std::string& key) {
  return params.source() + ": " + (params.path().empty() ? "" : params.path() + ".") + key;
}

double read_weight(const Config& params, const std::string& key, double fallback) {
  const double value = params.get_or<double>(key, fallback);
  if (!std::isfinite(value) || value < 0.0) {
    throw Error("must be finite and >= 0, got " + std::to_string(value), key_of(params, key));
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
  const std::string form = params.get_or<std::string>("orientation_form", "penalty");
  if (form != "penalty" && form != "bounded") {
    throw Error("must be 'penalty' or 'bounded', got '" + form + "'",
                key_of(params, "orientation_form"));
  }
  w.orientation_penalty = form == "penalty";
  return w;
}

ReachRewardTerms reach_reward(const ReachRewardWeights& weights, double previous_distance,
                              double distance, double orientation_error,
                              double action_penalty_weight, const Eigen::VectorXd& action,
                              bool success, bool collision) {
  ReachRewardTerms terms;
  terms.progress = weights.progress * (previous_distance - distance);
  terms.distance = weights.distance * std::exp(-weights.distance_sensitivity * distance);
  const double misalignment = orientation_error / std::numbers::pi;  // in [0, 1]
  terms.orientation =
      weights.orientation * (weights.orientation_penalty ? -misalignment : 1.0 - misalignment);
  terms.action = -action_penalty_weight * action.squaredNorm();
  terms.time = -weights.time;
  terms.success = success ? weights.success : 0.0;
  terms.collision = collision ? -weights.collision : 0.0;
  return terms;
}

}  // namespace tendril::envs::ur5
