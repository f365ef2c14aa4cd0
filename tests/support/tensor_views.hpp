#pragma once

#include <torch/torch.h>

#include <Eigen/Core>

namespace tendril::testing {

// A contiguous [batch, features] float tensor as the features × batch column-major matrix it
// already is in memory: one column per sample. No copy; the tensor must outlive the view.
inline Eigen::Map<const Eigen::MatrixXf> columns(const torch::Tensor& rows) {
  return {rows.data_ptr<float>(), rows.size(1), rows.size(0)};
}

// A contiguous 1-D float tensor as a row vector, without a copy.
inline Eigen::Map<const Eigen::RowVectorXf> row(const torch::Tensor& values) {
  return {values.data_ptr<float>(), values.numel()};
}

}  // namespace tendril::testing
