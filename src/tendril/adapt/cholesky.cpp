#include "tendril/adapt/cholesky.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace tendril::adapt {

bool factor_with_jitter(const Eigen::MatrixXd& kernel_matrix, double noise_variance,
                        double signal_variance, Eigen::Ref<Eigen::MatrixXd> factor,
                        double& jitter) {
  // Rung 0 is no jitter; rung k ≥ 1 adds 10^(k−1)·kFirstJitter·σ_f².
  const int rungs = 1 + static_cast<int>(std::lround(std::log10(kLastJitter / kFirstJitter))) + 1;
  double relative = kFirstJitter;
  for (int rung = 0; rung < rungs; ++rung) {
    jitter = rung == 0 ? 0.0 : relative * signal_variance;
    if (rung > 0) relative *= 10.0;
    factor = kernel_matrix;
    factor.diagonal().array() += noise_variance + jitter;
    Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(factor);
    if (llt.info() == Eigen::Success) return true;
  }
  return false;
}

void cholesky_remove_first(Eigen::Ref<Eigen::MatrixXd> factor, Eigen::Index n) {
  const Eigen::Index m = n - 1;
  if (m <= 0) return;
  Eigen::VectorXd v = factor.col(0).segment(1, m);  // l21, indexed like L22's rows
  for (Eigen::Index k = 0; k < m; ++k) {
    // L22's column k is factor column k + 1 from row k + 1; it lands in column k from row k.
    const double* source = &factor(k + 1, k + 1);
    double* target = &factor(k, k);
    double* rest = v.data() + k;
    const double diagonal = source[0];
    const double r = std::sqrt(diagonal * diagonal + rest[0] * rest[0]);
    const double c = r / diagonal, s = rest[0] / diagonal, inverse_c = diagonal / r;
    target[0] = r;
    const Eigen::Index below = m - k;
#pragma omp simd
    for (Eigen::Index i = 1; i < below; ++i) {
      const double updated = (source[i] + s * rest[i]) * inverse_c;
      target[i] = updated;
      rest[i] = c * rest[i] - s * updated;
    }
  }
}

void cholesky_inverse(const Eigen::Ref<const Eigen::MatrixXd>& factor, Eigen::MatrixXd& inverse) {
  constexpr Eigen::Index kBlock = 64;
  const Eigen::Index n = factor.rows();
  inverse.setZero(n, n);
  // L⁻¹, lower triangular: columns J..J+b solve L[J:, J:] X = I[J:, J:J+b] (rows above J are 0).
  for (Eigen::Index j = 0; j < n; j += kBlock) {
    const Eigen::Index width = std::min(kBlock, n - j);
    auto columns = inverse.block(j, j, n - j, width);
    columns.topRows(width).setIdentity();
    factor.block(j, j, n - j, n - j).triangularView<Eigen::Lower>().solveInPlace(columns);
  }
  // (L⁻ᵀL⁻¹)_ik = Σ_{m ≥ max(i,k)} (L⁻¹)_mi (L⁻¹)_mk: rows I..I+b, columns 0..I+b, need only rows
  // m ≥ I of L⁻¹, which later steps have not overwritten yet.
  Eigen::MatrixXd rows;
  for (Eigen::Index i = 0; i < n; i += kBlock) {
    const Eigen::Index height = std::min(kBlock, n - i);
    rows.noalias() =
        inverse.block(i, i, n - i, height).transpose() * inverse.block(i, 0, n - i, i + height);
    inverse.block(i, 0, height, i + height) = rows;
  }
}

}  // namespace tendril::adapt
