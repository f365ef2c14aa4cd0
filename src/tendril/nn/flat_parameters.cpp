#include "tendril/nn/flat_parameters.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <utility>

#include "tendril/core/error.hpp"

namespace tendril::nn {

FlatParameters::FlatParameters(std::vector<torch::Tensor> parameters)
    : parameters_(std::move(parameters)) {
  int64_t total = 0;
  for (const auto& p : parameters_) {
    require(p.scalar_type() == torch::kFloat && p.device().is_cpu(),
            "parameters must be float tensors on the CPU", "nn::FlatParameters");
    total += p.numel();
  }
  torch::NoGradGuard no_grad;
  values_ = torch::empty({total}, torch::kFloat);
  gradients_ = torch::zeros({total}, torch::kFloat);
  int64_t offset = 0;
  for (auto& p : parameters_) {
    const int64_t n = p.numel();
    torch::Tensor value = values_.slice(0, offset, offset + n).view(p.sizes());
    value.copy_(p);
    p.set_data(value);
    p.mutable_grad() = gradients_.slice(0, offset, offset + n).view(p.sizes());
    offset += n;
  }
}

double FlatParameters::clip_grad_norm(double max_norm) {
  // Σ g² in double over float partial sums of short blocks: as accurate as a double loop for
  // this purpose, and vectorised. A coefficient of 1 or more leaves the gradients as they are
  // (torch multiplies by exactly 1).
  constexpr int64_t kBlock = 256;
  Eigen::Map<Eigen::VectorXf> gradient(gradients_.data_ptr<float>(), gradients_.numel());
  double sum_of_squares = 0.0;
  for (int64_t start = 0; start < gradient.size(); start += kBlock) {
    sum_of_squares +=
        gradient.segment(start, std::min(kBlock, gradient.size() - start)).squaredNorm();
  }
  const double norm = std::sqrt(sum_of_squares);
  const double coefficient = max_norm / (norm + 1e-6);
  if (coefficient < 1.0) gradient *= static_cast<float>(coefficient);
  return norm;
}

}  // namespace tendril::nn
