#pragma once

#include <Eigen/Core>

#include "tendril/adapt/kernel.hpp"

namespace tendril::adapt {

// Scratch matrices for repeated likelihood evaluations (n × n each), so that a hyper-parameter
// search allocates once.
struct LikelihoodWorkspace {
  Eigen::MatrixXd squared_distances, kernel_matrix, factor, inverse, weights;
};

// What the search sees for hyper-parameters whose kernel matrix does not factor even with
// jitter: far below any attainable likelihood, finite so that L-BFGS's line search backs off.
constexpr double kUnfactorableLikelihood = -1e100;

// Σ_k log p(r_k | X, θ) over the columns r_k of `residuals` (targets minus prior mean), each an
// output with the same kernel K = K_f(θ) + σ_n² I (R&W eq. 2.30):
//   Σ_k [−½ r_kᵀα_k] − m Σ_i log L_ii − (mn/2) log 2π,   α_k = K⁻¹r_k,
// and, when `gradient` is given, ∂/∂θ_j = ½ tr((Σ_k α_kα_kᵀ − m K⁻¹) ∂K/∂θ_j) (R&W eq. 5.9) for
// θ = (log ℓ_1, …, log ℓ_d, log σ_f², log σ_n²). Sums over the symmetric matrices run over their
// lower triangles. Returns kUnfactorableLikelihood (gradient zero) when K does not factor.
double log_marginal_likelihood(KernelType type, const Eigen::Ref<const Eigen::MatrixXd>& inputs,
                               const Eigen::Ref<const Eigen::MatrixXd>& residuals,
                               const Eigen::VectorXd& log_parameters, Eigen::VectorXd* gradient,
                               LikelihoodWorkspace& workspace);

}  // namespace tendril::adapt
