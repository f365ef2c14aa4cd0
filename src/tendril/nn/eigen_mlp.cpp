#include "tendril/nn/eigen_mlp.hpp"

namespace tendril::nn {

EigenMlp::EigenMlp(int64_t input_size, const std::vector<int64_t>& hidden, Activation activation)
    : activation_(activation), output_size_(input_size) {
  for (int64_t units : hidden) {
    layers_.push_back({Eigen::MatrixXf::Zero(units, output_size_), Eigen::VectorXf::Zero(units)});
    output_size_ = units;
  }
  outputs_.resize(layers_.size());
}

void apply_dense(const DenseLayer& layer, const Eigen::Ref<const Eigen::MatrixXf>& inputs,
                 Eigen::MatrixXf& outputs) {
  outputs.resize(layer.weight.rows(), inputs.cols());
  outputs.noalias() = layer.weight * inputs;
  outputs.colwise() += layer.bias;
}

Eigen::Ref<const Eigen::MatrixXf> EigenMlp::forward(
    const Eigen::Ref<const Eigen::MatrixXf>& inputs) {
  if (layers_.empty()) return inputs;
  for (std::size_t i = 0; i < layers_.size(); ++i) {
    if (i == 0) {
      apply_dense(layers_[i], inputs, outputs_[i]);
    } else {
      apply_dense(layers_[i], outputs_[i - 1], outputs_[i]);
    }
    if (activation_ == Activation::kTanh) {
      outputs_[i].array() = outputs_[i].array().tanh();
    } else {
      outputs_[i].array() = outputs_[i].array().max(0.0f);
    }
  }
  return outputs_.back();
}

}  // namespace tendril::nn
