#pragma once

#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/rl/action_noise.hpp"
#include "tendril/rl/off_policy_config.hpp"

namespace tendril::rl {

// TD3, or DDPG = TD3 with one critic, no target smoothing and no policy delay (SB3's DDPG).
enum class Td3Variant { kTd3, kDdpg };

// TD3 hyper-parameters, and DDPG's as TD3's special case (one critic, no target smoothing,
// policy updated every step). Defaults are Stable-Baselines3's TD3 (stable_baselines3/td3/td3.py):
// buffer 1e6, 100 warm-up steps, batch 256, τ 0.005, γ 0.99, one gradient step per env step,
// Adam lr 1e-3, 400×300 ReLU networks, no action noise, policy delay 2, target noise 0.2
// clipped at 0.5.
struct Td3Config {
  OffPolicyConfig common;
  int n_critics = 2;
  int64_t policy_delay = 2;          // critic steps per actor (and target) step
  double target_policy_noise = 0.2;  // σ of the target-policy smoothing; 0: none
  double target_noise_clip = 0.5;
  std::optional<double> critic_learning_rate;  // unset: the learning rate (schedule) of the actor
  ActionNoiseConfig action_noise;

  static Td3Config sb3(Td3Variant variant);
  // stable-baselines v2's defaults (the Elastica paper's runs). TD3: buffer 50 000, batch 128,
  // 100 steps between updates of 100 gradient steps, lr 3e-4, 64×64 networks. DDPG: buffer
  // 50 000, batch 128, 100-step rollouts followed by 50 gradient steps, actor lr 1e-4, critic
  // lr 1e-3, τ 0.001, 64×64 networks.
  static Td3Config sb2(Td3Variant variant);
  // `preset: sb3 | sb2` and then, over it, the common off-policy keys and policy_delay,
  // target_policy_noise, target_noise_clip, n_critics (TD3 only), critic_learning_rate,
  // noise_type, noise_std, noise_theta, noise_dt.
  static Td3Config from_config(const Config& algo, Td3Variant variant);

  void validate(const std::string& where) const;
};

}  // namespace tendril::rl
