// The dense layers' BLAS products against Eigen's, on shapes that are not multiples of any
// kernel's tile and on operands with a column stride (blocks of larger matrices).
#include "tendril/nn/blas.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"

namespace tendril::nn {
namespace {

constexpr float kTolerance = 1e-5f;  // relative, of float sums over ≤ 300 terms

float relative_error(const Eigen::MatrixXf& actual, const Eigen::MatrixXf& expected) {
  return (actual - expected).norm() / expected.norm();
}

class BlasProducts : public ::testing::TestWithParam<std::tuple<int, int, int>> {
 protected:
  int out() const { return std::get<0>(GetParam()); }
  int in() const { return std::get<1>(GetParam()); }
  int batch() const { return std::get<2>(GetParam()); }
};

TEST_P(BlasProducts, MultiplyEqualsEigen) {
  const RowMajorMatrixXf weight = RowMajorMatrixXf::Random(out(), in());
  // The inputs are a block of a wider matrix: their columns are `in() + 3` floats apart.
  const Eigen::MatrixXf wide = Eigen::MatrixXf::Random(in() + 3, batch() + 2);
  const auto inputs = wide.topRightCorner(in(), batch());
  Eigen::MatrixXf result;
  multiply(ConstRowMajorMap(weight.data(), out(), in()), inputs, result);
  ASSERT_EQ(result.rows(), out());
  ASSERT_EQ(result.cols(), batch());
  EXPECT_LT(relative_error(result, weight * inputs), kTolerance);
}

TEST_P(BlasProducts, MultiplyTransposedEqualsEigen) {
  const RowMajorMatrixXf weight = RowMajorMatrixXf::Random(out(), in());
  const Eigen::MatrixXf inputs = Eigen::MatrixXf::Random(out(), batch());
  Eigen::MatrixXf result = Eigen::MatrixXf::Constant(2, 2, 7.0f);  // resized and overwritten
  multiply_transposed(ConstRowMajorMap(weight.data(), out(), in()), inputs, result);
  ASSERT_EQ(result.rows(), in());
  ASSERT_EQ(result.cols(), batch());
  EXPECT_LT(relative_error(result, weight.transpose() * inputs), kTolerance);
}

TEST_P(BlasProducts, AddOuterProductsAccumulates) {
  const Eigen::MatrixXf left = Eigen::MatrixXf::Random(out(), batch());
  const Eigen::MatrixXf right = Eigen::MatrixXf::Random(in(), batch());
  RowMajorMatrixXf gradient = RowMajorMatrixXf::Random(out(), in());
  const RowMajorMatrixXf expected = gradient + left * right.transpose();
  add_outer_products(left, right, RowMajorMap(gradient.data(), out(), in()));
  EXPECT_LT(relative_error(gradient, expected), kTolerance);
}

INSTANTIATE_TEST_SUITE_P(Shapes, BlasProducts,
                         ::testing::Values(std::tuple{1, 1, 1}, std::tuple{3, 5, 1},
                                           std::tuple{67, 13, 29}, std::tuple{256, 256, 256},
                                           std::tuple{1, 257, 100}, std::tuple{300, 4, 7}));

TEST(Blas, TwoThreadsGiveTheSameProductsTwice) {
  const RowMajorMatrixXf weight = RowMajorMatrixXf::Random(256, 256);
  const Eigen::MatrixXf inputs = Eigen::MatrixXf::Random(256, 256);
  set_blas_threads(2);
  Eigen::MatrixXf first, second;
  multiply(ConstRowMajorMap(weight.data(), 256, 256), inputs, first);
  multiply(ConstRowMajorMap(weight.data(), 256, 256), inputs, second);
  set_blas_threads(1);
  EXPECT_TRUE(first == second);
  EXPECT_LT(relative_error(first, weight * inputs), kTolerance);
}

TEST(Blas, MismatchedSizesAreRefused) {
  const RowMajorMatrixXf weight = RowMajorMatrixXf::Random(4, 3);
  Eigen::MatrixXf result;
  EXPECT_NE(testing::error_message([&] {
              multiply(ConstRowMajorMap(weight.data(), 4, 3), Eigen::MatrixXf(5, 2), result);
            }).find("wrong number of rows"),
            std::string::npos);
  RowMajorMatrixXf gradient(4, 3);
  EXPECT_NE(testing::error_message([&] {
              add_outer_products(Eigen::MatrixXf(4, 2), Eigen::MatrixXf(3, 5),
                                 RowMajorMap(gradient.data(), 4, 3));
            }).find("sizes do not match"),
            std::string::npos);
  EXPECT_NE(testing::error_message([] { set_blas_threads(0); }).find("at least one"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::nn
