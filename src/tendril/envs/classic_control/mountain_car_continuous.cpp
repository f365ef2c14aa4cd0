#include "tendril/envs/classic_control/mountain_car_continuous.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::envs {

std::unique_ptr<Env> MountainCarContinuous::create(const Config& params) {
  Params values;
  values.goal_velocity = params.get_or<double>("goal_velocity", values.goal_velocity);
  return std::make_unique<MountainCarContinuous>(values);
}

MountainCarContinuous::MountainCarContinuous(Params params)
    : params_(params),
      observation_space_(Space::box(Eigen::Vector2f(kMinPosition, -kMaxSpeed),
                                    Eigen::Vector2f(kMaxPosition, kMaxSpeed))),
      action_space_(Space::box(1, -1.0f, 1.0f)) {}

Observation MountainCarContinuous::reset(std::optional<uint64_t> seed) {
  if (seed) rng_ = Rng(*seed);
  position_ = rng_.uniform(-0.6, -0.4);
  velocity_ = 0.0;
  return Eigen::Vector2f(static_cast<float>(position_), static_cast<float>(velocity_));
}

Step MountainCarContinuous::step(const Action& action) {
  check_action(action_space_, action, "MountainCarContinuous-v0");
  const double a = action[0];
  const double force = std::clamp(a, -1.0, 1.0);

  double velocity = velocity_ + force * kPower - 0.0025 * std::cos(3.0 * position_);
  velocity = std::clamp(velocity, -kMaxSpeed, kMaxSpeed);
  double position = std::clamp(position_ + velocity, kMinPosition, kMaxPosition);
  if (position == kMinPosition && velocity < 0.0) velocity = 0.0;  // inelastic left wall

  Step result;
  result.terminated = position >= kGoalPosition && velocity >= params_.goal_velocity;
  result.reward = (result.terminated ? 100.0 : 0.0) - 0.1 * a * a;

  position_ = static_cast<float>(position);
  velocity_ = static_cast<float>(velocity);
  result.observation =
      Eigen::Vector2f(static_cast<float>(position_), static_cast<float>(velocity_));
  return result;
}

void MountainCarContinuous::set_state(double position, double velocity) {
  require(std::isfinite(position) && std::isfinite(velocity), "state must be finite",
          "MountainCarContinuous::set_state");
  position_ = position;
  velocity_ = velocity;
}

void MountainCarContinuous::save_state(SnapshotWriter& out) const {
  out.section("MountainCarContinuous");
  out.put(rng_);
  out.put(static_cast<double>(position_));
  out.put(static_cast<double>(velocity_));
}

void MountainCarContinuous::load_state(SnapshotReader& in) {
  in.section("MountainCarContinuous");
  Rng rng = rng_;
  in.get(rng);
  const auto position = static_cast<double>(in.get_double());
  const auto velocity = static_cast<double>(in.get_double());
  rng_ = rng;
  position_ = position;
  velocity_ = velocity;
}

EnvDescription MountainCarContinuous::description() {
  return {
      .observation = {{"car position x, in [−1.2, 0.6]", "m"},
                      {"car velocity, in [−0.07, 0.07]", "m/step"}},
      .action = {{"force, in [−1, 1] (scaled by 0.0015)", "1"}},
      .reward =
          "100 on reaching the goal, minus 0.1 a² every step (Gymnasium's "
          "MountainCarContinuous-v0)",
      .episode_end =
          "terminated when x ≥ 0.45 m with velocity ≥ goal_velocity; truncated by the "
          "time limit",
      .parameters = {{"goal_velocity", "m/step",
                      "least velocity at the goal that ends the episode"}},
  };
}

}  // namespace tendril::envs
