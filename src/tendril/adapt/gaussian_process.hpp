#pragma once

#include <Eigen/Core>

#include "tendril/adapt/kernel.hpp"
#include "tendril/adapt/likelihood.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::adapt {

// Hyper-parameters of a GP with an ARD kernel and Gaussian observation noise, in the units of
// the inputs (length scales) and of the targets squared (variances).
struct GpHyperparameters {
  Eigen::VectorXd length_scales;  // ℓ_j, one per input dimension
  double signal_variance = 1.0;   // σ_f²
  double noise_variance = 1e-2;   // σ_n²
};

struct GpOptions {
  KernelType kernel = KernelType::squared_exponential;
  // The prior mean: the mean of the targets held (recomputed as points arrive and leave), or
  // zero.
  bool mean_of_targets = true;
  // Keep only the `window` most recent points (0: keep every point).
  int window = 0;

  // Hyper-parameter search: L-BFGS on the log marginal likelihood from the current
  // hyper-parameters and from `restarts` further starts drawn log-uniformly in the bounds; the
  // best optimum wins. Each run stops after `max_evaluations` evaluations or when f changes by
  // less than `relative_tolerance`·|f| (≈ SciPy's L-BFGS-B default, 2.2e-9). A start near the
  // optimum converges in some 20–40 evaluations; a random one far out can take 250.
  int restarts = 3;
  int max_evaluations = 500;
  double relative_tolerance = 1e-9;
  // Bounds of the search. Length scales in input units; the variances relative to the
  // variance of the targets at the time of the search (so they hold whatever the targets'
  // unit), as if the targets were standardised.
  double min_length_scale = 1e-3, max_length_scale = 1e3;
  double min_signal_variance = 1e-3, max_signal_variance = 1e3;
  double min_noise_variance = 1e-8, max_noise_variance = 1.0;
};

// Gaussian-process regression with one output (Rasmussen & Williams 2006, Alg. 2.1): the data
// (x_i, y_i), the Cholesky factor L of K + σ_n² I and the weights α = (K + σ_n² I)⁻¹(y − m).
//
// Points are rows (inputs: n × input_dim). Adding a point extends L by one row, O(n²); dropping
// the oldest point (the sliding window) turns the factor of the remaining points into a rank-one
// update of L's trailing block, also O(n²) — neither refactors. Both give the factor a refit
// would give, to rounding. (A point whose new pivot vanishes — a duplicate without noise — makes
// the GP refactor, with jitter.) Without hyper-parameters given: ℓ = 1, σ_f² = 1, σ_n² = 0.01.
//
// Jitter: when K + σ_n² I does not factor, 1e-10·σ_f² is added to its diagonal and multiplied by
// ten until it does; beyond 1e-4·σ_f² the kernel is reported as not positive definite. The jitter
// stays in force for later additions until the next refit.
class GaussianProcess {
 public:
  explicit GaussianProcess(int input_dim, GpOptions options = {});
  GaussianProcess(int input_dim, GpOptions options, GpHyperparameters hyperparameters);

  // Replaces the data (keeping the last `window` rows when a window is set) and factors. Bad
  // data raise Error and leave the GP as it was; a kernel matrix that does not factor even with
  // jitter raises Error and leaves it empty.
  void fit(const Eigen::Ref<const Eigen::MatrixXd>& inputs,
           const Eigen::Ref<const Eigen::VectorXd>& targets);
  // Appends one point, dropping the oldest first when the window is full.
  void add(const Eigen::Ref<const Eigen::VectorXd>& input, double target);
  void remove_oldest();
  void clear();
  // Storage for `points` points, so that additions up to that number never reallocate (the
  // factor alone takes 8·points² bytes).
  void reserve(int points);

  // Sets the hyper-parameters and refactors the data held; if that fails (Error), the previous
  // hyper-parameters stay.
  void set_hyperparameters(const GpHyperparameters& hyperparameters);
  // Maximises the log marginal likelihood of the data held over the hyper-parameters (see
  // GpOptions), keeps the best and refactors. Returns its log marginal likelihood.
  double optimize_hyperparameters(Rng& rng);

  // Posterior mean and variance of the latent function at each row of `inputs` (plus σ_n² with
  // `with_noise`: the variance of a new observation). Variances are clamped at zero.
  void predict(const Eigen::Ref<const Eigen::MatrixXd>& inputs, Eigen::VectorXd& mean,
               Eigen::VectorXd& variance, bool with_noise = false) const;
  // One point, with the gradients of mean and latent variance with respect to the input.
  void predict(const Eigen::Ref<const Eigen::VectorXd>& input, double& mean, double& variance,
               Eigen::VectorXd& mean_gradient, Eigen::VectorXd& variance_gradient) const;

  // log p(y | X, θ) = −½ (y − m)ᵀα − Σ log L_ii − (n/2) log 2π (R&W eq. 2.30), at the current
  // hyper-parameters.
  double log_marginal_likelihood() const;
  // The same at log-parameters θ = (log ℓ_1, …, log ℓ_d, log σ_f², log σ_n²) for the data held,
  // with its gradient ∂/∂θ_k = ½ tr((ααᵀ − K⁻¹) ∂K/∂θ_k) (R&W eq. 5.9) when `gradient` is given.
  double log_marginal_likelihood(const Eigen::VectorXd& log_parameters,
                                 Eigen::VectorXd* gradient) const;
  // The same with caller-owned scratch matrices (a search reuses them).
  double log_marginal_likelihood(const Eigen::VectorXd& log_parameters, Eigen::VectorXd* gradient,
                                 LikelihoodWorkspace& workspace) const;
  static Eigen::VectorXd to_log_parameters(const GpHyperparameters& hyperparameters);
  static GpHyperparameters from_log_parameters(const Eigen::VectorXd& log_parameters);

  int size() const { return size_; }
  int input_dim() const { return input_dim_; }
  const GpOptions& options() const { return options_; }
  const GpHyperparameters& hyperparameters() const { return hyperparameters_; }
  double jitter() const { return jitter_; }
  double prior_mean() const { return prior_mean_; }
  auto inputs() const { return inputs_.topRows(size_); }
  auto targets() const { return targets_.head(size_); }
  // The lower Cholesky factor of K + (σ_n² + jitter) I.
  auto cholesky_factor() const { return factor_.topLeftCorner(size_, size_); }

 private:
  void check_input(const Eigen::Ref<const Eigen::VectorXd>& input, const char* where) const;
  // remove_oldest without the weights' update (add updates them once, after both changes).
  void drop_oldest();
  // Factors the data held from scratch, raising the jitter as needed.
  void refactor();
  // Prior mean and α from the factor and the targets, O(n²).
  void update_weights();

  int input_dim_;
  GpOptions options_;
  GpHyperparameters hyperparameters_;
  ArdKernel kernel_;
  int size_ = 0;
  Eigen::MatrixXd inputs_;   // capacity × input_dim; the first size_ rows hold the data
  Eigen::VectorXd targets_;  // capacity
  Eigen::MatrixXd factor_;   // capacity × capacity; its leading size_ × size_ lower triangle is L
  Eigen::VectorXd weights_;  // α, size_
  double prior_mean_ = 0.0;
  double jitter_ = 0.0;
};

}  // namespace tendril::adapt
