#include "tendril/adapt/likelihood.hpp"

#include <Eigen/Cholesky>
#include <cmath>
#include <numbers>
#include <utility>

#include "tendril/adapt/cholesky.hpp"

namespace tendril::adapt {

double log_marginal_likelihood(KernelType type, const Eigen::Ref<const Eigen::MatrixXd>& inputs,
                               const Eigen::Ref<const Eigen::MatrixXd>& residuals,
                               const Eigen::VectorXd& log_parameters, Eigen::VectorXd* gradient,
                               LikelihoodWorkspace& workspace) {
  const auto n = inputs.rows();
  const auto d = inputs.cols();
  const auto outputs = static_cast<double>(residuals.cols());
  if (gradient) gradient->setZero(d + 2);
  if (n == 0) return 0.0;
  const Eigen::VectorXd length_scales = log_parameters.head(d).array().exp();
  const double signal_variance = std::exp(log_parameters[d]);
  const double noise_variance = std::exp(log_parameters[d + 1]);
  const ArdKernel kernel(type, length_scales, signal_variance);

  auto& slope = workspace.squared_distances;  // r², then σ_f² g(r)
  auto& kernel_matrix = workspace.kernel_matrix;
  kernel.squared_distances(inputs, inputs, slope);
  if (gradient) {
    kernel.apply_shape_and_slope(slope, kernel_matrix);
  } else {
    kernel_matrix = slope;
    kernel.apply_shape(kernel_matrix);
  }
  workspace.factor.resize(n, n);
  double jitter = 0.0;
  if (!factor_with_jitter(kernel_matrix, noise_variance, signal_variance, workspace.factor,
                          jitter)) {
    if (gradient) gradient->setZero();
    return kUnfactorableLikelihood;
  }
  const auto lower = std::as_const(workspace.factor).triangularView<Eigen::Lower>();
  Eigen::MatrixXd alpha = residuals;
  lower.solveInPlace(alpha);
  lower.transpose().solveInPlace(alpha);
  const double value = -0.5 * (residuals.array() * alpha.array()).sum() -
                       outputs * workspace.factor.diagonal().array().log().sum() -
                       0.5 * outputs * n * std::log(2.0 * std::numbers::pi);
  if (!gradient) return value;

  // W = Σ_k α_kα_kᵀ − m K⁻¹ (lower triangle), then the trace sums column by column below the
  // diagonal, counted twice, plus the diagonal where ∂K has one.
  auto& w = workspace.weights;
  cholesky_inverse(workspace.factor, w);
  auto& g = *gradient;
  double signal_sum = 0.0, noise_sum = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index below = n - k - 1;
    const double diagonal = alpha.row(k).squaredNorm() - outputs * w(k, k);
    signal_sum += diagonal * kernel_matrix(k, k);
    noise_sum += diagonal;
    if (below == 0) continue;
    auto w_column = w.col(k).tail(below);
    w_column = alpha.bottomRows(below) * alpha.row(k).transpose() - outputs * w_column;
    signal_sum += 2.0 * w_column.dot(kernel_matrix.col(k).tail(below));
    // ∂K_ik/∂log ℓ_j = σ_f² g(r_ik) Δ_ikj² / ℓ_j² (ArdKernel::slope).
    const Eigen::ArrayXd m = w_column.array() * slope.col(k).tail(below).array();
    for (Eigen::Index j = 0; j < d; ++j) {
      g[j] += 2.0 * (m * (inputs.col(j).tail(below).array() - inputs(k, j)).square()).sum();
    }
  }
  g.head(d).array() *= 0.5 / length_scales.array().square();
  g[d] = 0.5 * signal_sum;                      // ∂K/∂log σ_f² = K_f
  g[d + 1] = 0.5 * noise_variance * noise_sum;  // ∂K/∂log σ_n² = σ_n² I
  return value;
}

}  // namespace tendril::adapt
