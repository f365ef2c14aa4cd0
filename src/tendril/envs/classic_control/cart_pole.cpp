#include "tendril/envs/classic_control/cart_pole.hpp"

#include <cmath>
#include <limits>

#include "tendril/core/error.hpp"

namespace tendril::envs {

namespace {

Space observation_bounds() {
  // Gymnasium bounds x and θ at twice their failure thresholds, so that the observation of a
  // failing state still lies inside the space, and the velocities at the largest float.
  const float big = std::numeric_limits<float>::max();
  const Eigen::Vector4f high(static_cast<float>(2.0 * CartPole::kXThreshold), big,
                             static_cast<float>(2.0 * CartPole::kThetaThreshold), big);
  return Space::box(-high, high);
}

}  // namespace

std::unique_ptr<Env> CartPole::create(const Config&) { return std::make_unique<CartPole>(); }

CartPole::CartPole()
    : observation_space_(observation_bounds()), action_space_(Space::discrete(2)) {}

Observation CartPole::reset(std::optional<uint64_t> seed) {
  if (seed) rng_ = Rng(*seed);
  for (int i = 0; i < 4; ++i) state_[i] = rng_.uniform(-0.05, 0.05);
  terminated_ = false;
  return state_.cast<float>();
}

Step CartPole::step(const Action& action) {
  check_action(action_space_, action, "CartPole-v1");
  const double force = action[0] == 1.0f ? kForce : -kForce;
  const double x = state_[0], x_dot = state_[1], theta = state_[2], theta_dot = state_[3];
  const double cos_theta = std::cos(theta);
  const double sin_theta = std::sin(theta);
  const double total_mass = kCartMass + kPoleMass;
  const double pole_mass_length = kPoleMass * kHalfLength;

  const double temp = (force + pole_mass_length * theta_dot * theta_dot * sin_theta) / total_mass;
  const double theta_acc =
      (kGravity * sin_theta - cos_theta * temp) /
      (kHalfLength * (4.0 / 3.0 - kPoleMass * cos_theta * cos_theta / total_mass));
  const double x_acc = temp - pole_mass_length * theta_acc * cos_theta / total_mass;

  state_ = Eigen::Vector4d(x + kTau * x_dot, x_dot + kTau * x_acc, theta + kTau * theta_dot,
                           theta_dot + kTau * theta_acc);

  const bool failed = state_[0] < -kXThreshold || state_[0] > kXThreshold ||
                      state_[2] < -kThetaThreshold || state_[2] > kThetaThreshold;
  Step result;
  result.observation = state_.cast<float>();
  result.terminated = failed;
  // Gymnasium rewards the step on which the pole falls, and gives 0 for failing steps taken
  // after it (its `steps_beyond_terminated`).
  result.reward = failed && terminated_ ? 0.0 : 1.0;
  terminated_ = terminated_ || failed;
  return result;
}

void CartPole::set_state(const Eigen::Vector4d& state) {
  require(state.allFinite(), "state must be finite", "CartPole::set_state");
  state_ = state;
  terminated_ = false;
}

void CartPole::save_state(SnapshotWriter& out) const {
  out.section("CartPole");
  out.put(rng_);
  out.put_matrix(state_);
  out.put(terminated_);
}

void CartPole::load_state(SnapshotReader& in) {
  in.section("CartPole");
  Rng rng = rng_;
  in.get(rng);
  Eigen::Vector4d state = state_;
  in.get_matrix(state);
  const bool terminated = in.get_bool();
  rng_ = rng;
  state_ = state;
  terminated_ = terminated;
}

EnvDescription CartPole::description() {
  return {
      .observation = {{"cart position x", "m"},
                      {"cart velocity ẋ", "m/s"},
                      {"pole angle θ from upright", "rad"},
                      {"pole angular velocity θ̇", "rad/s"}},
      .action = {{"push direction: 0 left, 1 right (±10 N)", "1"}},
      .reward =
          "+1 every step, including the one on which the pole falls (Gymnasium's "
          "CartPole-v1)",
      .episode_end = "terminated when |x| > 2.4 m or |θ| > 12°; truncated by the time limit",
      .parameters = {},
  };
}

}  // namespace tendril::envs
