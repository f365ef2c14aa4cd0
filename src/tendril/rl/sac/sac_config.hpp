#pragma once

#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/nn/feature_heads.hpp"
#include "tendril/rl/off_policy_config.hpp"

namespace tendril::rl {

// SAC hyper-parameters. Defaults are Stable-Baselines3's SAC (stable_baselines3/sac/sac.py):
// buffer 1e6, 100 random warm-up steps, batch 256, τ 0.005, γ 0.99, one gradient step per env
// step, Adam lr 3e-4, 256×256 ReLU networks, entropy coefficient tuned automatically from 1
// towards the target entropy −dim(A), targets updated every step.
struct SacConfig {
  OffPolicyConfig common;
  bool auto_entropy = true;              // learn α (Haarnoja et al. 2018b, eq. 18)
  double ent_coef = 1.0;                 // the fixed α, or the initial α when learned
  std::optional<double> target_entropy;  // unset: −dim(A)
  int64_t target_update_interval = 1;    // gradient steps between target updates
  // Critic updates per actor and α update (TD3's delayed policy update; the SAC of seed 001,
  // Table A.1, "policy network update frequency" 2): the actor and α step at the gradient steps
  // whose count is a multiple of it. 1: every step (SB3).
  int64_t policy_delay = 1;
  // At each delayed step, make up for the skipped ones: policy_delay actor and α steps, each on
  // a new policy sample of the same batch (CleanRL's SAC, which seed 001's code adapts).
  bool compensate_policy_delay = false;
  // Clip the gradients of the critics (one norm over both, one optimizer as in SB3), of the
  // actor (its log σ included under gSDE) and of log α to this L2 norm before their Adam steps
  // (torch.nn.utils.clip_grad_norm_; seed 001, Table A.1, "max gradient size" 1.0); unset: none
  // (SB3).
  std::optional<double> max_grad_norm;
  // Clip the critics' regression targets to ±q_clip (a guard against divergence in long runs
  // with large rewards); unset: no clipping.
  std::optional<double> q_clip;
  // gSDE exploration (Raffin et al. 2022) instead of independent Gaussian noise; its log σ
  // starts at `log_std_init` (SB3's −3 for SAC); `sde_sample_freq` env steps between new
  // exploration matrices while collecting (−1: only when a collection starts, SB3's default).
  bool use_sde = false;
  int64_t sde_sample_freq = -1;
  double log_std_init = -3.0;
  // A policy head feeding actor and critics (seed 001, thesis §5.1.2, Fig. 5.2; `head:` keys in
  // nn::FeatureHeadSpec); none: the networks read the observation ("MLP No Head").
  std::optional<nn::FeatureHeadSpec> head;

  static SacConfig sb3();
  // stable-baselines v2's SAC defaults (the Elastica paper's runs): buffer 50 000, batch 64,
  // 64×64 ReLU networks, otherwise as SB3.
  static SacConfig sb2();
  // `preset: sb3 | sb2` and then, over it, the common off-policy keys and
  //   ent_coef (a number, `auto`, or `auto_<initial>` as SB3), target_entropy (a number or
  //   `auto`), target_update_interval, policy_delay, compensate_policy_delay, max_grad_norm (a
  //   number or `none`), q_clip (a number or `none`), use_sde, sde_sample_freq, log_std_init,
  //   head (a mapping).
  static SacConfig from_config(const Config& algo);

  void validate() const;
};

}  // namespace tendril::rl
