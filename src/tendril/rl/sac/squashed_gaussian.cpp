#include "tendril/rl/sac/squashed_gaussian.hpp"

#include <cmath>

namespace tendril::rl {

namespace {

constexpr float kLogStdMin = -20.0f;
constexpr float kLogStdMax = 2.0f;
constexpr float kSquashEpsilon = 1e-6f;  // inside log(1 − tanh² u + ε), as SB3's TanhBijector

}  // namespace

void SquashedGaussianSample::evaluate(const Eigen::MatrixXf& head) {
  const Eigen::Index a = noise.rows();
  const float half_log_two_pi = 0.5f * std::log(2.0f * static_cast<float>(M_PI));
  const auto log_std = head.bottomRows(a).array().cwiseMax(kLogStdMin).cwiseMin(kLogStdMax);
  std = log_std.exp().matrix();
  actions = (head.topRows(a).array() + std.array() * noise.array()).tanh().matrix();
  // log N(u; μ, σ) = −ε²/2 − log σ − ½ log 2π, since (u − μ)/σ = ε.
  log_probs = (-0.5f * noise.array().square() - log_std - half_log_two_pi -
               (1.0f - actions.array().square() + kSquashEpsilon).log())
                  .colwise()
                  .sum()
                  .transpose()
                  .matrix();
}

void SquashedGaussianSample::head_gradient(const Eigen::MatrixXf& head,
                                           const Eigen::MatrixXf& action_gradient, float alpha,
                                           Eigen::MatrixXf& gradient) const {
  const Eigen::Index a = noise.rows();
  const auto weight = alpha / static_cast<float>(noise.cols());  // α / batch
  // Through a = tanh u: the outside term's ∂/∂a · (1 − a²); the squash correction
  // −log(1 − a² + ε) adds α/B · 2a(1 − a²)/(1 − a² + ε). ∂u/∂μ = 1, ∂u/∂log σ = σ ε; the
  // Gaussian term −ε²/2 − log σ adds −α/B to log σ directly (ε is fixed).
  const Eigen::ArrayXXf one_minus_square = 1.0f - actions.array().square();
  const Eigen::ArrayXXf u_gradient =
      action_gradient.array() * one_minus_square +
      weight * 2.0f * actions.array() * one_minus_square / (one_minus_square + kSquashEpsilon);
  const auto raw_log_std = head.bottomRows(a).array();
  const auto inside_clamp = raw_log_std >= kLogStdMin && raw_log_std <= kLogStdMax;
  gradient.resize(2 * a, noise.cols());
  gradient.topRows(a) = u_gradient.matrix();
  gradient.bottomRows(a) =
      inside_clamp.select(u_gradient * std.array() * noise.array() - weight, 0.0f).matrix();
}

}  // namespace tendril::rl
