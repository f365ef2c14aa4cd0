#pragma once

#include <Eigen/Core>

namespace tendril::rl {

// Generalized state-dependent exploration (gSDE; Raffin et al. 2022, "Smooth Exploration for
// Robotic Reinforcement Learning", section 3) for SAC, as SB3's StateDependentNoiseDistribution
// with a tanh squash: the exploration noise is a linear function of the policy's latent
// features z (the last hidden layer, treated as a constant here: SB3's learn_features = false),
//   u = μ + z W,   W_ij = σ_ij E_ij,  E ~ N(0, 1) held fixed between resamplings,
// so the same state gives the same noise until W is redrawn. σ = exp(log σ) is a learned
// latent × action matrix. The action is a = tanh(u), and u is scored under the Gaussian it is
// drawn from per state: N(μ_j, s_j²), s_j² = Σ_i z_i² σ_ij² + 1e-6. μ is clipped to [−2, 2]
// (SB3's clip_mean for SAC).
struct StateDependentNoiseSample {
  Eigen::MatrixXf standard_normal;  // E, latent × action_size, set by the caller

  Eigen::MatrixXf mean;     // μ (clipped), action_size × batch
  Eigen::MatrixXf noise;    // z W
  Eigen::MatrixXf std;      // s
  Eigen::MatrixXf actions;  // a ∈ (−1, 1)
  Eigen::VectorXf log_probs;

  // `raw_mean`: the actor's output (action_size × batch); `latent`: z (latent × batch);
  // `log_std`: latent × action_size. One W for every column.
  void evaluate(const Eigen::MatrixXf& raw_mean, const Eigen::MatrixXf& latent,
                const Eigen::Ref<const Eigen::MatrixXf>& log_std);

  // For L = mean_b(α log π(a_b|s_b)) + (terms through a whose ∂/∂a is `action_gradient`):
  // ∂L/∂raw_mean into `mean_gradient` and ∂L/∂log σ added to `log_std_gradient`.
  void gradients(const Eigen::MatrixXf& raw_mean, const Eigen::MatrixXf& latent,
                 const Eigen::Ref<const Eigen::MatrixXf>& log_std,
                 const Eigen::MatrixXf& action_gradient, float alpha,
                 Eigen::MatrixXf& mean_gradient,
                 Eigen::Ref<Eigen::MatrixXf> log_std_gradient) const;
};

}  // namespace tendril::rl
