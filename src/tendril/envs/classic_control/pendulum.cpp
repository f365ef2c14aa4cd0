#include "tendril/envs/classic_control/pendulum.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::envs {

std::unique_ptr<Env> Pendulum::create(const Config& params) {
  Params values;
  values.gravity = params.get_or<double>("g", values.gravity);
  return std::make_unique<Pendulum>(values);
}

Pendulum::Pendulum(Params params)
    : params_(params),
      observation_space_(Space::box(Eigen::Vector3f(-1.0f, -1.0f, -kMaxSpeed),
                                    Eigen::Vector3f(1.0f, 1.0f, kMaxSpeed))),
      action_space_(Space::box(1, -kMaxTorque, kMaxTorque)) {}

double Pendulum::normalize_angle(double x) {
  // Python's floored modulo: ((x + π) mod 2π) − π, the remainder taking the divisor's sign.
  constexpr double two_pi = 2.0 * std::numbers::pi;
  double wrapped = std::fmod(x + std::numbers::pi, two_pi);
  if (wrapped < 0.0) wrapped += two_pi;
  return wrapped - std::numbers::pi;
}

Observation Pendulum::reset(std::optional<uint64_t> seed) {
  if (seed) rng_ = Rng(*seed);
  theta_ = rng_.uniform(-std::numbers::pi, std::numbers::pi);
  theta_dot_ = rng_.uniform(-1.0, 1.0);
  return observe();
}

Step Pendulum::step(const Action& action) {
  check_action(action_space_, action, "Pendulum-v1");
  const double g = params_.gravity;
  const double u = std::clamp(static_cast<double>(action[0]), -kMaxTorque, kMaxTorque);
  const double angle = normalize_angle(theta_);
  const double cost = angle * angle + 0.1 * theta_dot_ * theta_dot_ + 0.001 * u * u;

  const double angular_acceleration =
      3.0 * g / (2.0 * kLength) * std::sin(theta_) + 3.0 / (kMass * kLength * kLength) * u;
  theta_dot_ = std::clamp(theta_dot_ + angular_acceleration * kDt, -kMaxSpeed, kMaxSpeed);
  theta_ = theta_ + theta_dot_ * kDt;  // semi-implicit Euler: the new velocity moves the angle

  Step result;
  result.observation = observe();
  result.reward = -cost;
  return result;
}

void Pendulum::set_state(double theta, double theta_dot) {
  require(std::isfinite(theta) && std::isfinite(theta_dot), "state must be finite",
          "Pendulum::set_state");
  theta_ = theta;
  theta_dot_ = theta_dot;
}

Observation Pendulum::observe() const {
  return Eigen::Vector3f(static_cast<float>(std::cos(theta_)), static_cast<float>(std::sin(theta_)),
                         static_cast<float>(theta_dot_));
}

void Pendulum::save_state(SnapshotWriter& out) const {
  out.section("Pendulum");
  out.put(rng_);
  out.put(static_cast<double>(theta_));
  out.put(static_cast<double>(theta_dot_));
}

void Pendulum::load_state(SnapshotReader& in) {
  in.section("Pendulum");
  Rng rng = rng_;
  in.get(rng);
  const auto theta = static_cast<double>(in.get_double());
  const auto theta_dot = static_cast<double>(in.get_double());
  rng_ = rng;
  theta_ = theta;
  theta_dot_ = theta_dot;
}

EnvDescription Pendulum::description() {
  return {
      .observation = {{"cos θ (θ = 0 upright)", "1"},
                      {"sin θ", "1"},
                      {"angular velocity θ̇", "rad/s"}},
      .action = {{"torque at the pivot", "N·m"}},
      .reward =
          "−(θ² + 0.1 θ̇² + 0.001 u²), θ normalised to [−π, π), u the clipped torque "
          "(Gymnasium's Pendulum-v1)",
      .episode_end = "never terminates; truncated by the time limit",
      .parameters = {{"g", "m/s²", "gravitational acceleration"}},
  };
}

}  // namespace tendril::envs
