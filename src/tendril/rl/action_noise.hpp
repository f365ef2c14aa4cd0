#pragma once

#include <Eigen/Core>
#include <string>

#include "tendril/core/config.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::rl {

// Exploration noise added to a deterministic policy's actions (in [−1, 1] units), one
// independent process per env and action component (SB3's VectorizedActionNoise):
//   normal:              n = σ N(0, 1)
//   ornstein_uhlenbeck:  n ← n + θ (0 − n) dt + σ √dt N(0, 1)   (Uhlenbeck & Ornstein 1930;
//                        the process of Lillicrap et al. 2016), back to 0 when an episode ends.
struct ActionNoiseConfig {
  enum class Kind { kNone, kNormal, kOrnsteinUhlenbeck };
  Kind kind = Kind::kNone;
  double sigma = 0.1;
  double theta = 0.15;  // SB3's OrnsteinUhlenbeckActionNoise defaults
  double dt = 1e-2;

  // noise_type (none | normal | ornstein_uhlenbeck), noise_std, noise_theta, noise_dt: the RL
  // Zoo's names.
  void read(const Config& algo);
  void validate(const std::string& where) const;
};

class ActionNoise {
 public:
  ActionNoise() = default;
  ActionNoise(const ActionNoiseConfig& config, int num_envs, int action_size);

  bool active() const { return config_.kind != ActionNoiseConfig::Kind::kNone; }
  // Adds the next noise sample of each env to the columns of `actions`.
  void add(Eigen::MatrixXf& actions, Rng& rng);
  void reset(int env_index) { state_.col(env_index).setZero(); }

  const Eigen::MatrixXf& state() const { return state_; }  // the OU processes' current values
  void set_state(const Eigen::MatrixXf& state) { state_ = state; }

 private:
  ActionNoiseConfig config_;
  Eigen::MatrixXf state_;  // action_size × num_envs
};

}  // namespace tendril::rl
