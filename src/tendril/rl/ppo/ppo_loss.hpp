#pragma once

#include <Eigen/Core>
#include <optional>

#include "tendril/rl/rollout_minibatches.hpp"

namespace tendril::rl {

// The coefficients of PPO's loss at one point of training (see PpoConfig).
struct PpoLossSettings {
  double clip_range = 0.2;              // ε
  std::optional<double> clip_range_vf;  // value clipping around the old values; off if unset
  double ent_coef = 0.0;                // c₂
  double vf_coef = 0.5;                 // c₁
};

// One minibatch's loss, its parts and diagnostics, as logged.
struct PpoLossTerms {
  double policy_loss = 0.0;   // −Ê[L^CLIP]
  double value_loss = 0.0;    // Ê[(V − V^targ)²]
  double entropy_loss = 0.0;  // −Ê[H]
  double loss = 0.0;          // policy_loss + c₂ entropy_loss + c₁ value_loss
  double approx_kl = 0.0;     // Ê[(r − 1) − log r]
  double clip_fraction = 0.0;
};

// ∂loss/∂(log π(a_t|s_t)), ∂loss/∂H_t and ∂loss/∂V(s_t) per sample (1 × batch each): what
// nn::DenseActorCritic::backward propagates to the parameters.
struct PpoSampleGradients {
  Eigen::RowVectorXf log_prob, entropy, value;
};

// PPO's loss (Schulman et al. 2017, eq. 9, as Stable-Baselines3 minimises it) on one minibatch
// whose current log π, entropy and value are given per sample, and its gradient with respect
// to them into `gradients`. The derivatives follow LibTorch's conventions at kinks, so they
// equal autograd's: min(x, y) sends half the gradient to each argument on a tie, clamp passes
// it on its closed interval.
PpoLossTerms ppo_loss(const RolloutMinibatch& batch,
                      const Eigen::Ref<const Eigen::RowVectorXf>& log_prob,
                      const Eigen::Ref<const Eigen::RowVectorXf>& entropy,
                      const Eigen::Ref<const Eigen::RowVectorXf>& value,
                      const PpoLossSettings& settings, PpoSampleGradients& gradients);

}  // namespace tendril::rl
