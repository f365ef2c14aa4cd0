#include "tendril/adapt/cholesky.hpp"

#include <Eigen/Cholesky>
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

}  // namespace tendril::adapt
