#include "tendril/envs/sma_limb/learned_safety_env.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/envs/learned/model_loader.hpp"
#include "tendril/envs/sma_limb/linear_limb_model.hpp"

namespace tendril::envs::sma_limb {

LearnedSafetyEnv::LearnedSafetyEnv(std::shared_ptr<DynamicsModel> model, Params params,
                                   uint64_t seed)
    : model_(std::move(model)),
      params_(params),
      windows_(1, model_ ? model_->window_length() : 1, 4, 2),
      rng_(seed),
      inputs_(BatchMatrix::Zero(1, 2)) {
  require(model_ != nullptr, "needs a dynamics model", kId);
  require(model_->state_dim() == 4 && model_->input_dim() == 2,
          "needs a model of the limb's 4 states (θx, θy, θ̇x, θ̇y) and 2 throttles", kId);
  require(params_.safe_radius > 0.0 && params_.start_velocity >= 0.0 &&
              params_.velocity_limit > 0.0 && params_.horizon > 0,
          "safe_radius, velocity_limit and horizon must be positive, start_velocity non-negative",
          kId);
  const float inf = std::numeric_limits<float>::infinity();
  Eigen::VectorXf low(5), high(5);
  low << -inf, -inf, -inf, -inf, 0.0f;
  high << inf, inf, inf, inf, 1.0f;
  observation_space_ = Space::box(low, high);
  action_space_ = Space::discrete(4);
}

std::unique_ptr<Env> LearnedSafetyEnv::create(const Config& params) {
  Params p;
  const uint64_t seed = params.get_or<uint64_t>("seed", 0);
  p.safe_radius = params.get_or("safe_radius", p.safe_radius);
  p.start_velocity = params.get_or("start_velocity", p.start_velocity);
  p.velocity_limit = params.get_or("velocity_limit", p.velocity_limit);
  p.horizon = params.get_or("horizon", p.horizon);
  p.terminate_on_unsafe = params.get_or("terminate_on_unsafe", p.terminate_on_unsafe);
  std::shared_ptr<DynamicsModel> model;
  if (params.has("model")) {
    model = load_dynamics_model(params.get<std::string>("model"), kId);
  } else {
    model = std::make_shared<LinearLimbModel>();
  }
  params.reject_unknown();
  return std::make_unique<LearnedSafetyEnv>(std::move(model), p, seed);
}

Eigen::Vector2d LearnedSafetyEnv::throttles(int action) {
  require(action >= 0 && action < 4, "action index out of range", kId);
  // u1 upper right, u2 upper left, u3 lower left, u4 lower right (thesis Fig. 3.1).
  static const double signs[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  return {kThrottle * signs[action][0], kThrottle * signs[action][1]};
}

Observation LearnedSafetyEnv::reset(std::optional<uint64_t> seed) {
  if (seed) rng_ = Rng(*seed);
  const double r = params_.safe_radius, v = params_.start_velocity;
  Eigen::Vector4d start;
  do {
    start[0] = rng_.uniform(-r, r);
    start[1] = rng_.uniform(-r, r);
  } while (safety_margin(params_, start[0], start[1]) <= 0.0);
  start[2] = rng_.uniform(-v, v);
  start[3] = rng_.uniform(-v, v);
  set_state(start);
  return observe();
}

void LearnedSafetyEnv::set_state(const Eigen::Vector4d& state, int elapsed_steps) {
  require(state.allFinite() && elapsed_steps >= 0, "state must be finite, time non-negative",
          "LearnedSafetyEnv::set_state");
  windows_.reset(0, state.cast<float>());
  elapsed_steps_ = elapsed_steps;
}

Step LearnedSafetyEnv::step(const Action& action) {
  check_action(action_space_, action, kId);
  inputs_.row(0) = throttles(static_cast<int>(action[0])).cast<float>().transpose();
  model_->step(windows_, inputs_, next_states_);
  ++elapsed_steps_;
  const Eigen::Vector4d next = next_states_.row(0).cast<double>().transpose();
  const bool finite = next.allFinite();
  const double margin = finite ? safety_margin(params_, next[0], next[1]) : -1.0;
  const bool unsafe = margin <= 0.0;
  const bool too_fast =
      !finite || std::max(std::abs(next[2]), std::abs(next[3])) > params_.velocity_limit;
  Step result;
  result.observation = observe();
  if (!result.observation.allFinite()) result.observation.head<4>().setZero();
  result.reward = 0.0;
  result.terminated = (params_.terminate_on_unsafe && unsafe) || too_fast;
  result.truncated = !result.terminated && elapsed_steps_ >= params_.horizon;
  result.info.set("safety_margin", margin);
  result.info.set("unsafe", unsafe ? 1.0 : 0.0);
  result.info.set(info_keys::kCost, unsafe ? 1.0 : 0.0);
  result.info.set(info_keys::kNan, finite ? 0.0 : 1.0);
  return result;
}

Observation LearnedSafetyEnv::observe() const {
  Observation o(5);
  o.head<4>() = windows_.state(0);
  o[4] = static_cast<float>(elapsed_steps_) / static_cast<float>(params_.horizon);
  return o;
}

void LearnedSafetyEnv::save_state(SnapshotWriter& out) const {
  out.section(kId);
  out.put(rng_);
  windows_.save_state(out);
  out.put(static_cast<int64_t>(elapsed_steps_));
}

void LearnedSafetyEnv::load_state(SnapshotReader& in) {
  in.section(kId);
  Rng rng = rng_;
  in.get(rng);
  windows_.load_state(in);
  const int64_t elapsed = in.get_int64();
  rng_ = rng;
  elapsed_steps_ = static_cast<int>(elapsed);
}

EnvDescription LearnedSafetyEnv::description() {
  return {
      .observation = {{"bend θx, θy", "°", 2},
                      {"bend rate θ̇x, θ̇y", "°/s", 2},
                      {"elapsed fraction of the horizon t/T", "1"}},
      .action = {{"diagonal move at full throttle: 0 (+10, +10), 1 (−10, +10), 2 (−10, −10), "
                  "3 (+10, −10)",
                  "1"}},
      .reward =
          "0 (the safety agent learns r_safe through the safety co-trainer; seed 001 "
          "§6.5.2)",
      .episode_end =
          "terminated when ‖θ‖ ≥ safe_radius (terminate_on_unsafe), |θ̇| > "
          "velocity_limit or on a non-finite prediction; truncated after horizon steps",
      .parameters = {{"model", "",
                      "a model file or a `tendril model fit` run; default "
                      "LinearLimbModel, a stand-in that is not the limb",
                      true},
                     {"seed", "", "random stream of the first reset without a seed"},
                     {"safe_radius", "°", "R of the safe disc ‖θ‖ < R"},
                     {"start_velocity", "°/s", "starts: θ̇ uniform in ± this"},
                     {"velocity_limit", "°/s", "|θ̇| beyond which the episode ends"},
                     {"horizon", "steps", "T: truncation, and the observation's time scale"},
                     {"terminate_on_unsafe", "", "leaving the safe disc ends the episode"}},
  };
}

}  // namespace tendril::envs::sma_limb
