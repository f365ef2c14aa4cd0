#pragma once

#include <Eigen/Core>

namespace tendril {

// Row-major, one row per environment: a batch of observations or actions is one contiguous float
// buffer that maps onto a (batch × size) tensor or NumPy array without a copy.
using BatchMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

}  // namespace tendril
