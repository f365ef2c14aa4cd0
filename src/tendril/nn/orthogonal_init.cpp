#include "tendril/nn/orthogonal_init.hpp"

#include <Eigen/QR>

namespace tendril::nn {

void orthogonal_init(torch::nn::Linear& layer, double gain, Rng& rng) {
  const int64_t rows = layer->weight.size(0);
  const int64_t cols = layer->weight.size(1);
  // QR needs a tall matrix; a wide weight is the transpose of a tall one.
  const bool wide = rows < cols;
  const int64_t tall_rows = wide ? cols : rows;
  const int64_t tall_cols = wide ? rows : cols;
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
  const Eigen::MatrixXd weight = wide ? Eigen::MatrixXd(q.transpose()) : q;

  torch::NoGradGuard no_grad;
  auto accessor = layer->weight.accessor<float, 2>();
  for (int64_t i = 0; i < rows; ++i) {
    for (int64_t j = 0; j < cols; ++j) accessor[i][j] = static_cast<float>(gain * weight(i, j));
  }
  if (layer->bias.defined()) layer->bias.zero_();
}

}  // namespace tendril::nn
