#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "tendril/core/config.hpp"
#include "tendril/rl/on_policy_config.hpp"
#include "tendril/rl/schedule.hpp"

namespace tendril::rl {

// PPO hyper-parameters. Defaults are Stable-Baselines3's PPO (stable_baselines3/ppo/ppo.py):
// n_steps 2048, batch 64, 10 epochs, γ 0.99, λ 0.95, clip 0.2, no value clipping, entropy
// coefficient 0, value coefficient 0.5, gradient norm 0.5, Adam lr 3e-4 (ε 1e-5, as SB3's
// ActorCriticPolicy), 64×64 tanh trunks for policy and value.
struct PpoConfig {
  OnPolicyConfig common;
  int64_t batch_size = 64;  // minibatch size
  int64_t n_epochs = 10;    // passes over each rollout
  Schedule learning_rate{3e-4, false};
  // A learning rate of the value network's own (seed 002 §IV-A3: critic 0.01 → 0.001 beside
  // the actor's 0.003 → 0.0001). Unset, one Adam over both networks follows `learning_rate`, as
  // SB3; set, the policy block and the value block each have an Adam, the value's following
  // this schedule. Adam acts element by element, so equal schedules give the same update.
  std::optional<Schedule> vf_learning_rate;
  Schedule clip_range{0.2, false};            // ε of the clipped surrogate
  std::optional<double> clip_range_vf;        // value clipping around the old values; off if unset
  double ent_coef = 0.0;                      // c₂, entropy bonus
  double vf_coef = 0.5;                       // c₁, value-loss weight
  std::optional<double> max_grad_norm = 0.5;  // global gradient-norm clip; off if unset
  std::optional<double> target_kl;            // stop the epochs early past 1.5 × this KL
  double adam_epsilon = 1e-5;

  // SB3's defaults (the member initialisers above).
  static PpoConfig sb3();
  // The defaults of stable-baselines v2's PPO1 (the Elastica paper's runs): 256 steps per
  // actor batch, clip 0.2, entropy coefficient 0.01, 4 epochs, Adam step 1e-3 (ε 1e-5), batch
  // 64, γ 0.99, λ 0.95, learning rate and clip range annealed linearly to 0. PPO1 sums the
  // losses without weights (value coefficient 1) and does not clip gradients.
  static PpoConfig ppo1();
  // `preset: sb3 | ppo1` (default sb3) and then any of the keys below over the preset:
  //   n_steps, batch_size, n_epochs, gamma, gae_lambda, learning_rate, learning_rate_schedule,
  //   learning_rate_final, vf_learning_rate (+ _schedule, _final),
  //   clip_range, clip_range_schedule, clip_range_vf, normalize_advantage, ent_coef, vf_coef,
  //   max_grad_norm, target_kl, adam_epsilon, policy{…}
  // clip_range_vf, max_grad_norm and target_kl take `none` to turn them off.
  // Unknown keys raise Error naming the key; out-of-range values raise Error naming the key.
  static PpoConfig from_config(const Config& algo);

  void validate() const;
};

}  // namespace tendril::rl
