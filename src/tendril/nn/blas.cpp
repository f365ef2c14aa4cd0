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

// A row-major out × in weight is, read column-major, its in × out transpose with leading
// dimension `in`: BLAS is told to transpose it back for weight · inputs and to take it as it is
// for weightᵀ · inputs.
void multiply_weight(bool transposed, const ConstRowMajorMap& weight,
                     const Eigen::Ref<const Eigen::MatrixXf>& inputs, Eigen::MatrixXf& result,
                     const char* where) {
  const auto out = static_cast<int>(weight.rows());
  const auto in = static_cast<int>(weight.cols());
  const int result_rows = transposed ? in : out;
  const int inner = transposed ? out : in;
  require(rows(inputs) == inner, "inputs have the wrong number of rows", where);
  result.resize(result_rows, inputs.cols());
  if (result.size() == 0) return;
  cblas_sgemm(CblasColMajor, transposed ? CblasNoTrans : CblasTrans, CblasNoTrans, result_rows,
              cols(inputs), inner, 1.0f, weight.data(), in, inputs.data(), stride(inputs), 0.0f,
              result.data(), result_rows);
}

}  // namespace

void multiply(const ConstRowMajorMap& weight, const Eigen::Ref<const Eigen::MatrixXf>& inputs,
              Eigen::MatrixXf& result) {
  multiply_weight(false, weight, inputs, result, "nn::multiply");
}

void multiply_transposed(const ConstRowMajorMap& weight,
                         const Eigen::Ref<const Eigen::MatrixXf>& inputs, Eigen::MatrixXf& result) {
  multiply_weight(true, weight, inputs, result, "nn::multiply_transposed");
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
