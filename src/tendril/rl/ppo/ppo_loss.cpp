#include "tendril/rl/ppo/ppo_loss.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace tendril::rl {

PpoLossTerms ppo_loss(const RolloutMinibatch& batch,
                      const Eigen::Ref<const Eigen::RowVectorXf>& log_prob,
                      const Eigen::Ref<const Eigen::RowVectorXf>& entropy,
                      const Eigen::Ref<const Eigen::RowVectorXf>& value,
                      const PpoLossSettings& settings, PpoSampleGradients& gradients) {
  const int64_t size = log_prob.size();
  const auto n = static_cast<double>(size);
  gradients.log_prob.resize(size);
  gradients.entropy.resize(size);
  gradients.value.resize(size);
  // Clip bounds in float, as LibTorch compares a float tensor with them.
  const auto lower = static_cast<float>(1.0 - settings.clip_range);
  const auto upper = static_cast<float>(1.0 + settings.clip_range);
  const auto policy_scale = static_cast<float>(-1.0 / n);
  const auto value_scale = static_cast<float>(2.0 * settings.vf_coef / n);
  const auto entropy_gradient = static_cast<float>(-settings.ent_coef / n);
  const auto clip_vf = static_cast<float>(settings.clip_range_vf.value_or(0.0));

  double surrogate_sum = 0.0, squared_error_sum = 0.0, entropy_sum = 0.0, kl_sum = 0.0;
  int64_t clipped = 0;
  for (int64_t i = 0; i < size; ++i) {
    // Probability ratio r_t(θ) = π_θ(a_t|s_t) / π_θold(a_t|s_t)                    (eq. 6)
    const float log_ratio = log_prob[i] - batch.old_log_probs[i];
    const float ratio = std::exp(log_ratio);
    // L^CLIP_t = min(r_t Â_t, clip(r_t, 1 − ε, 1 + ε) Â_t)                           (eq. 7)
    const float advantage = batch.advantages[i];
    const float unclipped = ratio * advantage;
    const float clipped_term = std::clamp(ratio, lower, upper) * advantage;
    surrogate_sum += std::min(unclipped, clipped_term);
    // ∂L^CLIP_t/∂r_t: Â_t through whichever argument is the minimum (the clipped one
    // only inside [1 − ε, 1 + ε], where clip passes the gradient); inside, the two are equal.
    const float unclipped_share = unclipped < clipped_term    ? 1.0f
                                  : unclipped == clipped_term ? 0.5f
                                                              : 0.0f;
    const float through_clip = ratio >= lower && ratio <= upper ? 1.0f : 0.0f;
    const float surrogate_gradient =
        advantage * (unclipped_share + (1.0f - unclipped_share) * through_clip);
    // The policy loss is −Ê[L^CLIP]; ∂r/∂log π = r.
    gradients.log_prob[i] = policy_scale * surrogate_gradient * ratio;
    // KL(π_old ‖ π_θ) ≈ (r − 1) − log r, an unbiased low-variance estimator (Schulman,
    // "Approximating KL divergence", 2020), as SB3.
    kl_sum += (ratio - 1.0) - log_ratio;
    clipped += std::abs(ratio - 1.0) > settings.clip_range ? 1 : 0;

    // L^VF_t = (V_θ(s_t) − V_t^targ)², V_θ optionally clipped to V_θold ± ε_vf.
    float predicted = value[i];
    float through_value_clip = 1.0f;
    if (settings.clip_range_vf) {
      const float change = value[i] - batch.old_values[i];
      predicted = batch.old_values[i] + std::clamp(change, -clip_vf, clip_vf);
      through_value_clip = change >= -clip_vf && change <= clip_vf ? 1.0f : 0.0f;
    }
    const float error = predicted - batch.returns[i];
    squared_error_sum += static_cast<double>(error) * error;
    gradients.value[i] = value_scale * error * through_value_clip;

    // The entropy bonus S enters as the loss −Ê[H].
    entropy_sum += entropy[i];
    gradients.entropy[i] = entropy_gradient;
  }

  PpoLossTerms terms;
  terms.policy_loss = -surrogate_sum / n;
  terms.value_loss = squared_error_sum / n;
  terms.entropy_loss = -entropy_sum / n;
  // Minimising −L^{CLIP+VF+S}                                                          (eq. 9)
  terms.loss = terms.policy_loss + settings.ent_coef * terms.entropy_loss +
               settings.vf_coef * terms.value_loss;
  terms.approx_kl = kl_sum / n;
  terms.clip_fraction = static_cast<double>(clipped) / n;
  return terms;
}

}  // namespace tendril::rl
