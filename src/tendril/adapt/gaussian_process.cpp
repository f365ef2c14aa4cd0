#include "tendril/adapt/gaussian_process.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <string>

#include "tendril/adapt/cholesky.hpp"
#include "tendril/adapt/number_text.hpp"
#include "tendril/core/error.hpp"

namespace tendril::adapt {

GaussianProcess::GaussianProcess(int input_dim, GpOptions options)
    : GaussianProcess(input_dim, options,
                      GpHyperparameters{Eigen::VectorXd::Ones(std::max(input_dim, 1)), 1.0, 1e-2}) {
}

GaussianProcess::GaussianProcess(int input_dim, GpOptions options,
                                 GpHyperparameters hyperparameters)
    : input_dim_(input_dim),
      options_(options),
      kernel_(options.kernel, Eigen::VectorXd::Ones(std::max(input_dim, 1)), 1.0) {
  require(input_dim > 0, "input_dim must be positive", "GaussianProcess");
  require(options.window >= 0, "window must be non-negative (0: no window)", "GaussianProcess");
  require(options.restarts >= 0 && options.max_evaluations > 0,
          "restarts must be non-negative and max_evaluations positive", "GaussianProcess");
  require(0 < options.min_length_scale && options.min_length_scale <= options.max_length_scale &&
              0 < options.min_signal_variance &&
              options.min_signal_variance <= options.max_signal_variance &&
              0 < options.min_noise_variance &&
              options.min_noise_variance <= options.max_noise_variance,
          "hyper-parameter bounds must be positive with min <= max", "GaussianProcess");
  set_hyperparameters(hyperparameters);
}

void GaussianProcess::check_input(const Eigen::Ref<const Eigen::VectorXd>& input,
                                  const char* where) const {
  if (input.size() != input_dim_) {
    throw Error("input has " + std::to_string(input.size()) + " values, expected " +
                    std::to_string(input_dim_),
                where);
  }
  if (!input.allFinite()) throw Error("input is not finite", where);
}

void GaussianProcess::reserve(int points) {
  const auto capacity = static_cast<int>(inputs_.rows());
  if (capacity >= points) return;
  // Growth by half again: the factor is capacity² doubles, so doubling would quadruple memory.
  int grown = std::max({points, capacity + capacity / 2, 16});
  if (options_.window > 0) grown = std::min(grown, std::max(points, options_.window));
  inputs_.conservativeResize(grown, input_dim_);
  targets_.conservativeResize(grown);
  factor_.conservativeResize(grown, grown);
}

void GaussianProcess::fit(const Eigen::Ref<const Eigen::MatrixXd>& inputs,
                          const Eigen::Ref<const Eigen::VectorXd>& targets) {
  const std::string where = "GaussianProcess::fit";
  if (inputs.rows() != targets.size()) {
    throw Error(std::to_string(inputs.rows()) + " inputs but " + std::to_string(targets.size()) +
                    " targets",
                where);
  }
  if (inputs.cols() != input_dim_) {
    throw Error("inputs have " + std::to_string(inputs.cols()) + " columns, expected " +
                    std::to_string(input_dim_),
                where);
  }
  for (Eigen::Index i = 0; i < inputs.rows(); ++i) {
    if (!inputs.row(i).allFinite()) {
      throw Error("input " + std::to_string(i) + " is not finite", where);
    }
    if (!std::isfinite(targets[i])) {
      throw Error("target " + std::to_string(i) + " is " + number_text(targets[i]), where);
    }
  }
  const auto total = static_cast<int>(inputs.rows());
  const int first = options_.window > 0 ? std::max(0, total - options_.window) : 0;
  size_ = total - first;
  reserve(size_);
  inputs_.topRows(size_) = inputs.bottomRows(size_);
  targets_.head(size_) = targets.tail(size_);
  try {
    refactor();
  } catch (const Error&) {
    clear();
    throw;
  }
}

void GaussianProcess::add(const Eigen::Ref<const Eigen::VectorXd>& input, double target) {
  check_input(input, "GaussianProcess::add");
  if (!std::isfinite(target)) {
    throw Error("target is " + number_text(target), "GaussianProcess::add");
  }
  if (options_.window > 0 && size_ == options_.window) drop_oldest();
  reserve(size_ + 1);
  const int n = size_;
  inputs_.row(n) = input.transpose();
  targets_[n] = target;
  size_ = n + 1;
  if (n == 0) {
    refactor();
    return;
  }
  // Bordered Cholesky: [K k; kᵀ κ] = [L 0; lᵀ d][Lᵀ l; 0 d] with L l = k, d² = κ − lᵀl.
  Eigen::VectorXd border;
  kernel_.covariance(inputs_.topRows(n), input, border);
  const auto factor = factor_.topLeftCorner(n, n);
  factor.triangularView<Eigen::Lower>().solveInPlace(border);
  const double pivot = hyperparameters_.signal_variance + hyperparameters_.noise_variance +
                       jitter_ - border.squaredNorm();
  if (!(pivot > 0.0) || !std::isfinite(pivot)) {
    refactor();  // the new point is (numerically) a duplicate: refactor with more jitter
    return;
  }
  factor_.row(n).head(n) = border.transpose();
  factor_(n, n) = std::sqrt(pivot);
  update_weights();
}

void GaussianProcess::remove_oldest() {
  require(size_ > 0, "no point to remove", "GaussianProcess::remove_oldest");
  drop_oldest();
  update_weights();
}

void GaussianProcess::drop_oldest() {
  const int m = size_ - 1;
  if (m > 0) {
    cholesky_remove_first(factor_, size_);
    for (int i = 0; i < m; ++i) {
      inputs_.row(i) = inputs_.row(i + 1);
      targets_[i] = targets_[i + 1];
    }
  }
  size_ = m;
}

void GaussianProcess::clear() {
  size_ = 0;
  jitter_ = 0.0;
  update_weights();
}

void GaussianProcess::set_hyperparameters(const GpHyperparameters& hyperparameters) {
  const std::string where = "GaussianProcess::set_hyperparameters";
  if (hyperparameters.length_scales.size() != input_dim_) {
    throw Error(std::to_string(hyperparameters.length_scales.size()) +
                    " length scales for an input of dimension " + std::to_string(input_dim_),
                where);
  }
  if (!(hyperparameters.noise_variance >= 0.0) || !std::isfinite(hyperparameters.noise_variance)) {
    throw Error("noise variance is " + number_text(hyperparameters.noise_variance) +
                    " (must be non-negative and finite)",
                where);
  }
  const ArdKernel previous_kernel = kernel_;
  const GpHyperparameters previous = hyperparameters_;
  kernel_ =
      ArdKernel(options_.kernel, hyperparameters.length_scales, hyperparameters.signal_variance);
  hyperparameters_ = hyperparameters;
  try {
    refactor();
  } catch (const Error&) {
    kernel_ = previous_kernel;  // the data keep the hyper-parameters they factored with
    hyperparameters_ = previous;
    refactor();
    throw;
  }
}

void GaussianProcess::refactor() {
  if (size_ == 0) {
    jitter_ = 0.0;
    update_weights();
    return;
  }
  Eigen::MatrixXd kernel_matrix;
  kernel_.covariance(inputs(), inputs(), kernel_matrix);
  double jitter = 0.0;
  if (!factor_with_jitter(kernel_matrix, hyperparameters_.noise_variance,
                          hyperparameters_.signal_variance, factor_.topLeftCorner(size_, size_),
                          jitter)) {
    throw Error("the kernel matrix of " + std::to_string(size_) +
                    " points is not positive definite even with jitter " +
                    number_text(kLastJitter * hyperparameters_.signal_variance) +
                    " (duplicate inputs with a noise variance of " +
                    number_text(hyperparameters_.noise_variance) + "?)",
                "GaussianProcess");
  }
  jitter_ = jitter;
  update_weights();
}

void GaussianProcess::update_weights() {
  const auto y = targets();
  prior_mean_ = options_.mean_of_targets && size_ > 0 ? y.mean() : 0.0;
  weights_ = y.array() - prior_mean_;
  const auto factor = cholesky_factor();
  factor.triangularView<Eigen::Lower>().solveInPlace(weights_);
  factor.triangularView<Eigen::Lower>().transpose().solveInPlace(weights_);
}

void GaussianProcess::predict(const Eigen::Ref<const Eigen::MatrixXd>& inputs,
                              Eigen::VectorXd& mean, Eigen::VectorXd& variance,
                              bool with_noise) const {
  if (inputs.cols() != input_dim_) {
    throw Error("inputs have " + std::to_string(inputs.cols()) + " columns, expected " +
                    std::to_string(input_dim_),
                "GaussianProcess::predict");
  }
  if (!inputs.allFinite()) throw Error("inputs are not finite", "GaussianProcess::predict");
  const double noise = with_noise ? hyperparameters_.noise_variance : 0.0;
  if (size_ == 0) {
    mean.setConstant(inputs.rows(), 0.0);
    variance.setConstant(inputs.rows(), hyperparameters_.signal_variance + noise);
    return;
  }
  // R&W Alg. 2.1: mean = k*ᵀα + m, variance = k** − vᵀv with L v = k*.
  Eigen::MatrixXd cross;
  kernel_.covariance(this->inputs(), inputs, cross);
  mean = cross.transpose() * weights_;
  mean.array() += prior_mean_;
  cholesky_factor().triangularView<Eigen::Lower>().solveInPlace(cross);
  variance = (hyperparameters_.signal_variance - cross.colwise().squaredNorm().array())
                 .max(0.0)
                 .matrix()
                 .transpose();
  variance.array() += noise;
}

void GaussianProcess::predict(const Eigen::Ref<const Eigen::VectorXd>& input, double& mean,
                              double& variance, Eigen::VectorXd& mean_gradient,
                              Eigen::VectorXd& variance_gradient) const {
  check_input(input, "GaussianProcess::predict");
  if (size_ == 0) {
    mean = 0.0;
    variance = hyperparameters_.signal_variance;
    mean_gradient.setZero(input_dim_);
    variance_gradient.setZero(input_dim_);
    return;
  }
  Eigen::VectorXd cross;
  Eigen::MatrixXd cross_gradient;  // ∂k(x, x_i)/∂x, input_dim × n
  kernel_.covariance(inputs(), input, cross);
  kernel_.input_gradient(inputs(), input, cross_gradient);
  mean = cross.dot(weights_) + prior_mean_;
  mean_gradient = cross_gradient * weights_;
  const auto factor = cholesky_factor().triangularView<Eigen::Lower>();
  factor.solveInPlace(cross);  // v = L⁻¹k
  variance = hyperparameters_.signal_variance - cross.squaredNorm();
  if (variance <= 0.0) {
    variance = 0.0;
    variance_gradient.setZero(input_dim_);
    return;
  }
  factor.transpose().solveInPlace(cross);  // K⁻¹k
  variance_gradient = -2.0 * cross_gradient * cross;
}

}  // namespace tendril::adapt
