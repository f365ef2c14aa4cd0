#include "tendril/adapt/kernel.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/error_message.hpp"

namespace tendril::adapt {
namespace {

using testing::error_message;

TEST(ArdKernel, ShapesMatchTheirFormulas) {
  // R&W eq. (4.9) and (4.17) at r = 0, 1, 2.
  EXPECT_DOUBLE_EQ(ArdKernel::shape(KernelType::squared_exponential, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(ArdKernel::shape(KernelType::squared_exponential, 2.0), std::exp(-2.0));
  EXPECT_DOUBLE_EQ(ArdKernel::shape(KernelType::matern52, 0.0), 1.0);
  const double s5 = std::sqrt(5.0);
  EXPECT_DOUBLE_EQ(ArdKernel::shape(KernelType::matern52, 1.0),
                   (1.0 + s5 + 5.0 / 3.0) * std::exp(-s5));
  EXPECT_DOUBLE_EQ(ArdKernel::shape(KernelType::matern52, 2.0),
                   (1.0 + 2.0 * s5 + 20.0 / 3.0) * std::exp(-2.0 * s5));
  // The slope g(r) = −k'(r)/(r σ_f²), by central differences.
  for (KernelType type : {KernelType::squared_exponential, KernelType::matern52}) {
    for (double r : {0.3, 1.0, 2.5}) {
      const double h = 1e-6;
      const double derivative =
          (ArdKernel::shape(type, r + h) - ArdKernel::shape(type, r - h)) / (2 * h);
      EXPECT_NEAR(ArdKernel::slope(type, r), -derivative / r, 1e-8) << r;
    }
  }
}

TEST(ArdKernel, CovarianceUsesOneLengthScalePerDimension) {
  const ArdKernel kernel(KernelType::squared_exponential, Eigen::Vector2d(0.5, 4.0), 2.0);
  Eigen::MatrixXd a(2, 2), b(1, 2);
  a << 0.0, 0.0, 1.0, 2.0;
  b << 0.5, 4.0;
  Eigen::MatrixXd k;
  kernel.covariance(a, b, k);
  ASSERT_EQ(k.rows(), 2);
  ASSERT_EQ(k.cols(), 1);
  // r² = (0.5/0.5)² + (4/4)² = 2 and (0.5/0.5)² + (2/4)² = 1.25.
  EXPECT_DOUBLE_EQ(k(0, 0), 2.0 * std::exp(-1.0));
  EXPECT_DOUBLE_EQ(k(1, 0), 2.0 * std::exp(-0.625));
  Eigen::VectorXd column;
  kernel.covariance(a, b.row(0).transpose(), column);
  EXPECT_EQ(column, k.col(0));
}

TEST(ArdKernel, NegligibleValuesAreExactZeros) {
  EXPECT_GT(ArdKernel::shape(KernelType::squared_exponential, 20.0), 0.0);  // e^−200
  EXPECT_EQ(ArdKernel::shape(KernelType::squared_exponential, 30.0), 0.0);  // e^−450
  EXPECT_EQ(ArdKernel::shape(KernelType::squared_exponential, 1e6), 0.0);
  EXPECT_GT(ArdKernel::shape(KernelType::matern52, 90.0), 0.0);
  EXPECT_EQ(ArdKernel::shape(KernelType::matern52, 120.0), 0.0);
  EXPECT_EQ(ArdKernel::slope(KernelType::matern52, 1e9), 0.0);
  const ArdKernel kernel(KernelType::matern52, Eigen::VectorXd::Constant(1, 1e-3), 1.0);
  Eigen::MatrixXd a(2, 1), k;
  a << 0.0, 1.0;
  kernel.covariance(a, a, k);
  EXPECT_EQ(k(0, 1), 0.0);
  EXPECT_EQ(k(0, 0), 1.0);
}

TEST(ArdKernel, BadParametersAreErrors) {
  EXPECT_NE(error_message([] {
              ArdKernel(KernelType::matern52, Eigen::Vector2d(1.0, 0.0), 1.0);
            }).find("length scale 1 is 0"),
            std::string::npos);
  EXPECT_NE(error_message([] {
              ArdKernel(KernelType::matern52, Eigen::Vector2d(1.0, 1.0), NAN);
            }).find("signal variance"),
            std::string::npos);
  EXPECT_EQ(kernel_type_from_name("matern52"), KernelType::matern52);
  EXPECT_EQ(kernel_type_from_name(kernel_type_name(KernelType::squared_exponential)),
            KernelType::squared_exponential);
}

}  // namespace
}  // namespace tendril::adapt
