#include "tendril/adapt/cholesky.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace tendril::adapt {
namespace {

Eigen::MatrixXd random_spd(int n, int seed) {
  std::srand(seed);
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(n, n);
  return a * a.transpose() + n * Eigen::MatrixXd::Identity(n, n);
}

TEST(Cholesky, InverseFromFactorMatchesTheInverse) {
  // Sizes below, at and across the 64-wide blocks.
  for (int n : {1, 5, 64, 65, 200}) {
    const Eigen::MatrixXd k = random_spd(n, n);
    const Eigen::MatrixXd factor = k.llt().matrixL();
    Eigen::MatrixXd inverse;
    cholesky_inverse(factor, inverse);
    const Eigen::MatrixXd expected = k.inverse();
    const Eigen::MatrixXd lower = inverse.triangularView<Eigen::Lower>();
    const Eigen::MatrixXd expected_lower = expected.triangularView<Eigen::Lower>();
    EXPECT_LT((lower - expected_lower).cwiseAbs().maxCoeff(),
              1e-12 * expected.cwiseAbs().maxCoeff())
        << "n = " << n;
  }
}

TEST(Cholesky, RankOneUpdateFactorsTheUpdatedMatrix) {
  const Eigen::MatrixXd k = random_spd(30, 1);
  Eigen::MatrixXd factor = k.llt().matrixL();
  Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(30, -2.0, 3.0);
  const Eigen::MatrixXd updated = k + v * v.transpose();
  cholesky_rank_one_update(factor, v);
  const Eigen::MatrixXd lower = factor.triangularView<Eigen::Lower>();
  const Eigen::MatrixXd expected = updated.llt().matrixL();
  EXPECT_LT((lower - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace tendril::adapt
