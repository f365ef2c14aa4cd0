#pragma once

#include <torch/torch.h>

namespace tendril::nn::categorical {

// A categorical distribution over n actions from unnormalised `logits` [batch, n]. Actions are
// indices stored as floats [batch, 1] (tendril's Action convention for Discrete spaces).

// log p(a) = logits_a − logsumexp(logits)
torch::Tensor log_prob(const torch::Tensor& logits, const torch::Tensor& actions);

// H = −Σ_k p_k log p_k
torch::Tensor entropy(const torch::Tensor& logits);

// KL(p‖q) = Σ_k p_k (log p_k − log q_k)
torch::Tensor kl(const torch::Tensor& logits_p, const torch::Tensor& logits_q);

}  // namespace tendril::nn::categorical
