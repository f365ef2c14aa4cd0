#pragma once

#include <Eigen/Core>

namespace tendril::nn {

// The matrix products of dense layers, computed by the system BLAS (Debian's OpenBLAS).
// OpenBLAS's single-precision kernels run ~1.5× faster than Eigen's on this class of machine
// (256³: ~100 vs ~65 GFLOP/s on one core) and can split a product across cores, which Eigen
// without OpenMP cannot. Operands are float matrices with contiguous columns; weights are
// row-major (torch::nn::Linear's layout).
using RowMajorMatrixXf = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ConstRowMajorMap = Eigen::Map<const RowMajorMatrixXf>;
using RowMajorMap = Eigen::Map<RowMajorMatrixXf>;

// result = weight · inputs (result is resized).
void multiply(const ConstRowMajorMap& weight, const Eigen::Ref<const Eigen::MatrixXf>& inputs,
              Eigen::MatrixXf& result);

// result = weightᵀ · inputs (result is resized).
void multiply_transposed(const ConstRowMajorMap& weight,
                         const Eigen::Ref<const Eigen::MatrixXf>& inputs, Eigen::MatrixXf& result);

// result += left · rightᵀ: the weight gradient of a layer, summed over the batch's columns.
void add_outer_products(const Eigen::Ref<const Eigen::MatrixXf>& left,
                        const Eigen::Ref<const Eigen::MatrixXf>& right, RowMajorMap result);

// Threads OpenBLAS may use for one product (it keeps small products on one). Results are
// reproducible for a fixed count; other counts may round differently. Without OpenBLAS (another
// BLAS behind libblas.so.3) this does nothing.
void set_blas_threads(int threads);

}  // namespace tendril::nn
