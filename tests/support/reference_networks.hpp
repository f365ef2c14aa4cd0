#pragma once

// Building blocks of the reference implementations the off-policy update tests compare against:
// LibTorch modules read from (and written back to) the flat parameter vectors the algorithms keep,
// and the random draws an update makes, replayed from a copy of its stream. Batches become
// tensors with torch_networks.hpp's rows_of.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "support/torch_networks.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/rl/observer.hpp"

namespace tendril::testing {

// An MLP as torch::nn layers: Linear layers of `sizes` with ReLU (or tanh) between them and,
// when `tanh_output`, a tanh after the last (a deterministic actor's squash).
inline torch::nn::Sequential reference_mlp(const std::vector<int64_t>& sizes, bool tanh_hidden,
                                           bool tanh_output = false) {
  torch::nn::Sequential module;
  for (size_t i = 0; i + 1 < sizes.size(); ++i) {
    module->push_back(torch::nn::Linear(sizes[i], sizes[i + 1]));
    const bool last = i + 2 == sizes.size();
    if (!last && tanh_hidden) module->push_back(torch::nn::Tanh());
    if (!last && !tanh_hidden) module->push_back(torch::nn::ReLU());
    if (last && tanh_output) module->push_back(torch::nn::Tanh());
  }
  return module;
}

inline int64_t parameter_count(const torch::nn::Module& module) {
  int64_t count = 0;
  for (const torch::Tensor& parameter : module.parameters()) count += parameter.numel();
  return count;
}

// Copies `parameters[offset…]` into the module's parameters in torch's order (each Linear's
// weight, out × in row-major, then its bias: the flat layout of the algorithms' networks).
// Returns the offset after the module.
inline int64_t load_flat(torch::nn::Module& module, const Eigen::VectorXf& parameters,
                         int64_t offset = 0) {
  torch::NoGradGuard no_grad;
  for (torch::Tensor& parameter : module.parameters()) {
    EXPECT_LE(offset + parameter.numel(), parameters.size());
    parameter.copy_(
        torch::from_blob(const_cast<float*>(parameters.data()) + offset, parameter.sizes()));
    offset += parameter.numel();
  }
  return offset;
}

// The modules' parameters, one after the other, as one flat vector.
inline Eigen::VectorXf flat_parameters(const std::vector<const torch::nn::Module*>& modules) {
  std::vector<torch::Tensor> pieces;
  for (const torch::nn::Module* module : modules) {
    for (const torch::Tensor& parameter : module->parameters())
      pieces.push_back(parameter.detach().reshape({-1}));
  }
  const torch::Tensor flat = torch::cat(pieces).contiguous();
  return Eigen::Map<const Eigen::VectorXf>(flat.data_ptr<float>(), flat.numel());
}

// A vector as a [size, 1] tensor (a copy).
inline torch::Tensor column_tensor(const Eigen::VectorXf& values) {
  return torch::from_blob(const_cast<float*>(values.data()), {values.size(), 1}).clone();
}

// `rows × cols` standard normal draws from `rng`, row by row (the order in which an update fills
// an action_size × batch matrix column by column).
inline torch::Tensor standard_normal(Rng& rng, int64_t rows, int64_t cols) {
  torch::Tensor draws = torch::empty({rows, cols});
  float* data = draws.data_ptr<float>();
  for (int64_t i = 0; i < rows * cols; ++i) data[i] = static_cast<float>(rng.normal());
  return draws;
}

// SB3's SquashedDiagGaussianDistribution on an actor whose output is [μ; log σ] (log σ clamped
// to [−20, 2]): a = tanh(μ + σ ε), log π = Σ_j log N(u_j; μ_j, σ_j) − Σ_j log(1 − a_j² + 1e-6).
// Returns a and log π ([batch, 1]).
inline std::pair<torch::Tensor, torch::Tensor> squashed_gaussian_sample(
    torch::nn::Sequential& actor, const torch::Tensor& inputs, const torch::Tensor& noise,
    int64_t actions) {
  const torch::Tensor head = actor->forward(inputs);
  const torch::Tensor mean = head.slice(1, 0, actions);
  const torch::Tensor log_std = torch::clamp(head.slice(1, actions, 2 * actions), -20, 2);
  const torch::Tensor std = torch::exp(log_std);
  const torch::Tensor u = mean + std * noise;
  const torch::Tensor a = torch::tanh(u);
  const torch::Tensor gaussian =
      -(u - mean).pow(2) / (2 * std.pow(2)) - log_std - 0.5 * std::log(2 * M_PI);
  const torch::Tensor log_prob =
      gaussian.sum(1, /*keepdim=*/true) - torch::log(1 - a.pow(2) + 1e-6).sum(1, true);
  return {a, log_prob};
}

// A named statistic of an update (fails the test when it is missing).
inline double stat(const rl::TrainStats& stats, const std::string& key) {
  for (const auto& [name, value] : stats) {
    if (name == key) return value;
  }
  ADD_FAILURE() << "no statistic " << key;
  return NAN;
}

// Largest |a_i − b_i| over two vectors of equal size.
inline double max_difference(const Eigen::VectorXf& a, const Eigen::VectorXf& b) {
  EXPECT_EQ(a.size(), b.size());
  if (a.size() != b.size()) return 1e30;
  return static_cast<double>((a - b).cwiseAbs().maxCoeff());
}

// The rounding a float32 computation of v may carry: `ulps` units in the last place of its largest
// entry. A Polyak average τ·θ + (1 − τ)·θ' that moves θ' by ~τ·step is compared within a
// fraction of that move plus this, since two correct orders of the same float operations (or
// one FMA more under other compiler flags) differ by an ulp.
inline double float_rounding(const Eigen::VectorXf& v, int ulps = 4) {
  return ulps * static_cast<double>(std::numeric_limits<float>::epsilon()) *
         static_cast<double>(v.cwiseAbs().maxCoeff());
}

}  // namespace tendril::testing
