#include "tendril/nn/dense_mlp.hpp"

#include <Eigen/QR>
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
  } else if (activation == Activation::kSoftsign) {
    values.array() = values.array() / (1.0f + values.array().abs());
  } else {
    values.array() = values.array().max(0.0f);
  }
}

// Multiplies `gradient` in place by the activation's derivative, expressed through the
// activation's output y: tanh' = 1 − y², softsign' = 1 / (1 + |x|)² = (1 − |y|)²,
// relu' = [y > 0].
void scale_by_derivative(Activation activation, const Eigen::MatrixXf& output,
                         Eigen::MatrixXf& gradient) {
  if (activation == Activation::kTanh) {
    gradient.array() *= 1.0f - output.array().square();
  } else if (activation == Activation::kSoftsign) {
    gradient.array() *= (1.0f - output.array().abs()).square();
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

void DenseMlp::initialize_orthogonal(Eigen::Ref<Eigen::VectorXf> parameters, double hidden_gain,
                                     double output_gain, Rng& rng) const {
  require(parameters.size() == parameter_count_, "parameter vector has the wrong size",
          "nn::DenseMlp::initialize_orthogonal");
  for (std::size_t layer = 0; layer + 1 < sizes_.size(); ++layer) {
    const int64_t rows = sizes_[layer + 1], cols = sizes_[layer];
    const double gain = layer + 2 == sizes_.size() ? output_gain : hidden_gain;
    // Q of the QR factorisation of a Gaussian matrix, columns signed by R's diagonal (so Q is
    // Haar-distributed); QR needs a tall matrix, so a wide weight is a tall one transposed.
    const bool wide = rows < cols;
    const int64_t tall_rows = wide ? cols : rows, tall_cols = wide ? rows : cols;
    Eigen::MatrixXd gaussian(tall_rows, tall_cols);
    for (int64_t i = 0; i < tall_rows; ++i) {
      for (int64_t j = 0; j < tall_cols; ++j) gaussian(i, j) = rng.normal();
    }
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(gaussian);
    Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(tall_rows, tall_cols);
    const Eigen::VectorXd r_diagonal = qr.matrixQR().diagonal();
    for (int64_t j = 0; j < tall_cols; ++j) {
      if (r_diagonal[j] < 0) q.col(j) *= -1.0;
    }
    RowMajorMap weight(parameters.data() + offsets_[layer], rows, cols);
    if (wide) {
      weight = (gain * q.transpose()).cast<float>();
    } else {
      weight = (gain * q).cast<float>();
    }
    parameters.segment(offsets_[layer] + rows * cols, rows).setZero();
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

void DenseMlp::jvp(const Eigen::Ref<const Eigen::VectorXf>& parameters, const Tape& tape,
                   const Eigen::Ref<const Eigen::VectorXf>& parameter_tangent,
                   const Eigen::MatrixXf* input_tangent, Eigen::MatrixXf& output_tangent,
                   std::vector<Eigen::MatrixXf>& scratch) const {
  require(parameter_tangent.size() == parameter_count_, "parameter tangent has the wrong size",
          "nn::DenseMlp::jvp");
  const std::size_t layers = sizes_.size() - 1;
  scratch.resize(3);  // two alternating layer tangents and a product
  const float* data = parameters.data();
  const float* tangent = parameter_tangent.data();
  // t_l = act'(pre_l) ⊙ (W_l t_{l−1} + δW_l x_{l−1} + δb_l), t_0 the input tangent.
  const Eigen::MatrixXf* previous = input_tangent;
  for (std::size_t layer = 0; layer < layers; ++layer) {
    const int64_t in = sizes_[layer];
    const int64_t out = sizes_[layer + 1];
    const bool last = layer + 1 == layers;
    const Eigen::MatrixXf& x = layer == 0 ? tape.input : tape.outputs[layer - 1];
    Eigen::MatrixXf& t = last ? output_tangent : scratch[layer % 2];
    multiply(ConstRowMajorMap(tangent + offsets_[layer], out, in), x, t);
    t.colwise() += ConstVectorMap(tangent + offsets_[layer] + out * in, out);
    if (previous != nullptr) {
      multiply(ConstRowMajorMap(data + offsets_[layer], out, in), *previous, scratch[2]);
      t += scratch[2];
    }
    if (!last || activated_output_) {
      scale_by_derivative(hidden_, tape.outputs[layer], t);
    } else if (tanh_output_) {
      scale_by_derivative(Activation::kTanh, tape.outputs[layer], t);
    }
    previous = &t;
  }
}

}  // namespace tendril::nn
