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

void cholesky_rank_one_update(Eigen::Ref<Eigen::MatrixXd> factor, Eigen::VectorXd& v) {
  // Plane rotations that fold v into L one column at a time.
  const Eigen::Index m = factor.rows();
  for (Eigen::Index k = 0; k < m; ++k) {
    const double diagonal = factor(k, k);
    const double r = std::hypot(diagonal, v[k]);
    const double c = r / diagonal, s = v[k] / diagonal;
    factor(k, k) = r;
    const Eigen::Index rest = m - k - 1;
    if (rest == 0) break;
    auto column = factor.col(k).tail(rest);
    auto tail = v.tail(rest);
    column = (column + s * tail) / c;
    tail = c * tail - s * column;
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
