#include "tendril/rl/trpo/conjugate_gradient.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

namespace tendril::rl {
namespace {

TEST(ConjugateGradient, SolvesASymmetricPositiveDefiniteSystem) {
  srand(0);
  const Eigen::MatrixXf m = Eigen::MatrixXf::Random(6, 6);
  const Eigen::MatrixXf a = m * m.transpose() + 0.5f * Eigen::MatrixXf::Identity(6, 6);
  const Eigen::VectorXf b = Eigen::VectorXf::Random(6);
  const auto product = [&](const Eigen::VectorXf& v) -> Eigen::VectorXf { return a * v; };
  // In exact arithmetic CG converges in n steps for an n × n system; in float a step or two
  // more reach the tolerance.
  int64_t products = 0;
  const Eigen::VectorXf x = conjugate_gradient(product, b, 20, 1e-10, &products);
  EXPECT_TRUE((a * x).isApprox(b, 1e-4f));
  EXPECT_LE(products, 8);
  EXPECT_GE(products, 6);
  // Capped at one step, it returns the steepest-descent step α b with α = bᵀb / bᵀAb.
  const Eigen::VectorXf one_step = conjugate_gradient(product, b, 1, 1e-10, &products);
  EXPECT_EQ(products, 1);
  const float alpha = b.dot(b) / b.dot(a * b);
  EXPECT_TRUE(one_step.isApprox(alpha * b, 1e-6f));
  // A system already solved by x = 0 takes no product at all.
  EXPECT_EQ(conjugate_gradient(product, Eigen::VectorXf::Zero(6), 20, 1e-10, &products),
            Eigen::VectorXf::Zero(6));
  EXPECT_EQ(products, 0);
}

}  // namespace
}  // namespace tendril::rl
