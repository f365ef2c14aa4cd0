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

TEST(Cholesky, RemovingTheFirstRowAndColumnFactorsTheTrailingBlock) {
  const Eigen::MatrixXd k = random_spd(40, 2);
  Eigen::MatrixXd factor = Eigen::MatrixXd::Constant(50, 50, 7.0);  // larger storage, as a GP keeps
  factor.topLeftCorner(40, 40) = k.llt().matrixL();
  cholesky_remove_first(factor, 40);
  const Eigen::MatrixXd lower = factor.topLeftCorner(39, 39).triangularView<Eigen::Lower>();
  const Eigen::MatrixXd expected = k.bottomRightCorner(39, 39).llt().matrixL();
  EXPECT_LT((lower - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace tendril::adapt
