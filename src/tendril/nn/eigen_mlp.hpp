#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "tendril/nn/activation.hpp"

namespace tendril::nn {

// y = W x + b, with W stored out × in like torch::nn::Linear's weight.
struct DenseLayer {
  Eigen::MatrixXf weight;
  Eigen::VectorXf bias;
};

// A plain-Eigen copy of an `Mlp` trunk for rollout inference. A LibTorch call costs ~10 µs of
// overhead whatever the batch; this costs a few matrix products (measured: 0.6 µs for a
// single observation). Batches are matrices with one column per sample, so a row-major
// [batch, features] buffer from a vector env is used in place. Scratch matrices are kept
// between calls: after the first call of a given batch size, `forward` does not allocate.
class EigenMlp {
 public:
  EigenMlp() = default;
  // Zero weights of the given shape: input_size → hidden[0] → … → hidden.back().
  EigenMlp(int64_t input_size, const std::vector<int64_t>& hidden, Activation activation);

  // inputs: input_size × batch. Returns the last hidden activations (the inputs themselves
  // when there are no layers), valid until the next call.
  Eigen::Ref<const Eigen::MatrixXf> forward(const Eigen::Ref<const Eigen::MatrixXf>& inputs);

  int64_t output_size() const { return output_size_; }
  std::vector<DenseLayer>& layers() { return layers_; }
  const std::vector<DenseLayer>& layers() const { return layers_; }

 private:
  std::vector<DenseLayer> layers_;
  std::vector<Eigen::MatrixXf> outputs_;
  Activation activation_ = Activation::kTanh;
  int64_t output_size_ = 0;
};

// Applies `layer` to each column of `inputs`, writing into `outputs` (resized if needed).
void apply_dense(const DenseLayer& layer, const Eigen::Ref<const Eigen::MatrixXf>& inputs,
                 Eigen::MatrixXf& outputs);

}  // namespace tendril::nn
