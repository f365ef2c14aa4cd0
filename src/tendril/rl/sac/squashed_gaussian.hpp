#pragma once

#include <Eigen/Core>

namespace tendril::rl {

// SAC's policy distribution (Haarnoja et al. 2018, appendix C): a = tanh(u), u ~ N(μ, σ²) per
// component, with μ and log σ the two halves of the actor's output and log σ clamped to
// [−20, 2] (SB3's LOG_STD_MIN/MAX). Draws are reparameterised, u = μ + σ ε, so the loss
// gradient flows to μ and log σ through fixed ε.
struct SquashedGaussianSample {
  Eigen::MatrixXf noise;    // ε, action_size × batch
  Eigen::MatrixXf std;      // σ
  Eigen::MatrixXf actions;  // a ∈ (−1, 1)
  Eigen::VectorXf log_probs;

  // `head` is the actor's output ((2 · action_size) × batch: μ on top, raw log σ below); `noise`
  // must already hold ε. Fills std, actions and
  //   log π(a|s) = Σ_j [log N(u_j; μ_j, σ_j) − log(1 − tanh²(u_j) + 1e-6)]   (SAC eq. 26)
  void evaluate(const Eigen::MatrixXf& head);

  // ∂L/∂head for L = mean_b(α log π(a_b|s_b)) + (terms through a whose ∂/∂a is
  // `action_gradient`, action_size × batch, e.g. of −mean min_i Q_i(s, a)). Zero on log σ
  // entries outside the clamp, as torch.clamp's gradient.
  void head_gradient(const Eigen::MatrixXf& head, const Eigen::MatrixXf& action_gradient,
                     float alpha, Eigen::MatrixXf& gradient) const;
};

}  // namespace tendril::rl
