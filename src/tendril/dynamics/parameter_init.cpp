#include "tendril/dynamics/parameter_init.hpp"

#include <Eigen/QR>
#include <cmath>
#include <vector>

namespace tendril::dynamics {

namespace {

void copy_into(torch::Tensor& parameter, const std::vector<float>& values) {
  torch::NoGradGuard no_grad;
  parameter.copy_(
      torch::from_blob(const_cast<float*>(values.data()), parameter.sizes(), torch::kFloat));
}

}  // namespace

void fill_uniform(torch::Tensor& parameter, double bound, Rng& rng) {
  std::vector<float> values(static_cast<std::size_t>(parameter.numel()));
  for (float& value : values) value = static_cast<float>(rng.uniform(-bound, bound));
  copy_into(parameter, values);
}

void fill_glorot_uniform(torch::Tensor& parameter, int64_t fan_in, int64_t fan_out, Rng& rng) {
  fill_uniform(parameter, std::sqrt(6.0 / static_cast<double>(fan_in + fan_out)), rng);
}

void fill_orthogonal(torch::Tensor& parameter, Rng& rng) {
  const int64_t rows = parameter.size(0);
  const int64_t columns = parameter.numel() / rows;
  const bool tall = rows >= columns;
  const int64_t long_side = tall ? rows : columns, short_side = tall ? columns : rows;
  Eigen::MatrixXd gaussian(long_side, short_side);
  for (Eigen::Index c = 0; c < gaussian.cols(); ++c) {
    for (Eigen::Index r = 0; r < gaussian.rows(); ++r) gaussian(r, c) = rng.normal();
  }
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(gaussian);
  Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(long_side, short_side);
  const Eigen::MatrixXd r = qr.matrixQR().topRows(short_side).triangularView<Eigen::Upper>();
  for (Eigen::Index c = 0; c < short_side; ++c) {
    if (r(c, c) < 0.0) q.col(c) = -q.col(c);
  }
  std::vector<float> values(static_cast<std::size_t>(rows * columns));
  for (int64_t i = 0; i < rows; ++i) {
    for (int64_t j = 0; j < columns; ++j) {
      values[static_cast<std::size_t>(i * columns + j)] =
          static_cast<float>(tall ? q(i, j) : q(j, i));
    }
  }
  copy_into(parameter, values);
}

void fill_constant(torch::Tensor& parameter, double value) {
  torch::NoGradGuard no_grad;
  parameter.fill_(value);
}

void init_recurrent(torch::nn::Module& layer, int64_t hidden_size, Rng& rng) {
  const double bound = 1.0 / std::sqrt(static_cast<double>(hidden_size));
  for (auto& parameter : layer.parameters()) fill_uniform(parameter, bound, rng);
}

void init_linear(torch::nn::Linear& layer, Rng& rng) {
  const double bound = 1.0 / std::sqrt(static_cast<double>(layer->options.in_features()));
  fill_uniform(layer->weight, bound, rng);
  if (layer->bias.defined()) fill_uniform(layer->bias, bound, rng);
}

}  // namespace tendril::dynamics
