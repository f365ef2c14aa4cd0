#include "tendril/rl/trpo/conjugate_gradient.hpp"

#include <gtest/gtest.h>

namespace tendril::rl {
namespace {

TEST(ConjugateGradient, SolvesASymmetricPositiveDefiniteSystem) {
  torch::manual_seed(0);
  const torch::Tensor m = torch::randn({6, 6}, torch::kDouble);
  const torch::Tensor a = m.mm(m.t()) + 0.5 * torch::eye(6, torch::kDouble);
  const torch::Tensor b = torch::randn({6}, torch::kDouble);
  int products = 0;
  const auto product = [&](const torch::Tensor& v) {
    ++products;
    return a.mv(v);
  };
  // In exact arithmetic CG converges in n steps for an n × n system.
  const torch::Tensor x = conjugate_gradient(product, b, 20, 1e-20);
  EXPECT_TRUE(torch::allclose(a.mv(x), b, 1e-6, 1e-8));
  EXPECT_LE(products, 20);
  // Capped at one step, it returns the steepest-descent step α b with α = bᵀb / bᵀAb.
  const torch::Tensor one_step = conjugate_gradient(product, b, 1);
  const double alpha = (b.dot(b) / b.dot(a.mv(b))).item<double>();
  EXPECT_TRUE(torch::allclose(one_step, alpha * b));
}

}  // namespace
}  // namespace tendril::rl
