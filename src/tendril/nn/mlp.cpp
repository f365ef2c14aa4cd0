#include "tendril/nn/mlp.hpp"

#include <string>

#include "tendril/core/error.hpp"
#include "tendril/nn/orthogonal_init.hpp"

namespace tendril::nn {

torch::nn::Linear make_linear(int64_t input_size, int64_t output_size, bool orthogonal, double gain,
                              Rng& init_rng) {
  torch::nn::Linear layer(input_size, output_size);
  if (orthogonal) orthogonal_init(layer, gain, init_rng);
  return layer;
}

MlpImpl::MlpImpl(int64_t input_size, const std::vector<int64_t>& hidden, Activation activation,
                 bool orthogonal, Rng& init_rng)
    : activation_(activation), output_size_(input_size) {
  require(input_size > 0, "input size must be positive", "nn::Mlp");
  for (std::size_t i = 0; i < hidden.size(); ++i) {
    require(hidden[i] > 0, "hidden layer " + std::to_string(i) + " has no units", "nn::Mlp");
    auto layer = make_linear(output_size_, hidden[i], orthogonal, kHiddenGain, init_rng);
    layers_.push_back(register_module("layer" + std::to_string(i), layer));
    output_size_ = hidden[i];
  }
}

torch::Tensor MlpImpl::forward(torch::Tensor input) {
  for (auto& layer : layers_) {
    input = layer->forward(input);
    input = activation_ == Activation::kTanh ? torch::tanh(input) : torch::relu(input);
  }
  return input;
}

}  // namespace tendril::nn
