#pragma once

#include <torch/torch.h>

#include <memory>
#include <string>
#include <vector>

#include "tendril/dynamics/model_description.hpp"
#include "tendril/dynamics/sequence_network.hpp"
#include "tendril/envs/learned/dynamics_model.hpp"

namespace tendril::dynamics {

// A learned dynamics model: a network with its normalisation, predicting x̂_{t+1} from windows of
// physical rows [x, u] (envs::DynamicsModel). The windows-to-network path is shared by training
// and prediction, so both see identical inputs.
class Model : public envs::DynamicsModel {
 public:
  // A model with freshly initialised weights drawn from Rng(seed).
  Model(ModelDescription description, uint64_t seed);

  const ModelDescription& description() const { return description_; }
  const ArchitectureSpec& spec() const { return description_.architecture; }
  SequenceNetwork& network() { return *network_; }

  // Physical windows [B, window, row] → the network's input [B, sequence, features]: rows
  // normalised; for seed 002 the newest states and inputs stacked as
  // (x_t, x_{t−1}, τ_t, τ_{t−1}, τ_{t−2}).
  torch::Tensor network_input(const torch::Tensor& windows) const;
  // The network's output for windows whose newest state is `current` [B, d_x] → x̂_{t+1}.
  torch::Tensor next_state(const torch::Tensor& output, const torch::Tensor& current) const;
  // The training target of a window: Δx = x_{t+1} − x_t (seed 001, data units) or the
  // normalised x_{t+1} (seed 002). Double precision in, float out.
  torch::Tensor target(const torch::Tensor& current, const torch::Tensor& next) const;

  // envs::DynamicsModel, in evaluation mode (no dropout), without gradients.
  int state_dim() const override { return spec().state_dim; }
  int input_dim() const override { return spec().input_dim; }
  int window_length() const override { return spec().window; }
  double sample_period() const override { return description_.sample_period; }
  void predict(const envs::BatchMatrix& windows, envs::BatchMatrix& next_states) override;
  // The same on a tensor of physical windows [B, window, row] → [B, d_x].
  torch::Tensor predict(const torch::Tensor& windows);

 private:
  ModelDescription description_;
  std::shared_ptr<SequenceNetwork> network_;
  torch::Tensor row_offset_, row_scale_;  // [row], float
};

}  // namespace tendril::dynamics
