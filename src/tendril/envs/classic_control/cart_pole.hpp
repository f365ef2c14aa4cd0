#pragma once

#include <Eigen/Core>
#include <memory>
#include <numbers>
#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/env_description.hpp"

namespace tendril::envs {

// Gymnasium's CartPole-v1 (gymnasium/envs/classic_control/cartpole.py), the cart-pole of Barto,
// Sutton & Anderson (1983) with the equations of motion of Florian (2007), "Correct equations for
// the dynamics of the cart-pole system", eqs. 23–24 with friction dropped:
//
//   temp  = (F + m_p l θdot² sin θ) / (m_c + m_p)
//   θddot = (g sin θ − cos θ · temp) / (l (4/3 − m_p cos² θ / (m_c + m_p)))
//   xddot = temp − m_p l θddot cos θ / (m_c + m_p)
//
// integrated by explicit Euler with τ = 0.02 s (positions use the old velocities). l is half the
// pole's length. Action 1 pushes right with F = +10 N, action 0 left with −10 N. The episode
// terminates once |x| > 2.4 m or |θ| > 12°; reward 1 per step, including the terminating one.
// State order [x (m), xdot (m/s), θ (rad), θdot (rad/s)].
class CartPole : public Env {
 public:
  static constexpr double kGravity = 9.8;                                           // m/s²
  static constexpr double kCartMass = 1.0;                                          // kg
  static constexpr double kPoleMass = 0.1;                                          // kg
  static constexpr double kHalfLength = 0.5;                                        // m
  static constexpr double kForce = 10.0;                                            // N
  static constexpr double kTau = 0.02;                                              // s per step
  static constexpr double kXThreshold = 2.4;                                        // m
  static constexpr double kThetaThreshold = 12.0 * 2.0 * std::numbers::pi / 360.0;  // rad

  // Registry factory; CartPole-v1 has no parameters.
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();

  CartPole();

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  // Every state component ~ U(−0.05, 0.05).
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  // Stepping on after termination gives reward 0, as in Gymnasium (call reset instead).
  Step step(const Action& action) override;
  // The state, the random stream and the episode flags: exact snapshots.
  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  void set_state(const Eigen::Vector4d& state);
  const Eigen::Vector4d& state() const { return state_; }

 private:
  Space observation_space_;
  Space action_space_;
  Rng rng_;
  Eigen::Vector4d state_ = Eigen::Vector4d::Zero();
  bool terminated_ = false;
};

}  // namespace tendril::envs
