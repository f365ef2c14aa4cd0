#pragma once

#include <torch/torch.h>

#include <vector>

#include "tendril/core/rng.hpp"
#include "tendril/nn/activation.hpp"

namespace tendril::nn {

// A trunk of fully connected layers, each followed by the activation:
// input_size → hidden[0] → … → hidden.back(). With no hidden layers it is the identity, so a
// head can sit directly on the observation (SB3's `net_arch=[]`).
class MlpImpl : public torch::nn::Module {
 public:
  MlpImpl(int64_t input_size, const std::vector<int64_t>& hidden, Activation activation,
          bool orthogonal, Rng& init_rng);

  torch::Tensor forward(torch::Tensor input);

  int64_t output_size() const { return output_size_; }
  Activation activation() const { return activation_; }
  const std::vector<torch::nn::Linear>& layers() const { return layers_; }

 private:
  std::vector<torch::nn::Linear> layers_;
  Activation activation_;
  int64_t output_size_;
};
TORCH_MODULE(Mlp);

// A linear layer initialised as SB3 does: orthogonal with `gain` when `orthogonal`, otherwise
// LibTorch's default (Kaiming-uniform) initialisation.
torch::nn::Linear make_linear(int64_t input_size, int64_t output_size, bool orthogonal, double gain,
                              Rng& init_rng);

}  // namespace tendril::nn
