#include "tendril/nn/blas.hpp"

#include <cblas.h>

#include "tendril/core/error.hpp"

// Declared weak: present only when libblas.so.3 is OpenBLAS.
extern "C" void openblas_set_num_threads(int threads) __attribute__((weak));

namespace tendril::nn {

namespace {

int rows(const Eigen::Ref<const Eigen::MatrixXf>& m) { return static_cast<int>(m.rows()); }
int cols(const Eigen::Ref<const Eigen::MatrixXf>& m) { return static_cast<int>(m.cols()); }
int stride(const Eigen::Ref<const Eigen::MatrixXf>& m) { return static_cast<int>(m.outerStride()); }

}  // namespace

// A row-major out × in weight is, read column-major, its in × out transpose with leading
// dimension `in`: the calls below pass it so and let BLAS transpose where needed.

void multiply(const ConstRowMajorMap& weight, const Eigen::Ref<const Eigen::MatrixXf>& inputs,
              Eigen::MatrixXf& result) {
  const auto out = static_cast<int>(weight.rows());
  const auto in = static_cast<int>(weight.cols());
  require(rows(inputs) == in, "inputs have the wrong number of rows", "nn::multiply");
  result.resize(out, inputs.cols());
  if (result.size() == 0) return;
  cblas_sgemm(CblasColMajor, CblasTrans, CblasNoTrans, out, cols(inputs), in, 1.0f, weight.data(),
              in, inputs.data(), stride(inputs), 0.0f, result.data(), out);
}

void multiply_transposed(const ConstRowMajorMap& weight,
                         const Eigen::Ref<const Eigen::MatrixXf>& inputs, Eigen::MatrixXf& result) {
  const auto out = static_cast<int>(weight.rows());
  const auto in = static_cast<int>(weight.cols());
  require(rows(inputs) == out, "inputs have the wrong number of rows", "nn::multiply_transposed");
  result.resize(in, inputs.cols());
  if (result.size() == 0) return;
  cblas_sgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, in, cols(inputs), out, 1.0f, weight.data(),
              in, inputs.data(), stride(inputs), 0.0f, result.data(), in);
}

void add_outer_products(const Eigen::Ref<const Eigen::MatrixXf>& left,
                        const Eigen::Ref<const Eigen::MatrixXf>& right, RowMajorMap result) {
  require(
      result.rows() == left.rows() && result.cols() == right.rows() && left.cols() == right.cols(),
      "operand sizes do not match", "nn::add_outer_products");
  if (result.size() == 0 || left.cols() == 0) return;
  // Row-major result = column-major resultᵀ = right · leftᵀ.
  const auto in = static_cast<int>(result.cols());
  cblas_sgemm(CblasColMajor, CblasNoTrans, CblasTrans, in, rows(left), cols(left), 1.0f,
              right.data(), stride(right), left.data(), stride(left), 1.0f, result.data(), in);
}

void set_blas_threads(int threads) {
  require(threads >= 1, "needs at least one thread", "nn::set_blas_threads");
  if (openblas_set_num_threads != nullptr) openblas_set_num_threads(threads);
}

}  // namespace tendril::nn
