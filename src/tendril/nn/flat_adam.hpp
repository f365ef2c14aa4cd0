#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <vector>

#include "tendril/nn/adam.hpp"
#include "tendril/nn/flat_parameters.hpp"

namespace tendril::nn {

// Adam (Kingma & Ba 2015, "Adam: A Method for Stochastic Optimization", Algorithm 1) over the
// parameters of a FlatParameters: nn::Adam's single pass over the flat value and gradient
// buffers, in place. The arithmetic is torch::optim::Adam's (no weight decay, no AMSGrad), so
// it is Stable-Baselines3's optimizer, equal to it up to float rounding:
//   m ← β₁ m + (1 − β₁) g,   v ← β₂ v + (1 − β₂) g²
//   θ ← θ − (lr / (1 − β₁ᵗ)) · m / (√v / √(1 − β₂ᵗ) + ε)
class FlatAdam {
 public:
  struct Options {
    double learning_rate = 1e-3;
    double beta1 = 0.9;
    double beta2 = 0.999;
    double epsilon = 1e-8;
  };

  // Takes the parameters into one flat buffer (see FlatParameters); moments start at zero.
  FlatAdam(std::vector<torch::Tensor> parameters, const Options& options);

  FlatParameters& parameters() { return parameters_; }
  const FlatParameters& parameters() const { return parameters_; }
  void zero_grad() { parameters_.zero_grad(); }
  // One update from the current gradients.
  void step();

  double learning_rate() const { return adam_.learning_rate(); }
  void set_learning_rate(double learning_rate) { adam_.set_learning_rate(learning_rate); }
  int64_t steps() const { return adam_.steps(); }

  // The state needed to continue: step count and both moment buffers. `load` raises Error
  // when the saved buffers do not fit these parameters.
  void save(torch::serialize::OutputArchive& archive) const;
  void load(torch::serialize::InputArchive& archive);

 private:
  FlatParameters parameters_;
  Adam adam_;
};

}  // namespace tendril::nn
