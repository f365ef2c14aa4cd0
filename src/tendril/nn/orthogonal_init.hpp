#pragma once

#include <torch/torch.h>

#include "tendril/core/rng.hpp"

namespace tendril::nn {

// Gains that Stable-Baselines3 uses with orthogonal initialisation: sqrt(2) for hidden layers,
// 0.01 for the policy head (near-uniform initial policy), 1 for the value head.
inline constexpr double kHiddenGain = 1.4142135623730951;
inline constexpr double kPolicyHeadGain = 0.01;
inline constexpr double kValueHeadGain = 1.0;

// Fills `weight` (out × in) with a scaled (semi-)orthogonal matrix and `bias` with zeros
// (Saxe et al. 2014, "Exact solutions to the nonlinear dynamics of learning in deep linear
// neural networks"): Q of the QR decomposition of a standard-normal matrix, column signs fixed
// by diag(R) so the distribution is uniform (Haar) over orthogonal matrices. The normal draws
// come from `rng`, so initialisation is reproducible without LibTorch's global generator.
void orthogonal_init(torch::nn::Linear& layer, double gain, Rng& rng);

}  // namespace tendril::nn
