#pragma once

#include <torch/torch.h>

namespace tendril::nn::diag_gaussian {

// A diagonal Gaussian over actions: `mean` [batch, dims], `log_std` [dims] (state-independent,
// broadcast over the batch). All results are per sample, summed over action dimensions.

// log N(a; μ, σ²) = −½ Σ_i ((a_i − μ_i)/σ_i)² − Σ_i log σ_i − (d/2) log 2π
torch::Tensor log_prob(const torch::Tensor& mean, const torch::Tensor& log_std,
                       const torch::Tensor& actions);

// H = Σ_i (½ + ½ log 2π + log σ_i), the same for every sample; returned as [batch].
torch::Tensor entropy(const torch::Tensor& mean, const torch::Tensor& log_std);

// KL(p‖q) = Σ_i [log(σ_q,i/σ_p,i) + (σ_p,i² + (μ_p,i − μ_q,i)²)/(2σ_q,i²) − ½]
torch::Tensor kl(const torch::Tensor& mean_p, const torch::Tensor& log_std_p,
                 const torch::Tensor& mean_q, const torch::Tensor& log_std_q);

}  // namespace tendril::nn::diag_gaussian
