#include "tendril/nn/flat_parameters.hpp"

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
  // One pass in double over the buffer; with a coefficient of 1 torch's multiplication is the
  // identity, so it is skipped.
  const float* gradient = gradients_.data_ptr<float>();
  double sum_of_squares = 0.0;
  for (int64_t i = 0; i < gradients_.numel(); ++i) {
    sum_of_squares += static_cast<double>(gradient[i]) * gradient[i];
  }
  const double norm = std::sqrt(sum_of_squares);
  const double coefficient = max_norm / (norm + 1e-6);
  if (coefficient < 1.0) gradients_.mul_(coefficient);
  return norm;
}

}  // namespace tendril::nn
