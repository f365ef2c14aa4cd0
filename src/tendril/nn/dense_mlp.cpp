#include "tendril/nn/dense_mlp.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "tendril/core/error.hpp"
#include "tendril/nn/blas.hpp"

namespace tendril::nn {

namespace {

using ConstVectorMap = Eigen::Map<const Eigen::VectorXf>;

void activate(Activation activation, Eigen::MatrixXf& values) {
  if (activation == Activation::kTanh) {
    values.array() = values.array().tanh();
  } else {
    values.array() = values.array().max(0.0f);
  }
}

// Multiplies `gradient` in place by the activation's derivative, expressed through the
// activation's output y: tanh' = 1 − y², relu' = [y > 0].
void scale_by_derivative(Activation activation, const Eigen::MatrixXf& output,
                         Eigen::MatrixXf& gradient) {
  if (activation == Activation::kTanh) {
    gradient.array() *= 1.0f - output.array().square();
  } else {
    gradient.array() = (output.array() > 0.0f).select(gradient.array(), 0.0f);
  }
}

}  // namespace

DenseMlp::DenseMlp(std::vector<int64_t> sizes, Activation hidden, bool tanh_output)
    : sizes_(std::move(sizes)), hidden_(hidden), tanh_output_(tanh_output) {
  require(sizes_.size() >= 2, "needs at least an input and an output size", "nn::DenseMlp");
  for (int64_t size : sizes_) require(size >= 1, "layer sizes must be positive", "nn::DenseMlp");
  for (std::size_t layer = 0; layer + 1 < sizes_.size(); ++layer) {
    offsets_.push_back(parameter_count_);
    parameter_count_ += sizes_[layer + 1] * (sizes_[layer] + 1);
  }
}

DenseMlp DenseMlp::trunk(std::vector<int64_t> sizes, Activation activation) {
  DenseMlp mlp(std::move(sizes), activation);
  mlp.activated_output_ = true;
  return mlp;
}

void DenseMlp::initialize(Eigen::Ref<Eigen::VectorXf> parameters, Rng& rng) const {
  require(parameters.size() == parameter_count_, "parameter vector has the wrong size",
          "nn::DenseMlp::initialize");
  for (std::size_t layer = 0; layer + 1 < sizes_.size(); ++layer) {
    const double bound = 1.0 / std::sqrt(static_cast<double>(sizes_[layer]));
    const int64_t count = sizes_[layer + 1] * (sizes_[layer] + 1);
    for (int64_t i = 0; i < count; ++i) {
      parameters[offsets_[layer] + i] = static_cast<float>(rng.uniform(-bound, bound));
    }
  }
}

void DenseMlp::forward(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                       const Eigen::Ref<const Eigen::MatrixXf>& inputs, Tape& tape) const {
  tape.input = inputs;
  tape.outputs.resize(sizes_.size() - 1);
  const float* data = parameters.data();
  for (std::size_t layer = 0; layer + 1 < sizes_.size(); ++layer) {
    const int64_t in = sizes_[layer];
    const int64_t out = sizes_[layer + 1];
    const ConstRowMajorMap weight(data + offsets_[layer], out, in);
    const ConstVectorMap bias(data + offsets_[layer] + out * in, out);
    const Eigen::MatrixXf& x = layer == 0 ? tape.input : tape.outputs[layer - 1];
    Eigen::MatrixXf& y = tape.outputs[layer];
    multiply(weight, x, y);
    y.colwise() += bias;
    const bool last = layer + 2 == sizes_.size();
    if (!last || activated_output_) {
      activate(hidden_, y);
    } else if (tanh_output_) {
      activate(Activation::kTanh, y);
    }
  }
}

void DenseMlp::backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, const Tape& tape,
                        const Eigen::Ref<const Eigen::MatrixXf>& output_gradient,
                        Eigen::Ref<Eigen::VectorXf> parameter_gradient,
                        Eigen::MatrixXf* input_gradient,
                        std::vector<Eigen::MatrixXf>& scratch) const {
  const std::size_t layers = sizes_.size() - 1;
  scratch.resize(layers);
  // scratch[l]: ∂L/∂(pre-activation of layer l).
  scratch[layers - 1] = output_gradient;
  if (activated_output_) {
    scale_by_derivative(hidden_, tape.outputs[layers - 1], scratch[layers - 1]);
  } else if (tanh_output_) {
    scale_by_derivative(Activation::kTanh, tape.outputs[layers - 1], scratch[layers - 1]);
  }
  const float* data = parameters.data();
  float* gradient = parameter_gradient.size() == 0 ? nullptr : parameter_gradient.data();
  require(gradient == nullptr || parameter_gradient.size() == parameter_count_,
          "parameter gradient has the wrong size", "nn::DenseMlp::backward");
  for (std::size_t layer = layers; layer-- > 0;) {
    const int64_t in = sizes_[layer];
    const int64_t out = sizes_[layer + 1];
    const Eigen::MatrixXf& x = layer == 0 ? tape.input : tape.outputs[layer - 1];
    const Eigen::MatrixXf& delta = scratch[layer];
    if (gradient != nullptr) {
      RowMajorMap weight_gradient(gradient + offsets_[layer], out, in);
      Eigen::Map<Eigen::VectorXf> bias_gradient(gradient + offsets_[layer] + out * in, out);
      add_outer_products(delta, x, weight_gradient);
      bias_gradient += delta.rowwise().sum();
    }
    const ConstRowMajorMap weight(data + offsets_[layer], out, in);
    if (layer > 0) {
      Eigen::MatrixXf& previous = scratch[layer - 1];
      multiply_transposed(weight, delta, previous);
      scale_by_derivative(hidden_, tape.outputs[layer - 1], previous);
    } else if (input_gradient != nullptr) {
      multiply_transposed(weight, delta, *input_gradient);
    }
  }
}

}  // namespace tendril::nn
