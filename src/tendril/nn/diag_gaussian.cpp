#include "tendril/nn/diag_gaussian.hpp"

#include <cmath>

namespace tendril::nn::diag_gaussian {

namespace {
constexpr double kHalfLogTwoPi = 0.91893853320467274178;  // ½ log 2π
}

torch::Tensor log_prob(const torch::Tensor& mean, const torch::Tensor& log_std,
                       const torch::Tensor& actions) {
  const torch::Tensor z = (actions - mean) * torch::exp(-log_std);
  const auto dims = static_cast<double>(mean.size(-1));
  return -0.5 * z.pow(2).sum(-1) - log_std.sum() - dims * kHalfLogTwoPi;
}

torch::Tensor entropy(const torch::Tensor& mean, const torch::Tensor& log_std) {
  const auto dims = static_cast<double>(mean.size(-1));
  return (log_std.sum() + dims * (0.5 + kHalfLogTwoPi)).expand({mean.size(0)});
}

torch::Tensor kl(const torch::Tensor& mean_p, const torch::Tensor& log_std_p,
                 const torch::Tensor& mean_q, const torch::Tensor& log_std_q) {
  const torch::Tensor variance_p = torch::exp(2.0 * log_std_p);
  const torch::Tensor variance_q = torch::exp(2.0 * log_std_q);
  return (log_std_q - log_std_p + (variance_p + (mean_p - mean_q).pow(2)) / (2.0 * variance_q) -
          0.5)
      .sum(-1);
}

}  // namespace tendril::nn::diag_gaussian
