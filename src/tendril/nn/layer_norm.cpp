#include "tendril/nn/layer_norm.hpp"

#include "tendril/core/error.hpp"

namespace tendril::nn {

void LayerNorm::forward(const Eigen::Ref<const Eigen::MatrixXf>& inputs, Tape& tape) const {
  const auto features = static_cast<float>(inputs.rows());
  require(inputs.rows() >= 1, "needs at least one feature", "nn::LayerNorm");
  tape.output.resize(inputs.rows(), inputs.cols());
  tape.inverse_std.resize(inputs.cols());
  for (Eigen::Index i = 0; i < inputs.cols(); ++i) {
    const float mean = inputs.col(i).sum() / features;
    tape.output.col(i) = inputs.col(i).array() - mean;
    const float variance = tape.output.col(i).squaredNorm() / features;
    tape.inverse_std[i] = 1.0f / std::sqrt(variance + epsilon_);
    tape.output.col(i) *= tape.inverse_std[i];
  }
}

void LayerNorm::backward(const Tape& tape, const Eigen::Ref<const Eigen::MatrixXf>& output_gradient,
                         Eigen::MatrixXf& input_gradient) const {
  require(
      output_gradient.rows() == tape.output.rows() && output_gradient.cols() == tape.output.cols(),
      "the gradient does not match the forward pass", "nn::LayerNorm");
  const auto features = static_cast<float>(tape.output.rows());
  input_gradient.resize(tape.output.rows(), tape.output.cols());
  for (Eigen::Index i = 0; i < tape.output.cols(); ++i) {
    const float mean_gradient = output_gradient.col(i).sum() / features;
    const float mean_projection = output_gradient.col(i).dot(tape.output.col(i)) / features;
    input_gradient.col(i) = (output_gradient.col(i).array() - mean_gradient -
                             tape.output.col(i).array() * mean_projection) *
                            tape.inverse_std[i];
  }
}

}  // namespace tendril::nn
