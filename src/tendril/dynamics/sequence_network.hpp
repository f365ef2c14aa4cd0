#pragma once

#include <torch/torch.h>

#include <memory>

#include "tendril/core/rng.hpp"
#include "tendril/dynamics/architecture.hpp"

namespace tendril::dynamics {

// A learned dynamics network: a batch of normalised input sequences
// [B, spec.sequence_length(), spec.feature_size()] → [B, state_dim]: the change Δx in the data's
// units (seed 001) or the normalised next state (seed 002). Parameters keep PyTorch's names
// ("encoder.weight_ih_l0", "head.bias", ...).
class SequenceNetwork : public torch::nn::Module {
 public:
  explicit SequenceNetwork(const ArchitectureSpec& spec) : spec_(spec) {}

  virtual torch::Tensor forward(const torch::Tensor& inputs) = 0;
  // Draws every parameter from `rng` with the default initialisation of the library the seed
  // used (PyTorch for seed 001, Keras for seed 002).
  virtual void initialize(Rng& rng) = 0;

  const ArchitectureSpec& spec() const { return spec_; }
  // The stream dropout masks come from in training mode (seed 002's network).
  void set_noise(const Rng& rng) { noise_ = rng; }
  const Rng& noise() const { return noise_; }

 protected:
  ArchitectureSpec spec_;
  Rng noise_;
};

// The network `spec` describes, with uninitialised parameters.
std::shared_ptr<SequenceNetwork> make_network(const ArchitectureSpec& spec);

}  // namespace tendril::dynamics
