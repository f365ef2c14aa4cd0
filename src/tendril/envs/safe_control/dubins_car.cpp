#include "tendril/envs/safe_control/dubins_car.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"

namespace tendril::envs::safe_control {

std::unique_ptr<Env> DubinsCar::create(const Config& params) {
  Params p;
  p.speed = params.get_or("speed", p.speed);
  p.max_turn_rate = params.get_or("max_turn_rate", p.max_turn_rate);
  p.box_limit = params.get_or("box_limit", p.box_limit);
  p.obstacle_radius = params.get_or("obstacle_radius", p.obstacle_radius);
  p.absolute_limit = params.get_or("absolute_limit", p.absolute_limit);
  p.goal_x = params.get_or("goal_x", p.goal_x);
  p.goal_y = params.get_or("goal_y", p.goal_y);
  p.goal_radius = params.get_or("goal_radius", p.goal_radius);
  p.goal_bonus = params.get_or("goal_bonus", p.goal_bonus);
  p.distance_weight = params.get_or("distance_weight", p.distance_weight);
  p.dt = params.get_or("dt", p.dt);
  p.horizon = params.get_or("horizon", p.horizon);
  p.discrete_actions = params.get_or("discrete_actions", p.discrete_actions);
  p.discrete_speeds = params.get_or("discrete_speeds", p.discrete_speeds);
  p.start_low = params.get_or("start_low", p.start_low);
  p.start_high = params.get_or("start_high", p.start_high);
  p.heading_low = params.get_or("heading_low", p.heading_low);
  p.heading_high = params.get_or("heading_high", p.heading_high);
  p.start_anywhere = params.get_or("start_anywhere", p.start_anywhere);
  p.unsafe_penalty = params.get_or("unsafe_penalty", p.unsafe_penalty);
  p.speed_control = params.get_or("speed_control", p.speed_control);
  p.min_speed = params.get_or("min_speed", p.min_speed);
  p.observe_margin = params.get_or("observe_margin", p.observe_margin);
  params.reject_unknown();
  return std::make_unique<DubinsCar>(p);
}

DubinsCar::DubinsCar(Params params) : params_(params) {
  const std::string who = std::string(kId) + " params";
  require(
      params_.speed > 0.0 && params_.max_turn_rate > 0.0 && params_.dt > 0.0 && params_.horizon > 0,
      "speed, max_turn_rate, dt and horizon must be positive", who);
  require(params_.obstacle_radius >= 0.0 && params_.box_limit > params_.obstacle_radius &&
              params_.absolute_limit > params_.box_limit,
          "need 0 ≤ obstacle_radius < box_limit < absolute_limit", who);
  require(params_.discrete_actions == 0 || params_.discrete_actions >= 2,
          "discrete_actions must be 0 (continuous) or at least 2", who);
  require(params_.discrete_speeds == 0 || params_.discrete_speeds >= 2,
          "discrete_speeds must be 0 or at least 2", who);
  require(params_.speed_control || params_.discrete_speeds == 0,
          "discrete_speeds needs speed_control", who);
  const bool discrete_turns = params_.discrete_actions > 0;
  require(!params_.speed_control || discrete_turns == (params_.discrete_speeds > 0),
          "speed_control takes continuous actions (discrete_actions: 0) or both discrete_actions "
          "and discrete_speeds",
          who);
  require(params_.min_speed >= 0.0 && params_.min_speed <= params_.speed,
          "min_speed must lie in [0, speed]", who);
  require(params_.start_low <= params_.start_high && params_.heading_low <= params_.heading_high,
          "start ranges must not be empty", who);
  require(safety_margin(params_, params_.start_low, params_.start_low) > 0.0 &&
              safety_margin(params_, params_.start_high, params_.start_high) > 0.0 &&
              safety_margin(params_, params_.start_low, params_.start_high) > 0.0,
          "the start box must lie in the safe set", who);
  // Unbounded position: the last step of an episode ends beyond the absolute box.
  const float inf = std::numeric_limits<float>::infinity();
  const int size = params_.observe_margin ? 6 : 5;
  Eigen::VectorXf low(size), high(size);
  low.head(5) << -inf, -inf, -1.0f, -1.0f, 0.0f;
  high.head(5) << inf, inf, 1.0f, 1.0f, 1.0f;
  if (params_.observe_margin) {  // d ≤ max d, and unbounded below beyond the walls
    low[5] = -inf;
    high[5] = static_cast<float>(max_safety_margin(params_));
  }
  observation_space_ = Space::box(low, high);
  if (params_.discrete_actions > 0) {
    action_space_ =
        Space::discrete(params_.discrete_actions * std::max(params_.discrete_speeds, 1));
  } else if (params_.speed_control) {
    action_space_ = Space::box(Eigen::Vector2f(static_cast<float>(-params_.max_turn_rate),
                                               static_cast<float>(params_.min_speed)),
                               Eigen::Vector2f(static_cast<float>(params_.max_turn_rate),
                                               static_cast<float>(params_.speed)));
  } else {
    action_space_ = Space::box(1, static_cast<float>(-params_.max_turn_rate),
                               static_cast<float>(params_.max_turn_rate));
  }
}

double DubinsCar::safety_margin(const Params& params, double x, double y) {
  const double walls = params.box_limit - std::max(std::abs(x), std::abs(y));
  return std::min(walls, std::hypot(x, y) - params.obstacle_radius);
}

double DubinsCar::max_safety_margin(const Params& params) {
  const double diagonal = (params.box_limit + params.obstacle_radius) / (1.0 + std::numbers::sqrt2);
  return params.box_limit - diagonal;
}

double DubinsCar::turn_rate(const Action& action) const {
  check_action(action_space_, action, kId);
  const double w_max = params_.max_turn_rate;
  if (params_.discrete_actions == 0)
    return std::clamp(static_cast<double>(action[0]), -w_max, w_max);
  const int64_t turn = discrete_index(action) % params_.discrete_actions;
  return -w_max + 2.0 * w_max * static_cast<double>(turn) / (params_.discrete_actions - 1);
}

int64_t DubinsCar::discrete_index(const Action& action) const {
  const auto index = static_cast<int64_t>(action[0]);
  require(index >= 0 && index < action_space_.n(), "action index out of range", kId);
  return index;
}

double DubinsCar::commanded_speed(const Action& action) const {
  if (!params_.speed_control) return params_.speed;
  check_action(action_space_, action, kId);
  if (params_.discrete_speeds == 0)
    return std::clamp(static_cast<double>(action[1]), params_.min_speed, params_.speed);
  const int64_t level = discrete_index(action) / params_.discrete_actions;
  return params_.min_speed + (params_.speed - params_.min_speed) * static_cast<double>(level) /
                                 (params_.discrete_speeds - 1);
}

Observation DubinsCar::reset(std::optional<uint64_t> seed) {
  if (seed) rng_ = Rng(*seed);
  if (params_.start_anywhere) {
    const double box = params_.box_limit;
    do {  // rejection: the disc and the walls are outside the safe set
      x_ = rng_.uniform(-box, box);
      y_ = rng_.uniform(-box, box);
    } while (safety_margin(params_, x_, y_) <= 0.0);
    heading_ = rng_.uniform(-std::numbers::pi, std::numbers::pi);
  } else {
    x_ = rng_.uniform(params_.start_low, params_.start_high);
    y_ = rng_.uniform(params_.start_low, params_.start_high);
    heading_ = rng_.uniform(params_.heading_low, params_.heading_high);
  }
  elapsed_steps_ = 0;
  return observe();
}

Step DubinsCar::step(const Action& action) {
  const double omega = turn_rate(action);
  const double v = commanded_speed(action), dt = params_.dt;
  const double heading = heading_ + omega * dt;
  if (std::abs(omega) < 1e-9) {
    x_ += v * dt * std::cos(heading_);
    y_ += v * dt * std::sin(heading_);
  } else {  // exact arc of radius v/ω
    x_ += v / omega * (std::sin(heading) - std::sin(heading_));
    y_ -= v / omega * (std::cos(heading) - std::cos(heading_));
  }
  heading_ = std::remainder(heading, 2.0 * std::numbers::pi);
  ++elapsed_steps_;

  Step result;
  result.observation = observe();
  const double distance = std::hypot(x_ - params_.goal_x, y_ - params_.goal_y);
  const bool in_goal = distance <= params_.goal_radius;
  result.reward = -params_.distance_weight * distance + (in_goal ? params_.goal_bonus : 0.0);
  result.terminated = std::max(std::abs(x_), std::abs(y_)) > params_.absolute_limit;
  result.truncated = !result.terminated && elapsed_steps_ >= params_.horizon;
  const double margin = safety_margin(params_, x_, y_);
  const double unsafe = margin <= 0.0 ? 1.0 : 0.0;
  result.reward -= params_.unsafe_penalty * unsafe;
  result.info.set("safety_margin", margin);
  result.info.set("unsafe", unsafe);
  result.info.set(info_keys::kCost, unsafe);
  result.info.set(info_keys::kDistance, distance);
  result.info.set(info_keys::kIsSuccess, in_goal ? 1.0 : 0.0);
  return result;
}

void DubinsCar::set_state(double x, double y, double heading, int elapsed_steps) {
  require(std::isfinite(x) && std::isfinite(y) && std::isfinite(heading) && elapsed_steps >= 0,
          "state must be finite and time non-negative", "DubinsCar::set_state");
  x_ = x;
  y_ = y;
  heading_ = heading;
  elapsed_steps_ = elapsed_steps;
}

Observation DubinsCar::observation_of(const Params& params, double x, double y, double heading,
                                      float time_fraction) {
  Observation o(params.observe_margin ? 6 : 5);
  o.head(5) << static_cast<float>(x), static_cast<float>(y), static_cast<float>(std::cos(heading)),
      static_cast<float>(std::sin(heading)), time_fraction;
  if (params.observe_margin) o[5] = static_cast<float>(safety_margin(params, x, y));
  return o;
}

Observation DubinsCar::observe() const {
  return observation_of(params_, x_, y_, heading_,
                        static_cast<float>(elapsed_steps_) / static_cast<float>(params_.horizon));
}

void DubinsCar::save_state(SnapshotWriter& out) const {
  out.section("DubinsCar");
  out.put(rng_);
  out.put(x_);
  out.put(y_);
  out.put(heading_);
  out.put(static_cast<int64_t>(elapsed_steps_));
}

void DubinsCar::load_state(SnapshotReader& in) {
  in.section("DubinsCar");
  Rng rng = rng_;
  in.get(rng);
  const double x = in.get_double(), y = in.get_double(), heading = in.get_double();
  const int64_t elapsed = in.get_int64();
  rng_ = rng;
  x_ = x;
  y_ = y;
  heading_ = heading;
  elapsed_steps_ = static_cast<int>(elapsed);
}

EnvDescription DubinsCar::description() {
  return {
      .observation =
          {{"position x", "m"},
           {"position y", "m"},
           {"cos ψ (heading from the x axis)", "1"},
           {"sin ψ", "1"},
           {"elapsed fraction of the horizon t/T (observe_margin: then the safety margin "
            "d = min(box − |x|, box − |y|, ‖p‖ − obstacle_radius) in m, one more entry)",
            "1"}},
      .action = {{"turn rate ω, |ω| ≤ max_turn_rate (speed_control: then the speed v, one more "
                  "entry; discrete_actions ≥ 2: one index)",
                  "rad/s"}},
      .reward =
          "−distance_weight ‖p' − goal‖ + goal_bonus inside the goal disc, minus "
          "unsafe_penalty where the new state is unsafe (seed 001 §6.4.1)",
      .episode_end =
          "terminated when |x| or |y| exceeds absolute_limit; truncated after horizon "
          "steps",
      .parameters = {{"speed", "m/s", "forward speed (the top speed with speed_control)"},
                     {"max_turn_rate", "rad/s", "largest |ω|"},
                     {"box_limit", "m", "safe |x|, |y|"},
                     {"obstacle_radius", "m", "keep-out disc at the origin"},
                     {"absolute_limit", "m", "|x|, |y| beyond which the episode ends"},
                     {"goal_x", "m", "goal centre x"},
                     {"goal_y", "m", "goal centre y"},
                     {"goal_radius", "m", "goal disc radius"},
                     {"goal_bonus", "1", "reward inside the goal disc"},
                     {"distance_weight", "1/m", "weight of the goal distance"},
                     {"dt", "s", "time per step"},
                     {"horizon", "steps", "T: truncation, and the observation's time scale"},
                     {"discrete_actions", "", "0: a Box action; n ≥ 2: n turn rates"},
                     {"discrete_speeds", "",
                      "with speed_control and discrete turn rates: m speeds"},
                     {"start_low", "m", "starts: x, y uniform in [start_low, start_high]"},
                     {"start_high", "m", "see start_low"},
                     {"heading_low", "rad", "starts: ψ uniform in [heading_low, heading_high]"},
                     {"heading_high", "rad", "see heading_low"},
                     {"start_anywhere", "", "start anywhere in the safe set instead"},
                     {"unsafe_penalty", "1", "subtracted from the reward of unsafe steps"},
                     {"speed_control", "", "the action is [ω, v], v in [min_speed, speed]"},
                     {"min_speed", "m/s", "lowest speed with speed_control"},
                     {"observe_margin", "",
                      "the observation gets a sixth entry: the safety margin d (m)"}},
  };
}

}  // namespace tendril::envs::safe_control
