#include "tendril/rl/sac/state_dependent_noise.hpp"

#include <cmath>

namespace tendril::rl {

namespace {

constexpr float kClipMean = 2.0f;
constexpr float kVarianceEpsilon = 1e-6f;  // SB3's StateDependentNoiseDistribution.epsilon
constexpr float kSquashEpsilon = 1e-6f;    // inside log(1 − tanh² u + ε)

}  // namespace

void StateDependentNoiseSample::evaluate(const Eigen::MatrixXf& raw_mean,
                                         const Eigen::MatrixXf& latent,
                                         const Eigen::Ref<const Eigen::MatrixXf>& log_std) {
  const float half_log_two_pi = 0.5f * std::log(2.0f * static_cast<float>(M_PI));
  const Eigen::MatrixXf sigma = log_std.array().exp().matrix();
  const Eigen::MatrixXf weights = (sigma.array() * standard_normal.array()).matrix();
  mean = raw_mean.cwiseMax(-kClipMean).cwiseMin(kClipMean);
  noise.noalias() = weights.transpose() * latent;
  std.noalias() = sigma.array().square().matrix().transpose() * latent.array().square().matrix();
  std = (std.array() + kVarianceEpsilon).sqrt().matrix();
  actions = (mean + noise).array().tanh().matrix();
  // log N(u; μ, s) − log(1 − tanh² u + ε), summed over action components.
  log_probs = (-0.5f * (noise.array() / std.array()).square() - std.array().log() -
               half_log_two_pi - (1.0f - actions.array().square() + kSquashEpsilon).log())
                  .colwise()
                  .sum()
                  .transpose()
                  .matrix();
}

void StateDependentNoiseSample::gradients(const Eigen::MatrixXf& raw_mean,
                                          const Eigen::MatrixXf& latent,
                                          const Eigen::Ref<const Eigen::MatrixXf>& log_std,
                                          const Eigen::MatrixXf& action_gradient, float alpha,
                                          Eigen::MatrixXf& mean_gradient,
                                          Eigen::Ref<Eigen::MatrixXf> log_std_gradient) const {
  const float weight = alpha / static_cast<float>(noise.cols());  // α / batch
  const Eigen::ArrayXXf one_minus_square = 1.0f - actions.array().square();
  const Eigen::ArrayXXf variance = std.array().square();
  // ∂L/∂u: through a = tanh u (the outside term and the squash correction) and through the
  // Gaussian's −(u − μ)²/(2 s²).
  const Eigen::ArrayXXf through_squash =
      action_gradient.array() * one_minus_square +
      weight * 2.0f * actions.array() * one_minus_square / (one_minus_square + kSquashEpsilon);
  const Eigen::MatrixXf u_gradient = (through_squash - weight * noise.array() / variance).matrix();
  // μ enters u and (u − μ): the Gaussian term's two contributions cancel.
  mean_gradient = through_squash.matrix();
  mean_gradient =
      (raw_mean.array().abs() <= kClipMean).select(mean_gradient.array(), 0.0f).matrix();
  // log σ_ij enters u through W_ij = σ_ij E_ij (∂W/∂log σ = W) and s through
  // ∂s/∂log σ_ij = z_i² σ_ij² / s; ∂(log N)/∂s = (u − μ)²/s³ − 1/s.
  const Eigen::ArrayXXf sigma_square = (2.0f * log_std.array()).exp();
  const Eigen::ArrayXXf weights = log_std.array().exp() * standard_normal.array();
  const Eigen::MatrixXf s_gradient =
      (weight * (noise.array().square() / (variance * variance) - 1.0f / variance)).matrix();
  log_std_gradient.array() +=
      (latent * u_gradient.transpose()).array() * weights +
      (latent.array().square().matrix() * s_gradient.transpose()).array() * sigma_square;
}

}  // namespace tendril::rl
