#include "tendril/envs/safe_control/double_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"

namespace tendril::envs::safe_control {

std::unique_ptr<Env> DoubleIntegrator::create(const Config& params) {
  Params p;
  p.position_limit = params.get_or("position_limit", p.position_limit);
  p.velocity_limit = params.get_or("velocity_limit", p.velocity_limit);
  p.absolute_position_limit = params.get_or("absolute_position_limit", p.absolute_position_limit);
  p.absolute_velocity_limit = params.get_or("absolute_velocity_limit", p.absolute_velocity_limit);
  p.max_acceleration = params.get_or("max_acceleration", p.max_acceleration);
  p.goal_position = params.get_or("goal_position", p.goal_position);
  p.dt = params.get_or("dt", p.dt);
  p.horizon = params.get_or("horizon", p.horizon);
  p.discrete_actions = params.get_or("discrete_actions", p.discrete_actions);
  p.start_position = params.get_or("start_position", p.start_position);
  p.start_velocity = params.get_or("start_velocity", p.start_velocity);
  p.unsafe_penalty = params.get_or("unsafe_penalty", p.unsafe_penalty);
  params.reject_unknown();
  return std::make_unique<DoubleIntegrator>(p);
}

DoubleIntegrator::DoubleIntegrator(Params params) : params_(params) {
  const std::string who = std::string(kId) + " params";
  require(params_.position_limit > 0.0 && params_.velocity_limit > 0.0,
          "safe limits must be positive", who);
  require(params_.absolute_position_limit > params_.position_limit &&
              params_.absolute_velocity_limit > params_.velocity_limit,
          "absolute bounds must contain the safe set", who);
  require(params_.max_acceleration > 0.0 && params_.dt > 0.0 && params_.horizon > 0,
          "max_acceleration, dt and horizon must be positive", who);
  require(params_.discrete_actions == 0 || params_.discrete_actions >= 2,
          "discrete_actions must be 0 (continuous) or at least 2", who);
  require(params_.start_position >= 0.0 && params_.start_position <= params_.position_limit &&
              params_.start_velocity >= 0.0 && params_.start_velocity <= params_.velocity_limit,
          "the start box must lie in the safe box", who);
  // Unbounded position and velocity: the last step of an episode ends beyond the absolute box.
  const float inf = std::numeric_limits<float>::infinity();
  observation_space_ =
      Space::box(Eigen::Vector3f(-inf, -inf, 0.0f), Eigen::Vector3f(inf, inf, 1.0f));
  action_space_ = params_.discrete_actions > 0
                      ? Space::discrete(params_.discrete_actions)
                      : Space::box(1, static_cast<float>(-params_.max_acceleration),
                                   static_cast<float>(params_.max_acceleration));
}

double DoubleIntegrator::safety_margin(const Params& params, double position, double velocity) {
  return std::min(params.position_limit - std::abs(position),
                  params.velocity_limit - std::abs(velocity));
}

double DoubleIntegrator::max_safety_margin(const Params& params) {
  return std::min(params.position_limit, params.velocity_limit);
}

bool DoubleIntegrator::in_analytic_safe_set(const Params& params, double position,
                                            double velocity) {
  // Braking at a_max stops after ẋ²/(2 a_max); the stopping point must stay strictly inside.
  const double stop = position + velocity * std::abs(velocity) / (2.0 * params.max_acceleration);
  return std::abs(velocity) < params.velocity_limit && std::abs(stop) < params.position_limit &&
         std::abs(position) < params.position_limit;
}

double DoubleIntegrator::acceleration(const Action& action) const {
  check_action(action_space_, action, kId);
  const double a_max = params_.max_acceleration;
  if (params_.discrete_actions == 0)
    return std::clamp(static_cast<double>(action[0]), -a_max, a_max);
  const auto index = static_cast<int64_t>(action[0]);
  require(index >= 0 && index < params_.discrete_actions, "action index out of range", kId);
  return -a_max + 2.0 * a_max * static_cast<double>(index) / (params_.discrete_actions - 1);
}

Observation DoubleIntegrator::reset(std::optional<uint64_t> seed) {
  if (seed) rng_ = Rng(*seed);
  position_ = rng_.uniform(-params_.start_position, params_.start_position);
  velocity_ = rng_.uniform(-params_.start_velocity, params_.start_velocity);
  elapsed_steps_ = 0;
  return observe();
}

Step DoubleIntegrator::step(const Action& action) {
  const double a = acceleration(action);
  const double dt = params_.dt;
  position_ += velocity_ * dt + 0.5 * a * dt * dt;
  velocity_ += a * dt;
  ++elapsed_steps_;

  Step result;
  result.observation = observe();
  result.reward = -std::abs(position_ - params_.goal_position);
  result.terminated = std::abs(position_) > params_.absolute_position_limit ||
                      std::abs(velocity_) > params_.absolute_velocity_limit;
  result.truncated = !result.terminated && elapsed_steps_ >= params_.horizon;
  const double margin = safety_margin(params_, position_, velocity_);
  const double unsafe = margin <= 0.0 ? 1.0 : 0.0;
  result.reward -= params_.unsafe_penalty * unsafe;
  result.info.set("safety_margin", margin);
  result.info.set("unsafe", unsafe);
  result.info.set(info_keys::kCost, unsafe);
  return result;
}

void DoubleIntegrator::set_state(double position, double velocity, int elapsed_steps) {
  require(std::isfinite(position) && std::isfinite(velocity) && elapsed_steps >= 0,
          "state must be finite and time non-negative", "DoubleIntegrator::set_state");
  position_ = position;
  velocity_ = velocity;
  elapsed_steps_ = elapsed_steps;
}

Observation DoubleIntegrator::observe() const {
  return Eigen::Vector3f(static_cast<float>(position_), static_cast<float>(velocity_),
                         static_cast<float>(elapsed_steps_) / static_cast<float>(params_.horizon));
}

void DoubleIntegrator::save_state(SnapshotWriter& out) const {
  out.section("DoubleIntegrator");
  out.put(rng_);
  out.put(position_);
  out.put(velocity_);
  out.put(static_cast<int64_t>(elapsed_steps_));
}

void DoubleIntegrator::load_state(SnapshotReader& in) {
  in.section("DoubleIntegrator");
  Rng rng = rng_;
  in.get(rng);
  const double position = in.get_double();
  const double velocity = in.get_double();
  const int64_t elapsed = in.get_int64();
  rng_ = rng;
  position_ = position;
  velocity_ = velocity;
  elapsed_steps_ = static_cast<int>(elapsed);
}

EnvDescription DoubleIntegrator::description() {
  return {
      .observation = {{"position x", "m"},
                      {"velocity ẋ", "m/s"},
                      {"elapsed fraction of the horizon t/T", "1"}},
      .action = {{"commanded acceleration, |a| ≤ max_acceleration (discrete_actions ≥ 2: the index "
                  "of one of n evenly spaced levels)",
                  "m/s²"}},
      .reward =
          "−|x' − goal_position| per step, minus unsafe_penalty where the new state is "
          "unsafe (seed 001 §6.4.1; Table 6.1's penalty baseline)",
      .episode_end =
          "terminated beyond the absolute bounds |x| > absolute_position_limit or "
          "|ẋ| > absolute_velocity_limit; truncated after horizon steps",
      .parameters = {{"position_limit", "m", "safe |x|"},
                     {"velocity_limit", "m/s", "safe |ẋ|"},
                     {"absolute_position_limit", "m", "|x| beyond which the episode ends"},
                     {"absolute_velocity_limit", "m/s", "|ẋ| beyond which the episode ends"},
                     {"max_acceleration", "m/s²", "largest |a|"},
                     {"goal_position", "m", "the task's target x"},
                     {"dt", "s", "time per step"},
                     {"horizon", "steps", "T: truncation, and the observation's time scale"},
                     {"discrete_actions", "", "0: a Box action; n ≥ 2: Discrete(n)"},
                     {"start_position", "m", "starts uniform in ±start_position"},
                     {"start_velocity", "m/s", "starts uniform in ±start_velocity"},
                     {"unsafe_penalty", "1", "subtracted from the reward of unsafe steps"}},
  };
}

}  // namespace tendril::envs::safe_control
