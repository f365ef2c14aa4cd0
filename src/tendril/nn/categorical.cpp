#include "tendril/nn/categorical.hpp"

namespace tendril::nn::categorical {

torch::Tensor log_prob(const torch::Tensor& logits, const torch::Tensor& actions) {
  const torch::Tensor log_p = torch::log_softmax(logits, -1);
  const torch::Tensor index = actions.reshape({-1, 1}).to(torch::kLong);
  return log_p.gather(-1, index).squeeze(-1);
}

torch::Tensor entropy(const torch::Tensor& logits) {
  const torch::Tensor log_p = torch::log_softmax(logits, -1);
  return -(torch::exp(log_p) * log_p).sum(-1);
}

torch::Tensor kl(const torch::Tensor& logits_p, const torch::Tensor& logits_q) {
  const torch::Tensor log_p = torch::log_softmax(logits_p, -1);
  const torch::Tensor log_q = torch::log_softmax(logits_q, -1);
  return (torch::exp(log_p) * (log_p - log_q)).sum(-1);
}

}  // namespace tendril::nn::categorical
