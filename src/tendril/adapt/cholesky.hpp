#pragma once

#include <Eigen/Core>

namespace tendril::adapt {

// The jitter ladder for kernel matrices that do not factor: 1e-10·σ_f² added to the diagonal,
// ×10 per failed attempt, up to 1e-4·σ_f².
constexpr double kFirstJitter = 1e-10;
constexpr double kLastJitter = 1e-4;

// Factors `kernel_matrix` + (noise_variance + jitter) I into the lower triangle of `factor`
// (same size), climbing the jitter ladder (relative to `signal_variance`) from zero until the
// Cholesky factorisation succeeds. Returns false when even the last rung fails; `jitter` holds
// the jitter used.
bool factor_with_jitter(const Eigen::MatrixXd& kernel_matrix, double noise_variance,
                        double signal_variance, Eigen::Ref<Eigen::MatrixXd> factor, double& jitter);

// Given in the leading n × n lower triangle of `factor` the Cholesky factor L of K, writes to its
// leading (n − 1) × (n − 1) lower triangle the factor of K without its first row and column, in
// O(n²): with L = [l11 0; l21 L22], that matrix is L22 L22ᵀ + l21 l21ᵀ, a rank-one update of L22 by
// plane rotations (Golub & Van Loan, "Matrix Computations", 4th ed., §6.5.4), done while moving
// each column up and left by one (one pass over the memory).
void cholesky_remove_first(Eigen::Ref<Eigen::MatrixXd> factor, Eigen::Index n);

// The lower triangle of (L Lᵀ)⁻¹ = L⁻ᵀL⁻¹ from the lower Cholesky factor L, in ≈ 2n³/3 flops
// (half of solving L Lᵀ X = I): L⁻¹ one block of columns at a time, then L⁻ᵀL⁻¹ one block of
// rows at a time, each a matrix product over the rows below (the blocked forms of LAPACK's
// dtrtri and dlauum). Above the diagonal `inverse` holds no meaningful values.
void cholesky_inverse(const Eigen::Ref<const Eigen::MatrixXd>& factor, Eigen::MatrixXd& inverse);

}  // namespace tendril::adapt
