#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "tendril/core/rng.hpp"
#include "tendril/nn/activation.hpp"

namespace tendril::nn {

// A multilayer perceptron whose forward and backward passes are written out by hand over
// Eigen matrices, with every weight in one flat float vector owned by the caller. The
// off-policy algorithms use it for all their networks: with the small networks of continuous
// control a LibTorch call costs ~10 µs of dispatch whatever its size, which would dominate an
// update of a 64×64 network; here an update is a handful of matrix products (nn/blas). A flat
// vector also makes Adam, Polyak averaging and checkpoints whole-vector operations.
//
// Batches are matrices with one column per sample (features × batch). Parameters are laid out
// layer after layer, each as its weight (out × in, row-major) followed by its bias: the memory
// layout of a torch::nn::Linear's weight and bias, so a LibTorch module's flat parameter buffer
// can be read in place.
class DenseMlp {
 public:
  // What a forward pass keeps for the backward pass: the input and every layer's output.
  // Reusing a tape of the same batch size does not allocate.
  struct Tape {
    Eigen::MatrixXf input;
    std::vector<Eigen::MatrixXf> outputs;  // after each layer's activation
    const Eigen::MatrixXf& output() const { return outputs.back(); }
  };

  DenseMlp() = default;
  // sizes: input, hidden…, output (at least input and output). Hidden layers use `hidden`;
  // the output layer is linear, or tanh when `tanh_output` (a deterministic actor's squash).
  DenseMlp(std::vector<int64_t> sizes, Activation hidden, bool tanh_output = false);
  // A feature trunk: every layer, the last one included, is followed by `activation` (the
  // trunk of an actor-critic, whose heads are separate linear layers).
  static DenseMlp trunk(std::vector<int64_t> sizes, Activation activation);

  int64_t input_size() const { return sizes_.front(); }
  int64_t output_size() const { return sizes_.back(); }
  int64_t parameter_count() const { return parameter_count_; }
  const std::vector<int64_t>& sizes() const { return sizes_; }
  Activation hidden_activation() const { return hidden_; }
  bool tanh_output() const { return tanh_output_; }
  bool activates_output() const { return activated_output_; }  // a trunk

  // LibTorch's default initialisation of nn.Linear (what SB3's off-policy networks use):
  // weight and bias uniform in ±1/√fan_in, drawn from `rng`.
  void initialize(Eigen::Ref<Eigen::VectorXf> parameters, Rng& rng) const;
  // SB3's on-policy initialisation (Saxe et al. 2014 via SB3's `ortho_init`): each weight a
  // scaled orthogonal matrix — `hidden_gain` for every layer but the last, `output_gain` for
  // the last — and zero biases. Layer by layer, one standard-normal matrix per layer from `rng`.
  void initialize_orthogonal(Eigen::Ref<Eigen::VectorXf> parameters, double hidden_gain,
                             double output_gain, Rng& rng) const;

  // inputs: input_size × batch. The result is `tape.output()`.
  void forward(const Eigen::Ref<const Eigen::VectorXf>& parameters,
               const Eigen::Ref<const Eigen::MatrixXf>& inputs, Tape& tape) const;

  // Back-propagates `output_gradient` (∂L/∂output, output_size × batch) through the pass
  // recorded in `tape`: adds ∂L/∂parameters to `parameter_gradient` (skipped when it is empty,
  // for a pass that only needs ∂L/∂inputs) and, when given, writes ∂L/∂inputs to
  // `input_gradient`. `scratch` holds intermediate gradients between calls.
  void backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, const Tape& tape,
                const Eigen::Ref<const Eigen::MatrixXf>& output_gradient,
                Eigen::Ref<Eigen::VectorXf> parameter_gradient, Eigen::MatrixXf* input_gradient,
                std::vector<Eigen::MatrixXf>& scratch) const;

  // Forward-mode derivative: the change of the output of the pass recorded in `tape` when the
  // parameters move along `parameter_tangent` and the inputs along `input_tangent` (null:
  // inputs fixed), J·v, into `output_tangent` (output_size × batch). TRPO's Fisher-vector
  // products are JᵀMJv.
  void jvp(const Eigen::Ref<const Eigen::VectorXf>& parameters, const Tape& tape,
           const Eigen::Ref<const Eigen::VectorXf>& parameter_tangent,
           const Eigen::MatrixXf* input_tangent, Eigen::MatrixXf& output_tangent,
           std::vector<Eigen::MatrixXf>& scratch) const;

 private:
  std::vector<int64_t> sizes_;
  std::vector<int64_t> offsets_;  // of each layer's weight in the parameter vector
  Activation hidden_ = Activation::kRelu;
  bool tanh_output_ = false;
  bool activated_output_ = false;  // the output layer uses `hidden_` too (a trunk)
  int64_t parameter_count_ = 0;
};

}  // namespace tendril::nn
