#include "tendril/nn/parameter_vector.hpp"

#include "tendril/core/error.hpp"

namespace tendril::nn {

torch::Tensor flatten(const std::vector<torch::Tensor>& tensors) {
  std::vector<torch::Tensor> pieces;
  pieces.reserve(tensors.size());
  for (const auto& t : tensors) pieces.push_back(t.reshape({-1}));
  return torch::cat(pieces);
}

torch::Tensor flatten_parameters(const std::vector<torch::Tensor>& parameters) {
  return flatten(parameters).detach().clone();
}

torch::Tensor flatten_gradients(const std::vector<torch::Tensor>& parameters) {
  std::vector<torch::Tensor> pieces;
  pieces.reserve(parameters.size());
  for (const auto& p : parameters) {
    pieces.push_back(p.grad().defined() ? p.grad().reshape({-1}) : torch::zeros({p.numel()}));
  }
  return torch::cat(pieces);
}

void assign_parameters(const std::vector<torch::Tensor>& parameters, const torch::Tensor& flat) {
  int64_t total = 0;
  for (const auto& p : parameters) total += p.numel();
  require(flat.numel() == total,
          "flat vector has " + std::to_string(flat.numel()) + " values for " +
              std::to_string(total) + " parameters",
          "nn::assign_parameters");
  torch::NoGradGuard no_grad;
  int64_t offset = 0;
  for (const auto& p : parameters) {
    p.copy_(flat.slice(0, offset, offset + p.numel()).view_as(p));
    offset += p.numel();
  }
}

}  // namespace tendril::nn
